// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// The SocketCAN backend against a real kernel. ROBOGENE_CAN_VCAN names an up vcan interface and
// ROBOGENE_CAN_VCAN_DOWN one that is down (make test-can-vm sets both inside its qemu VM); without
// them these tests skip, except the one for a kernel without CAN, which runs where that is true.
#include <linux/can.h>
#include <linux/can/error.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cstdlib>
#include <cstring>

#include <gtest/gtest.h>

#include "robogene/can/bus.hpp"
#include "robogene/can/socketcan_bus.hpp"
#include "socketcan_env.hpp"

namespace robogene::can {
namespace {

constexpr Millis kWait{1000};

TEST(SocketCan, TwoSocketsSeeEachOthersFramesButNotTheirOwn) {
  const std::string iface = testing::vcan_or_skip();
  if (iface.empty()) GTEST_SKIP() << testing::kSkipReason;
  auto a = open_bus("socketcan:" + iface);
  auto b = open_bus("socketcan:" + iface);
  EXPECT_EQ(a->name(), "socketcan:" + iface);
  EXPECT_EQ(a->interface(), iface);
  a->send(Frame(0x123, {0xDE, 0xAD, 0xBE, 0xEF}), kWait);
  auto f = b->receive(kWait);
  ASSERT_TRUE(f);
  EXPECT_EQ(*f, Frame(0x123, {0xDE, 0xAD, 0xBE, 0xEF}));
  EXPECT_FALSE(a->receive(Millis(100)));
  b->send(Frame(0x7FF, {}), kWait);
  EXPECT_EQ(*a->receive(kWait), Frame(0x7FF, {}));
}

TEST(SocketCan, KernelFiltersDropOtherIdsAndExtendedFrames) {
  const std::string iface = testing::vcan_or_skip();
  if (iface.empty()) GTEST_SKIP() << testing::kSkipReason;
  SocketCanBus rx(iface);
  rx.set_filters({{0x100, 0x700}});
  // An extended frame from a plain raw socket: the head never uses them, the filter drops them.
  const int raw = testing::raw_socket(iface);
  can_frame eff{};
  eff.can_id = 0x101 | CAN_EFF_FLAG;
  eff.can_dlc = 1;
  ASSERT_EQ(::write(raw, &eff, sizeof eff), static_cast<ssize_t>(sizeof eff));
  ::close(raw);
  SocketCanBus tx(iface);
  tx.send(Frame(0x031, {1}), kWait);
  tx.send(Frame(0x131, {2}), kWait);
  auto f = rx.receive(kWait);
  ASSERT_TRUE(f);
  EXPECT_EQ(*f, Frame(0x131, {2}));
  EXPECT_FALSE(rx.receive(Millis(100)));
}

TEST(SocketCan, ErrorFramesArriveAsBusErrorsThroughTheFilters) {
  const std::string iface = testing::vcan_or_skip();
  if (iface.empty()) GTEST_SKIP() << testing::kSkipReason;
  SocketCanBus rx(iface);
  rx.set_filters({{0x7FF, 0x7FF}});
  // vcan passes on whatever is written, error frames included: what a controller would report.
  const int raw = testing::raw_socket(iface);
  for (BusErrorKind k : {BusErrorKind::bus_off, BusErrorKind::error_passive}) {
    const ErrorFrame e = make_error_frame(k);
    can_frame cf{};
    cf.can_id = e.can_id;
    cf.can_dlc = CAN_ERR_DLC;
    std::memcpy(cf.data, e.data.data(), 8);
    ASSERT_EQ(::write(raw, &cf, sizeof cf), static_cast<ssize_t>(sizeof cf)) << std::strerror(errno);
    try {
      rx.receive(kWait);
      FAIL() << name_of(k) << " not reported";
    } catch (const BusError& err) {
      EXPECT_EQ(err.kind(), k) << err.what();
      EXPECT_NE(std::string(err.what()).find("socketcan:" + iface), std::string::npos) << err.what();
    }
  }
  ::close(raw);
}

TEST(SocketCan, MissingInterfaceIsNamed) {
  const std::string iface = testing::vcan_or_skip();
  if (iface.empty()) GTEST_SKIP() << testing::kSkipReason;
  try {
    SocketCanBus bus("nosuchcan0");
    FAIL();
  } catch (const BusError& e) {
    EXPECT_EQ(e.kind(), BusErrorKind::io);
    EXPECT_NE(std::string(e.what()).find("socketcan:nosuchcan0: no such network interface"), std::string::npos)
        << e.what();
  }
}

TEST(SocketCan, SendingOnADownInterfaceIsAnError) {
  const char* down = std::getenv("ROBOGENE_CAN_VCAN_DOWN");
  if (testing::vcan_or_skip().empty() || !down) GTEST_SKIP() << testing::kSkipReason;
  SocketCanBus bus(down);
  try {
    bus.send(Frame(0x001, {0x14}), kWait);
    FAIL() << "send on a down interface succeeded";
  } catch (const BusError& e) {
    EXPECT_EQ(e.kind(), BusErrorKind::io);
    EXPECT_NE(std::string(e.what()).find("down"), std::string::npos) << e.what();
  }
}

TEST(SocketCan, ReceiveTimesOut) {
  const std::string iface = testing::vcan_or_skip();
  if (iface.empty()) GTEST_SKIP() << testing::kSkipReason;
  SocketCanBus bus(iface);
  bus.set_filters({{0x5A5, 0x7FF}});
  const auto start = std::chrono::steady_clock::now();
  EXPECT_FALSE(bus.receive(Millis(100)));
  EXPECT_GE(std::chrono::steady_clock::now() - start, Millis(95));
}

// Runs where the kernel has no CAN (this project's usual build machine): the error must say so.
TEST(SocketCanWithoutKernelSupport, SaysTheKernelHasNoSocketCan) {
  if (testing::kernel_has_can()) GTEST_SKIP() << "this kernel has SocketCAN";
  try {
    open_bus("socketcan:vcan0");
    FAIL();
  } catch (const BusError& e) {
    EXPECT_EQ(e.kind(), BusErrorKind::io);
    EXPECT_NE(std::string(e.what()).find("this kernel has no SocketCAN"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace robogene::can
