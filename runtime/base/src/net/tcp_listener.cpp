// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "robogene/net/tcp_listener.hpp"

#include <netinet/in.h>
#include <sys/eventfd.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>
#include <cstdint>

#include "robogene/error.hpp"
#include "socket_util.hpp"

namespace robogene::net {

TcpListener TcpListener::listen(const Endpoint& at, int backlog) {
  sockaddr_in addr = detail::to_sockaddr(at);
  TcpListener l;
  l.fd_.reset(::socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC, 0));
  if (!l.fd_.valid()) {
    throw NetworkError("cannot create a socket to listen on " + at.to_string() + ": " +
                       detail::errno_text(errno));
  }
  int one = 1;
  ::setsockopt(l.fd_.get(), SOL_SOCKET, SO_REUSEADDR, &one, sizeof one);
  if (::bind(l.fd_.get(), reinterpret_cast<sockaddr*>(&addr), sizeof addr) != 0) {
    throw NetworkError("cannot listen on " + at.to_string() + ": " + detail::errno_text(errno));
  }
  if (::listen(l.fd_.get(), backlog) != 0) {
    throw NetworkError("cannot listen on " + at.to_string() + ": " + detail::errno_text(errno));
  }
  l.wake_.reset(::eventfd(0, EFD_CLOEXEC | EFD_NONBLOCK));
  l.local_ = detail::local_of(l.fd_.get());
  if (!at.host.empty() && at.host != "0.0.0.0") l.local_.host = detail::from_sockaddr(addr).host;
  return l;
}

std::optional<TcpStream> TcpListener::accept(Millis timeout) {
  for (;;) {
    if (!fd_.valid()) return std::nullopt;
    int ready = detail::poll_readable(fd_.get(), wake_.get(), timeout);
    if (ready <= 0) return std::nullopt;
    int fd = ::accept4(fd_.get(), nullptr, nullptr, SOCK_CLOEXEC);
    if (fd >= 0) return TcpStream(UniqueFd(fd));
    if (errno == EINTR || errno == ECONNABORTED || errno == EAGAIN || errno == EPROTO) continue;
    if (errno == EMFILE || errno == ENFILE || errno == ENOBUFS || errno == ENOMEM) {
      // Out of descriptors: back off briefly rather than spin; the caller logs nothing per try.
      ::usleep(10000);
      continue;
    }
    return std::nullopt;
  }
}

void TcpListener::interrupt() noexcept {
  if (wake_.valid()) {
    std::uint64_t one = 1;
    ssize_t ignored = ::write(wake_.get(), &one, sizeof one);
    (void)ignored;
  }
}

void TcpListener::close() noexcept {
  fd_.reset();
  wake_.reset();
}

}  // namespace robogene::net
