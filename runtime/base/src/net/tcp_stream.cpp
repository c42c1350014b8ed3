// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "robogene/net/tcp_stream.hpp"

#include <fcntl.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <climits>
#include <cerrno>

#include "robogene/error.hpp"
#include "socket_util.hpp"

namespace robogene::net {

namespace {
timeval to_timeval(Millis t) {
  timeval tv{};
  tv.tv_sec = static_cast<time_t>(t.count() / 1000);
  tv.tv_usec = static_cast<suseconds_t>((t.count() % 1000) * 1000);
  return tv;
}
}  // namespace

TcpStream::TcpStream(UniqueFd fd) : fd_(std::move(fd)) {
  peer_ = detail::peer_of(fd_.get());
  local_ = detail::local_of(fd_.get());
  set_nodelay(true);
}

TcpStream TcpStream::connect(const Endpoint& to, Millis timeout) {
  sockaddr_in addr = detail::to_sockaddr(to);
  UniqueFd fd(::socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC | SOCK_NONBLOCK, 0));
  if (!fd.valid()) {
    throw NetworkError("cannot create a socket to connect to " + to.to_string() + ": " +
                       detail::errno_text(errno));
  }
  int rc;
  do {
    rc = ::connect(fd.get(), reinterpret_cast<sockaddr*>(&addr), sizeof addr);
  } while (rc != 0 && errno == EINTR);
  if (rc != 0 && errno != EINPROGRESS) {
    throw NetworkError("cannot connect to " + to.to_string() + ": " + detail::errno_text(errno));
  }
  if (rc != 0) {
    pollfd p{fd.get(), POLLOUT, 0};
    int ready;
    do {
      ready = ::poll(&p, 1, timeout.count() > 0 ? static_cast<int>(timeout.count()) : -1);
    } while (ready < 0 && errno == EINTR);
    if (ready == 0) {
      throw NetworkError("cannot connect to " + to.to_string() + ": timed out after " +
                         std::to_string(timeout.count()) + " ms");
    }
    int err = 0;
    socklen_t len = sizeof err;
    ::getsockopt(fd.get(), SOL_SOCKET, SO_ERROR, &err, &len);
    if (err != 0) {
      throw NetworkError("cannot connect to " + to.to_string() + ": " + detail::errno_text(err));
    }
  }
  int flags = ::fcntl(fd.get(), F_GETFL);
  ::fcntl(fd.get(), F_SETFL, flags & ~O_NONBLOCK);
  TcpStream s(std::move(fd));
  if (s.peer_.host.empty()) s.peer_ = to;
  return s;
}

void TcpStream::set_read_timeout(Millis t) {
  timeval tv = to_timeval(t);
  ::setsockopt(fd_.get(), SOL_SOCKET, SO_RCVTIMEO, &tv, sizeof tv);
}

void TcpStream::set_write_timeout(Millis t) {
  timeval tv = to_timeval(t);
  ::setsockopt(fd_.get(), SOL_SOCKET, SO_SNDTIMEO, &tv, sizeof tv);
}

void TcpStream::set_nodelay(bool on) {
  int v = on ? 1 : 0;
  ::setsockopt(fd_.get(), IPPROTO_TCP, TCP_NODELAY, &v, sizeof v);
}

void TcpStream::fail(const char* doing, int err) const {
  if (err == EAGAIN || err == EWOULDBLOCK) {
    throw NetworkError(std::string(doing) + " peer " + peer_text() + ": timed out");
  }
  throw NetworkError(std::string(doing) + " peer " + peer_text() + ": " + detail::errno_text(err));
}

void TcpStream::read_exact(void* data, std::size_t size) {
  auto* p = static_cast<std::uint8_t*>(data);
  std::size_t got = 0;
  while (got < size) {
    ssize_t n = ::recv(fd_.get(), p + got, size - got, 0);
    if (n > 0) {
      got += static_cast<std::size_t>(n);
      continue;
    }
    if (n == 0) {
      throw NetworkError("peer " + peer_text() + " closed the connection after " +
                         std::to_string(got) + " of " + std::to_string(size) + " expected bytes");
    }
    if (errno == EINTR) continue;
    fail("reading from", errno);
  }
}

std::size_t TcpStream::read_some(void* data, std::size_t size) {
  for (;;) {
    ssize_t n = ::recv(fd_.get(), data, size, 0);
    if (n >= 0) return static_cast<std::size_t>(n);
    if (errno == EINTR) continue;
    if (errno == ECONNRESET) return 0;  // a vanished peer ends the stream like EOF
    fail("reading from", errno);
  }
}

bool TcpStream::wait_readable(Millis timeout) const {
  return detail::poll_readable(fd_.get(), -1, timeout) == 1;
}

void TcpStream::write_all(const void* data, std::size_t size) {
  iovec v{const_cast<void*>(data), size};
  writev_all(&v, 1);
}

void TcpStream::writev_all(iovec* iov, std::size_t count) {
  while (count > 0 && iov->iov_len == 0) {
    ++iov;
    --count;
  }
  while (count > 0) {
    msghdr msg{};
    msg.msg_iov = iov;
    msg.msg_iovlen = count > IOV_MAX ? IOV_MAX : count;
    ssize_t n = ::sendmsg(fd_.get(), &msg, MSG_NOSIGNAL);
    if (n < 0) {
      if (errno == EINTR) continue;
      fail("writing to", errno);
    }
    auto left = static_cast<std::size_t>(n);
    while (count > 0 && left >= iov->iov_len) {
      left -= iov->iov_len;
      ++iov;
      --count;
    }
    if (count > 0) {
      iov->iov_base = static_cast<std::uint8_t*>(iov->iov_base) + left;
      iov->iov_len -= left;
    }
  }
}

void TcpStream::shutdown() noexcept {
  if (fd_.valid()) ::shutdown(fd_.get(), SHUT_RDWR);
}

void TcpStream::close() noexcept { fd_.reset(); }

}  // namespace robogene::net
