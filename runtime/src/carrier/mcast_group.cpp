// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "mcast_group.hpp"

#include <algorithm>

#include "robogene/error.hpp"
#include "robogene/log.hpp"
#include "robogene/name_client.hpp"
#include "robogene/name_config.hpp"

namespace robogene::carrier::detail {

namespace {

// Asks the name server for a group as YARP's McastCarrier does; nullopt when it cannot help.
std::optional<net::Endpoint> allocate(McastGroup& g, const std::string& sender, net::Millis timeout) {
  if (!g.name_server) {
    try {
      g.name_server = NameConfig::load().server;
    } catch (const Error& e) {
      log::warn(sender, std::string("mcast: no name server to allocate a group from: ") + e.what());
      return std::nullopt;
    }
  }
  try {
    NameClient names(*g.name_server, timeout);
    for (const auto& line : names.request("NAME_SERVER register ... mcast ... ...\r\n")) {
      auto c = NameClient::parse_registration(line);
      if (!c || !is_multicast_group(c->host) || c->port <= 0 || c->port > 65535) continue;
      g.registration = c->name;
      // Marks the group as the port's, so the server drops it when the port unregisters.
      if (!sender.empty() && sender[0] == '/') names.set_property(sender, "owns", {c->name});
      return net::Endpoint{c->host, c->port};
    }
    log::warn(sender, "mcast: the name server at " + g.name_server->to_string() +
                          " did not hand out a multicast group");
  } catch (const std::exception& e) {
    log::warn(sender, std::string("mcast: asking the name server for a group failed: ") + e.what());
  }
  return std::nullopt;
}

}  // namespace

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
                                                const std::optional<net::Endpoint>& name_server,
                                                net::Millis timeout) {
  std::lock_guard<std::mutex> lock(mutex_);
  auto it = groups_.find(key);
  if (it != groups_.end()) {
    std::lock_guard<std::mutex> glock(it->second->mutex);
    it->second->members.push_back(member);
    return it->second;
  }
  auto g = std::make_shared<McastGroup>();
  g->name_server = name_server;
  auto address = allocate(*g, sender, timeout);
  if (!address) {
    log::warn(sender, "mcast: using YARP's fallback group " + fallback_mcast_group().to_string() +
                          " (every fallback sender on this network shares it)");
    address = fallback_mcast_group();
  }
  g->address = *address;
  try {
    g->socket = McastSocket::sender(iface);
  } catch (...) {
    if (!g->registration.empty()) NameClient(*g->name_server, timeout).unregister(g->registration);
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
  if (gone->registration.empty() || !gone->name_server) return;
  try {
    NameClient(*gone->name_server, net::Millis{2000}).unregister(gone->registration);
  } catch (const std::exception& e) {
    log::warn(key, "mcast: could not unregister group " + gone->registration + ": " + e.what());
  }
}

}  // namespace robogene::carrier::detail
