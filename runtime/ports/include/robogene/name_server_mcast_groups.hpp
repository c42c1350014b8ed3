// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// Multicast groups handed out by a name server, as YARP's McastCarrier asks for them:
// `register ... mcast ... ...` for a fresh group, `set <port> owns <group>` so the server drops
// it with the port, `unregister <group>` when the port's last mcast output closes. Ports pass
// this to the mcast carrier (carrier::ConnectContext::mcast_groups).
#pragma once

#include <memory>
#include <optional>

#include "robogene/carrier/mcast_group_allocator.hpp"
#include "robogene/net/endpoint.hpp"

namespace robogene {

// Groups from the name server at `server`; unset: the one the YARP configuration names, read
// when the first group is needed.
std::shared_ptr<carrier::McastGroupAllocator> name_server_mcast_groups(std::optional<net::Endpoint> server);

}  // namespace robogene
