// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "robogene/net/mcast_socket.hpp"

#include <arpa/inet.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/eventfd.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>
#include <cstdint>
#include <cstring>

#include "robogene/error.hpp"

namespace robogene::net {

namespace {

in_addr parse_ipv4(const std::string& host, const std::string& what) {
  in_addr a{};
  if (::inet_pton(AF_INET, host.c_str(), &a) != 1) {
    throw NetworkError(what + " \"" + host + "\" is not an IPv4 address");
  }
  return a;
}

std::string errno_text(int err) { return std::strerror(err); }

net::UniqueFd udp_socket(const std::string& where) {
  net::UniqueFd fd(::socket(AF_INET, SOCK_DGRAM | SOCK_CLOEXEC, 0));
  if (!fd.valid()) throw NetworkError("cannot create a UDP socket for " + where + ": " + errno_text(errno));
  return fd;
}

void set_option(int fd, int level, int name, const void* value, socklen_t size, const std::string& what) {
  if (::setsockopt(fd, level, name, value, size) != 0) throw NetworkError(what + ": " + errno_text(errno));
}

}  // namespace

bool is_multicast_group(const std::string& dotted_quad) {
  in_addr a{};
  if (::inet_pton(AF_INET, dotted_quad.c_str(), &a) != 1) return false;
  return IN_MULTICAST(ntohl(a.s_addr));
}

McastSocket McastSocket::join(const net::Endpoint& group, const std::string& iface) {
  McastSocket s;
  s.where_ = "mcast group " + group.to_string() + " on " + iface;
  in_addr g = parse_ipv4(group.host, "mcast group");
  if (!IN_MULTICAST(ntohl(g.s_addr))) throw NetworkError(group.host + " is not a multicast group");
  in_addr i = parse_ipv4(iface, "interface");
  s.fd_ = udp_socket(s.where_);
  int one = 1;
  set_option(s.fd_.get(), SOL_SOCKET, SO_REUSEADDR, &one, sizeof one, "cannot share " + s.where_);
  // Images arrive as bursts of datagrams: a bigger receive buffer avoids drops.
  int size = 4 * 1024 * 1024;
  ::setsockopt(s.fd_.get(), SOL_SOCKET, SO_RCVBUF, &size, sizeof size);
  sockaddr_in addr{};
  addr.sin_family = AF_INET;
  addr.sin_addr = g;  // binding the group itself keeps other groups on this port out
  addr.sin_port = htons(static_cast<std::uint16_t>(group.port));
  if (::bind(s.fd_.get(), reinterpret_cast<sockaddr*>(&addr), sizeof addr) != 0) {
    throw NetworkError("cannot bind " + s.where_ + ": " + errno_text(errno));
  }
  ip_mreq mreq{};
  mreq.imr_multiaddr = g;
  mreq.imr_interface = i;
  set_option(s.fd_.get(), IPPROTO_IP, IP_ADD_MEMBERSHIP, &mreq, sizeof mreq, "cannot join " + s.where_);
  s.wake_.reset(::eventfd(0, EFD_CLOEXEC | EFD_NONBLOCK));
  return s;
}

McastSocket McastSocket::sender(const std::string& iface) {
  McastSocket s;
  s.where_ = "mcast sender on " + iface;
  in_addr i = parse_ipv4(iface, "interface");
  s.fd_ = udp_socket(s.where_);
  set_option(s.fd_.get(), IPPROTO_IP, IP_MULTICAST_IF, &i, sizeof i, "cannot send multicast through " + iface);
  unsigned char loop = 1, ttl = 1;
  set_option(s.fd_.get(), IPPROTO_IP, IP_MULTICAST_LOOP, &loop, sizeof loop, "cannot loop multicast back on " + iface);
  set_option(s.fd_.get(), IPPROTO_IP, IP_MULTICAST_TTL, &ttl, sizeof ttl, "cannot set the multicast TTL on " + iface);
  int size = 4 * 1024 * 1024;
  ::setsockopt(s.fd_.get(), SOL_SOCKET, SO_SNDBUF, &size, sizeof size);
  s.wake_.reset(::eventfd(0, EFD_CLOEXEC | EFD_NONBLOCK));
  return s;
}

void McastSocket::send_to(const net::Endpoint& to, const iovec* iov, std::size_t count) {
  sockaddr_in addr{};
  addr.sin_family = AF_INET;
  addr.sin_addr = parse_ipv4(to.host, "mcast group");
  addr.sin_port = htons(static_cast<std::uint16_t>(to.port));
  msghdr msg{};
  msg.msg_name = &addr;
  msg.msg_namelen = sizeof addr;
  msg.msg_iov = const_cast<iovec*>(iov);
  msg.msg_iovlen = count;
  for (;;) {
    if (::sendmsg(fd_.get(), &msg, MSG_NOSIGNAL) >= 0) return;
    if (errno == EINTR) continue;
    if (errno == ENOBUFS || errno == EAGAIN) {
      ::usleep(100);  // socket buffer full: let the kernel drain it
      continue;
    }
    throw NetworkError("cannot send a datagram to mcast group " + to.to_string() + ": " + errno_text(errno));
  }
}

std::optional<std::size_t> McastSocket::receive(void* data, std::size_t capacity, net::Millis timeout,
                                                net::Endpoint* from) {
  for (;;) {
    pollfd fds[2] = {{fd_.get(), POLLIN, 0}, {wake_.get(), POLLIN, 0}};
    int ms = timeout.count() > 0 ? static_cast<int>(timeout.count()) : -1;
    int ready = ::poll(fds, 2, ms);
    if (ready < 0) {
      if (errno == EINTR) continue;
      throw NetworkError("cannot wait on " + where_ + ": " + errno_text(errno));
    }
    if (ready == 0 || (fds[1].revents & POLLIN)) return std::nullopt;
    sockaddr_in addr{};
    socklen_t len = sizeof addr;
    ssize_t n = ::recvfrom(fd_.get(), data, capacity, MSG_TRUNC, reinterpret_cast<sockaddr*>(&addr), &len);
    if (n < 0) {
      if (errno == EINTR || errno == EAGAIN) continue;
      throw NetworkError("cannot receive on " + where_ + ": " + errno_text(errno));
    }
    char host[INET_ADDRSTRLEN] = {0};
    ::inet_ntop(AF_INET, &addr.sin_addr, host, sizeof host);
    if (from) *from = net::Endpoint{host, ntohs(addr.sin_port)};
    if (static_cast<std::size_t>(n) > capacity) {
      throw NetworkError("datagram of " + std::to_string(n) + " bytes from " + host + " exceeds the " +
                         std::to_string(capacity) + "-byte buffer on " + where_);
    }
    return static_cast<std::size_t>(n);
  }
}

void McastSocket::interrupt() noexcept {
  if (wake_.valid()) {
    std::uint64_t one = 1;
    ssize_t ignored = ::write(wake_.get(), &one, sizeof one);
    (void)ignored;
  }
}

void McastSocket::close() noexcept {
  fd_.reset();
  wake_.reset();
}

}  // namespace robogene::net
