// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "robogene/net/udp_socket.hpp"

#include <netinet/in.h>
#include <sys/eventfd.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>
#include <cstdint>

#include "robogene/error.hpp"
#include "socket_util.hpp"

namespace robogene::net {

UdpSocket UdpSocket::bind(const Endpoint& at) {
  sockaddr_in addr = detail::to_sockaddr(at);
  UdpSocket s;
  s.fd_.reset(::socket(AF_INET, SOCK_DGRAM | SOCK_CLOEXEC, 0));
  if (!s.fd_.valid()) {
    throw NetworkError("cannot create a UDP socket on " + at.to_string() + ": " +
                       detail::errno_text(errno));
  }
  // Large messages arrive as bursts of datagrams: a bigger receive buffer avoids drops.
  int size = 4 * 1024 * 1024;
  ::setsockopt(s.fd_.get(), SOL_SOCKET, SO_RCVBUF, &size, sizeof size);
  if (::bind(s.fd_.get(), reinterpret_cast<sockaddr*>(&addr), sizeof addr) != 0) {
    throw NetworkError("cannot bind UDP " + at.to_string() + ": " + detail::errno_text(errno));
  }
  s.wake_.reset(::eventfd(0, EFD_CLOEXEC | EFD_NONBLOCK));
  s.local_ = detail::local_of(s.fd_.get());
  if (!at.host.empty() && at.host != "0.0.0.0") s.local_.host = detail::from_sockaddr(addr).host;
  return s;
}

void UdpSocket::send_to(const Endpoint& to, const void* data, std::size_t size) {
  iovec v{const_cast<void*>(data), size};
  send_to(to, &v, 1);
}

void UdpSocket::send_to(const Endpoint& to, const iovec* iov, std::size_t count) {
  sockaddr_in addr = detail::to_sockaddr(to);
  msghdr msg{};
  msg.msg_name = &addr;
  msg.msg_namelen = sizeof addr;
  msg.msg_iov = const_cast<iovec*>(iov);
  msg.msg_iovlen = count;
  for (;;) {
    ssize_t n = ::sendmsg(fd_.get(), &msg, MSG_NOSIGNAL);
    if (n >= 0) return;
    if (errno == EINTR) continue;
    if (errno == ENOBUFS || errno == EAGAIN) {
      ::usleep(100);  // socket buffer full: wait for the kernel to drain it
      continue;
    }
    throw NetworkError("cannot send a datagram to " + to.to_string() + ": " +
                       detail::errno_text(errno));
  }
}

std::optional<std::size_t> UdpSocket::receive(void* data, std::size_t capacity, Millis timeout,
                                              Endpoint* from) {
  for (;;) {
    int ready = detail::poll_readable(fd_.get(), wake_.get(), timeout);
    if (ready <= 0) return std::nullopt;
    sockaddr_in addr{};
    socklen_t len = sizeof addr;
    ssize_t n = ::recvfrom(fd_.get(), data, capacity, MSG_TRUNC, reinterpret_cast<sockaddr*>(&addr),
                           &len);
    if (n < 0) {
      if (errno == EINTR || errno == EAGAIN) continue;
      throw NetworkError("cannot receive on UDP " + local_.to_string() + ": " +
                         detail::errno_text(errno));
    }
    if (from) *from = detail::from_sockaddr(addr);
    if (static_cast<std::size_t>(n) > capacity) {
      throw NetworkError("datagram of " + std::to_string(n) + " bytes from " +
                         detail::from_sockaddr(addr).to_string() + " exceeds the " +
                         std::to_string(capacity) + "-byte buffer on " + local_.to_string());
    }
    return static_cast<std::size_t>(n);
  }
}

void UdpSocket::interrupt() noexcept {
  if (wake_.valid()) {
    std::uint64_t one = 1;
    ssize_t ignored = ::write(wake_.get(), &one, sizeof one);
    (void)ignored;
  }
}

void UdpSocket::close() noexcept {
  fd_.reset();
  wake_.reset();
}

}  // namespace robogene::net
