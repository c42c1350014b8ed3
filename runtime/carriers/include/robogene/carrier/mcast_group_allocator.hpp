// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// Where the mcast carrier gets a multicast group for a port's outputs. YARP's writers ask the
// name server for one; the carrier layer sits below the name client, so the port that connects
// passes an allocator in (ConnectContext::mcast_groups) and the carrier only calls it.
#pragma once

#include <optional>
#include <string>

#include "robogene/net/endpoint.hpp"
#include "robogene/net/tcp_stream.hpp"

namespace robogene::carrier {

class McastGroupAllocator {
 public:
  struct Grant {
    net::Endpoint group;       // 224.1.1.3:10005
    std::string registration;  // what to give back ("" = nothing to give back)
  };
  virtual ~McastGroupAllocator() = default;
  // A group for the outputs of `sender`, or nullopt when none can be had (the carrier then uses
  // YARP's shared fallback group). Reports its own failures; does not throw.
  virtual std::optional<Grant> allocate(const std::string& sender, net::Millis timeout) = 0;
  // Gives a group back once its last member has left. Does not throw.
  virtual void release(const Grant& grant, net::Millis timeout) noexcept = 0;
};

}  // namespace robogene::carrier
