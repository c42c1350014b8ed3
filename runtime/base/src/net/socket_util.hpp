// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// Helpers shared by the socket classes (private to src/net).
#pragma once

#include <netinet/in.h>

#include <string>

#include "robogene/net/endpoint.hpp"
#include "robogene/net/tcp_stream.hpp"

namespace robogene::net::detail {

// Resolves host (dotted quad, "localhost", a name, or "" / "0.0.0.0" for any) to an IPv4 address.
// Throws NetworkError naming the host.
sockaddr_in to_sockaddr(const Endpoint& e);
Endpoint from_sockaddr(const sockaddr_in& a);
Endpoint local_of(int fd);
Endpoint peer_of(int fd);
std::string errno_text(int err);
// poll() for POLLIN on fd and on wake_fd (-1 = none); returns 1 when fd is ready, 0 on timeout,
// -1 when woken.
int poll_readable(int fd, int wake_fd, Millis timeout);

}  // namespace robogene::net::detail
