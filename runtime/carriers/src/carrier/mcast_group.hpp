// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// The multicast groups this process sends to (private to src/carrier). As in YARP, every mcast
// output of one port on one network interface shares one group and one stream: the first
// output to a reader gets a group from the connecting port's allocator (the name server's:
// `register ... mcast ... ...`, then `set <port> owns <group name>`), later outputs to other
// readers join it, and only the group's first member (the "elect") actually sends, so a write
// reaches all readers once. When the last member leaves, the group is given back.
#pragma once

#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "robogene/carrier/mcast_group_allocator.hpp"
#include "robogene/net/mcast_socket.hpp"
#include "robogene/net/endpoint.hpp"
#include "robogene/net/tcp_stream.hpp"

namespace robogene::carrier::detail {

struct McastGroup {
  net::Endpoint address;                          // 224.1.1.3:10005
  std::optional<McastGroupAllocator::Grant> grant;  // unset: the fallback group
  std::shared_ptr<McastGroupAllocator> allocator;   // who gave it, to give it back
  net::McastSocket socket;
  std::mutex mutex;                          // guards members and sending
  std::vector<const void*> members;          // members.front() sends
};

// The YARP fallback when no name server hands out a group (one mcast output per network then).
const net::Endpoint& fallback_mcast_group();

class McastGroups {
 public:
  static McastGroups& global();

  // Adds `member` to the group of `key` ("<sender>/net=<interface address>"), creating it with
  // a group from `allocator` (none: the fallback group) when there is none yet.
  std::shared_ptr<McastGroup> enlist(const std::string& key, const void* member, const std::string& sender,
                                     const std::string& iface, std::shared_ptr<McastGroupAllocator> allocator,
                                     net::Millis timeout);
  // Removes `member`; the last one out gives the group back.
  void leave(const std::string& key, const void* member) noexcept;

 private:
  std::mutex mutex_;
  std::map<std::string, std::shared_ptr<McastGroup>> groups_;
};

}  // namespace robogene::carrier::detail
