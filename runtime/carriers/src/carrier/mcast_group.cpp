// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "mcast_group.hpp"

#include <algorithm>

#include "robogene/log.hpp"

namespace robogene::carrier::detail {

const net::Endpoint& fallback_mcast_group() {
  static const net::Endpoint group{"224.3.1.1", 11000};
  return group;
}

McastGroups& McastGroups::global() {
  static McastGroups groups;
  return groups;
}

std::shared_ptr<McastGroup> McastGroups::enlist(const std::string& key, const void* member,
                                                const std::string& sender, const std::string& iface,
                                                std::shared_ptr<McastGroupAllocator> allocator,
                                                net::Millis timeout) {
  std::lock_guard<std::mutex> lock(mutex_);
  auto it = groups_.find(key);
  if (it != groups_.end()) {
    std::lock_guard<std::mutex> glock(it->second->mutex);
    it->second->members.push_back(member);
    return it->second;
  }
  auto g = std::make_shared<McastGroup>();
  g->allocator = std::move(allocator);
  if (g->allocator) g->grant = g->allocator->allocate(sender, timeout);
  if (g->grant) {
    g->address = g->grant->group;
  } else {
    log::warn(sender, "mcast: using YARP's fallback group " + fallback_mcast_group().to_string() +
                          " (every fallback sender on this network shares it)");
    g->address = fallback_mcast_group();
  }
  try {
    g->socket = net::McastSocket::sender(iface);
  } catch (...) {
    if (g->grant) g->allocator->release(*g->grant, timeout);
    throw;
  }
  g->members.push_back(member);
  groups_[key] = g;
  return g;
}

void McastGroups::leave(const std::string& key, const void* member) noexcept {
  std::shared_ptr<McastGroup> gone;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    auto it = groups_.find(key);
    if (it == groups_.end()) return;
    std::lock_guard<std::mutex> glock(it->second->mutex);
    auto& m = it->second->members;
    m.erase(std::remove(m.begin(), m.end(), member), m.end());
    if (!m.empty()) return;
    gone = it->second;
    groups_.erase(it);
  }
  gone->socket.close();
  if (gone->grant) gone->allocator->release(*gone->grant, net::Millis{2000});
}

}  // namespace robogene::carrier::detail
