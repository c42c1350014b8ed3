// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "socket_util.hpp"

#include <arpa/inet.h>
#include <netdb.h>
#include <poll.h>
#include <sys/socket.h>

#include <cerrno>
#include <chrono>
#include <cstring>

#include "robogene/error.hpp"

namespace robogene::net::detail {

sockaddr_in to_sockaddr(const Endpoint& e) {
  if (e.port < 0 || e.port > 65535) {
    throw NetworkError("port number " + std::to_string(e.port) + " of " + e.to_string() +
                       " is outside 0..65535");
  }
  sockaddr_in a{};
  a.sin_family = AF_INET;
  a.sin_port = htons(static_cast<std::uint16_t>(e.port));
  if (e.host.empty() || e.host == "0.0.0.0" || e.host == "...") {
    a.sin_addr.s_addr = htonl(INADDR_ANY);
    return a;
  }
  if (::inet_pton(AF_INET, e.host.c_str(), &a.sin_addr) == 1) return a;
  addrinfo hints{};
  hints.ai_family = AF_INET;
  hints.ai_socktype = SOCK_STREAM;
  addrinfo* found = nullptr;
  int rc = ::getaddrinfo(e.host.c_str(), nullptr, &hints, &found);
  if (rc != 0 || found == nullptr) {
    throw NetworkError("cannot resolve host \"" + e.host + "\": " + ::gai_strerror(rc));
  }
  a.sin_addr = reinterpret_cast<sockaddr_in*>(found->ai_addr)->sin_addr;
  ::freeaddrinfo(found);
  return a;
}

Endpoint from_sockaddr(const sockaddr_in& a) {
  char text[INET_ADDRSTRLEN] = {0};
  ::inet_ntop(AF_INET, &a.sin_addr, text, sizeof text);
  return Endpoint{text, ntohs(a.sin_port)};
}

Endpoint local_of(int fd) {
  sockaddr_in a{};
  socklen_t len = sizeof a;
  if (::getsockname(fd, reinterpret_cast<sockaddr*>(&a), &len) != 0) return {};
  return from_sockaddr(a);
}

Endpoint peer_of(int fd) {
  sockaddr_in a{};
  socklen_t len = sizeof a;
  if (::getpeername(fd, reinterpret_cast<sockaddr*>(&a), &len) != 0) return {};
  return from_sockaddr(a);
}

std::string errno_text(int err) { return std::strerror(err); }

int poll_readable(int fd, int wake_fd, Millis timeout) {
  using Clock = std::chrono::steady_clock;
  const auto deadline = Clock::now() + timeout;
  for (;;) {
    pollfd fds[2] = {{fd, POLLIN, 0}, {wake_fd, POLLIN, 0}};
    int wait_ms = -1;
    if (timeout.count() > 0) {
      auto left = std::chrono::duration_cast<Millis>(deadline - Clock::now()).count();
      wait_ms = left < 0 ? 0 : static_cast<int>(left);
    }
    int rc = ::poll(fds, wake_fd >= 0 ? 2 : 1, wait_ms);
    if (rc < 0) {
      if (errno == EINTR) continue;
      return -1;
    }
    if (rc == 0) return 0;
    if (wake_fd >= 0 && (fds[1].revents & POLLIN)) return -1;
    if (fds[0].revents & (POLLIN | POLLHUP | POLLERR)) return 1;
    if (fds[0].revents & POLLNVAL) return -1;
  }
}

}  // namespace robogene::net::detail
