// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// Where the SocketCAN tests run: the interface named by ROBOGENE_CAN_VCAN. When that is set the
// kernel must have CAN (a failure then is a real failure, never a skip).
#pragma once

#include <linux/can.h>
#include <net/if.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cstdlib>
#include <string>

#include <gtest/gtest.h>

namespace robogene::can::testing {

inline constexpr const char* kSkipReason =
    "set ROBOGENE_CAN_VCAN=vcan0 on a kernel with SocketCAN (make test-can-vm does, inside qemu)";

inline bool kernel_has_can() {
  const int fd = ::socket(PF_CAN, SOCK_RAW, CAN_RAW);
  if (fd < 0) return false;
  ::close(fd);
  return true;
}

inline std::string vcan_or_skip() {
  const char* name = std::getenv("ROBOGENE_CAN_VCAN");
  if (!name || !*name) return "";
  EXPECT_TRUE(kernel_has_can()) << "ROBOGENE_CAN_VCAN is set but this kernel has no SocketCAN";
  return name;
}

// A plain raw socket bound to `iface`, for writing frames our Bus would refuse to send.
inline int raw_socket(const std::string& iface) {
  const int fd = ::socket(PF_CAN, SOCK_RAW, CAN_RAW);
  sockaddr_can addr{};
  addr.can_family = AF_CAN;
  addr.can_ifindex = static_cast<int>(::if_nametoindex(iface.c_str()));
  EXPECT_EQ(::bind(fd, reinterpret_cast<sockaddr*>(&addr), sizeof addr), 0);
  return fd;
}

}  // namespace robogene::can::testing
