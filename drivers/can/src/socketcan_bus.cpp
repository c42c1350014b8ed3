// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "robogene/can/socketcan_bus.hpp"

#include <errno.h>
#include <linux/can.h>
#include <linux/can/error.h>
#include <linux/can/raw.h>
#include <net/if.h>
#include <poll.h>
#include <sys/ioctl.h>
#include <sys/socket.h>
#include <unistd.h>

#include <chrono>
#include <cstring>

namespace robogene::can {
namespace {

// Waits for `events` on fd until the deadline; false on timeout. EINTR just waits again.
bool wait_for(int fd, short events, std::chrono::steady_clock::time_point deadline) {
  for (;;) {
    const auto left = std::chrono::duration_cast<Millis>(deadline - std::chrono::steady_clock::now());
    pollfd p{fd, events, 0};
    const int n = ::poll(&p, 1, left.count() > 0 ? static_cast<int>(left.count()) : 0);
    if (n > 0) return true;
    if (n == 0) return false;
    if (errno != EINTR) return true;  // let the following call report the error
  }
}

}  // namespace

SocketCanBus::SocketCanBus(const std::string& interface) : interface_(interface) {
  if (interface.empty() || interface.size() >= IFNAMSIZ) {
    throw BusError(BusErrorKind::io, "socketcan: interface name \"" + interface +
                                         "\" must have 1 to " + std::to_string(IFNAMSIZ - 1) + " characters");
  }
  fd_ = ::socket(PF_CAN, SOCK_RAW | SOCK_CLOEXEC, CAN_RAW);
  if (fd_ < 0) {
    const int err = errno;
    if (err == EAFNOSUPPORT) {
      throw BusError(BusErrorKind::io, name() + ": this kernel has no SocketCAN (socket(PF_CAN) failed: " +
                                           std::strerror(err) + "); load the can and can-raw modules");
    }
    fail("socket(PF_CAN)", err);
  }
  const unsigned index = ::if_nametoindex(interface.c_str());
  if (index == 0) {
    const int err = errno;
    ::close(fd_);
    fd_ = -1;
    throw BusError(BusErrorKind::io, name() + ": no such network interface (" + std::strerror(err) +
                                         "); create it, e.g. `ip link add dev " + interface + " type vcan`");
  }
  const can_err_mask_t errors = CAN_ERR_MASK;  // report every class of controller error
  if (::setsockopt(fd_, SOL_CAN_RAW, CAN_RAW_ERR_FILTER, &errors, sizeof errors) != 0) {
    const int err = errno;
    ::close(fd_);
    fd_ = -1;
    fail("setsockopt(CAN_RAW_ERR_FILTER)", err);
  }
  try {
    set_filters({});
  } catch (...) {
    ::close(fd_);
    fd_ = -1;
    throw;
  }
  sockaddr_can addr{};
  addr.can_family = AF_CAN;
  addr.can_ifindex = static_cast<int>(index);
  if (::bind(fd_, reinterpret_cast<sockaddr*>(&addr), sizeof addr) != 0) {
    const int err = errno;
    ::close(fd_);
    fd_ = -1;
    fail("bind", err);
  }
}

SocketCanBus::~SocketCanBus() {
  if (fd_ >= 0) ::close(fd_);
}

void SocketCanBus::fail(const std::string& doing, int err) const {
  throw BusError(BusErrorKind::io, name() + ": " + doing + " failed: " + std::strerror(err));
}

void SocketCanBus::set_filters(const std::vector<Filter>& filters) {
  // Standard data frames only: the EFF and RTR flags are part of every mask and clear in every id.
  std::vector<can_filter> raw;
  if (filters.empty()) {
    raw.push_back({0, CAN_EFF_FLAG | CAN_RTR_FLAG});
  } else {
    for (const auto& f : filters) {
      raw.push_back({static_cast<canid_t>(f.id & kMaxStandardId),
                     static_cast<canid_t>((f.mask & kMaxStandardId) | CAN_EFF_FLAG | CAN_RTR_FLAG)});
    }
  }
  if (::setsockopt(fd_, SOL_CAN_RAW, CAN_RAW_FILTER, raw.data(),
                   static_cast<socklen_t>(raw.size() * sizeof(can_filter))) != 0) {
    fail("setsockopt(CAN_RAW_FILTER)", errno);
  }
}

void SocketCanBus::send(const Frame& frame, Millis timeout) {
  validate(frame);
  can_frame raw{};
  raw.can_id = frame.id;
  raw.can_dlc = frame.len;
  std::memcpy(raw.data, frame.data.data(), frame.len);
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  for (;;) {
    const ssize_t n = ::send(fd_, &raw, sizeof raw, MSG_DONTWAIT);
    if (n == static_cast<ssize_t>(sizeof raw)) return;
    if (n >= 0) fail("send (short write)", EIO);
    const int err = errno;
    if (err == EINTR) continue;
    // A full transmit queue (ENOBUFS on CAN) is what a bus nobody acknowledges looks like.
    if (err == EAGAIN || err == ENOBUFS) {
      if (std::chrono::steady_clock::now() >= deadline) {
        throw BusError(BusErrorKind::timeout, name() + ": could not send " + to_string(frame) + " within " +
                                                  std::to_string(timeout.count()) +
                                                  " ms (transmit queue full: is the bus acknowledged?)");
      }
      wait_for(fd_, POLLOUT, std::min(deadline, std::chrono::steady_clock::now() + Millis(2)));
      continue;
    }
    if (err == ENETDOWN) {
      throw BusError(BusErrorKind::io, name() + ": interface is down; cannot send " + to_string(frame));
    }
    fail("send " + to_string(frame), err);
  }
}

std::optional<Frame> SocketCanBus::receive(Millis timeout) {
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  for (;;) {
    if (!wait_for(fd_, POLLIN, deadline)) return std::nullopt;
    can_frame raw{};
    const ssize_t n = ::recv(fd_, &raw, sizeof raw, MSG_DONTWAIT);
    if (n < 0) {
      const int err = errno;
      if (err == EAGAIN || err == EINTR) continue;
      if (err == ENETDOWN) throw BusError(BusErrorKind::io, name() + ": interface went down");
      fail("recv", err);
    }
    if (n != static_cast<ssize_t>(sizeof raw)) continue;  // CAN FD frames are not ours
    if (raw.can_id & CAN_ERR_FLAG) {
      ErrorFrame e;
      e.can_id = raw.can_id;
      std::memcpy(e.data.data(), raw.data, 8);
      throw decode_error_frame(name(), e);
    }
    if (raw.can_id & (CAN_EFF_FLAG | CAN_RTR_FLAG)) continue;  // filtered by the kernel already
    Frame f;
    f.id = static_cast<std::uint16_t>(raw.can_id & CAN_SFF_MASK);
    f.len = raw.can_dlc > 8 ? 8 : raw.can_dlc;
    std::memcpy(f.data.data(), raw.data, f.len);
    return f;
  }
}

}  // namespace robogene::can
