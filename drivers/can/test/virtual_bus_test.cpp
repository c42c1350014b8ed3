// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
#include <dirent.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/un.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstring>

#include <gtest/gtest.h>

#include "robogene/can/virtual_bus.hpp"
#include "test_bus_dir.hpp"

namespace robogene::can {
namespace {

using std::chrono::steady_clock;
constexpr Millis kWait{1000};

class VirtualBusTest : public ::testing::Test {
 protected:
  testing::TempBusDir dir_;
};

TEST_F(VirtualBusTest, EveryNodeSeesEveryOtherNodesFramesButNotItsOwn) {
  VirtualBus a("head"), b("head"), c("head");
  a.send(Frame(0x123, {0xDE, 0xAD}), kWait);
  for (VirtualBus* n : {&b, &c}) {
    auto f = n->receive(kWait);
    ASSERT_TRUE(f);
    EXPECT_EQ(*f, Frame(0x123, {0xDE, 0xAD}));
  }
  EXPECT_FALSE(a.receive(Millis(50)));
  c.send(Frame(0x7FF, {1, 2, 3, 4, 5, 6, 7, 8}), kWait);
  EXPECT_EQ(*a.receive(kWait), Frame(0x7FF, {1, 2, 3, 4, 5, 6, 7, 8}));
  EXPECT_EQ(*b.receive(kWait), Frame(0x7FF, {1, 2, 3, 4, 5, 6, 7, 8}));
}

TEST_F(VirtualBusTest, BusesWithDifferentNamesAreSeparate) {
  VirtualBus a("left"), b("right");
  a.send(Frame(0x1, {}), kWait);
  EXPECT_FALSE(b.receive(Millis(50)));
}

TEST_F(VirtualBusTest, FiltersDropOtherIds) {
  VirtualBus a("f"), b("f");
  b.set_filters({{0x100, 0x700}});
  a.send(Frame(0x010, {1}), kWait);
  a.send(Frame(0x131, {2}), kWait);
  auto f = b.receive(kWait);
  ASSERT_TRUE(f);
  EXPECT_EQ(f->id, 0x131);
  b.set_filters({});
  a.send(Frame(0x010, {3}), kWait);
  EXPECT_EQ(b.receive(kWait)->id, 0x010);
}

TEST_F(VirtualBusTest, ReceiveTimesOutWithNothing) {
  VirtualBus a("t");
  const auto start = steady_clock::now();
  EXPECT_FALSE(a.receive(Millis(80)));
  EXPECT_GE(steady_clock::now() - start, Millis(75));
}

TEST_F(VirtualBusTest, WorksAcrossProcesses) {
  VirtualBus parent("proc");
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    int rc = 1;
    try {
      VirtualBus node("proc");
      node.send(Frame(0x0B0, {0x14, 0x01}), kWait);  // announce, then echo one frame back
      if (auto f = node.receive(Millis(3000))) {
        Frame echo = *f;
        echo.id = 0x0B1;
        node.send(echo, kWait);
        rc = 0;
      }
    } catch (...) {
    }
    ::_exit(rc);
  }
  auto hello = parent.receive(Millis(3000));
  ASSERT_TRUE(hello);
  EXPECT_EQ(*hello, Frame(0x0B0, {0x14, 0x01}));
  parent.send(Frame(0x00B, {0x14}), kWait);
  auto echo = parent.receive(Millis(3000));
  ASSERT_TRUE(echo);
  EXPECT_EQ(*echo, Frame(0x0B1, {0x14}));
  int status = 0;
  ASSERT_EQ(::waitpid(child, &status, 0), child);
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0);
}

TEST_F(VirtualBusTest, InjectedErrorFramesReachEveryOtherNodeAsBusErrors) {
  VirtualBus a("e"), b("e"), tester("e");
  tester.inject_error(make_error_frame(BusErrorKind::bus_off));
  for (VirtualBus* n : {&a, &b}) {
    try {
      n->receive(kWait);
      FAIL() << "bus-off not reported";
    } catch (const BusError& e) {
      EXPECT_EQ(e.kind(), BusErrorKind::bus_off);
      EXPECT_NE(std::string(e.what()).find("virtual:e"), std::string::npos) << e.what();
    }
  }
  // Filters never hide errors.
  a.set_filters({{0x7FF, 0x7FF}});
  tester.inject_error(make_error_frame(BusErrorKind::error_passive));
  EXPECT_THROW(a.receive(kWait), BusError);
}

TEST_F(VirtualBusTest, DeadNodesAreForgottenAndTheirSocketsRemoved) {
  VirtualBus a("d");
  const std::string dir = VirtualBus::directory_for("d");
  {
    VirtualBus gone("d");
    a.send(Frame(0x1, {}), kWait);
  }
  // A node killed without cleaning up leaves its socket file behind.
  const std::string stale = dir + "/99999999-0";
  {
    int fd = ::socket(AF_UNIX, SOCK_DGRAM, 0);
    sockaddr_un addr{};
    addr.sun_family = AF_UNIX;
    std::strcpy(addr.sun_path, stale.c_str());
    ASSERT_EQ(::bind(fd, reinterpret_cast<sockaddr*>(&addr), sizeof addr), 0);
    ::close(fd);
  }
  VirtualBus b("d");
  a.send(Frame(0x2, {7}), kWait);
  EXPECT_EQ(*b.receive(kWait), Frame(0x2, {7}));
  struct stat st {};
  EXPECT_NE(::stat(stale.c_str(), &st), 0) << "stale socket still there";
}

TEST_F(VirtualBusTest, ANodeThatDoesNotReadLosesFramesWithoutStallingTheSender) {
  VirtualBus sender("c"), sleeper("c"), reader("c");
  const auto start = steady_clock::now();
  int got = 0;
  for (int i = 0; i < 200; ++i) {
    sender.send(Frame(0x10, {static_cast<std::uint8_t>(i)}), kWait);
    while (reader.receive(Millis(0))) ++got;
  }
  while (reader.receive(Millis(20))) ++got;
  EXPECT_LT(steady_clock::now() - start, std::chrono::seconds(3));
  EXPECT_EQ(got, 200) << "a reading node lost frames";
  EXPECT_GT(sender.dropped(), 0U);
}

TEST_F(VirtualBusTest, GarbageDatagramsAreDroppedNotFatal) {
  VirtualBus a("g"), b("g");
  const std::string dir = VirtualBus::directory_for("g");
  const int fd = ::socket(AF_UNIX, SOCK_DGRAM, 0);
  DIR* d = ::opendir(dir.c_str());
  ASSERT_NE(d, nullptr);
  int sent = 0;
  while (const dirent* e = ::readdir(d)) {
    if (e->d_name[0] == '.') continue;
    sockaddr_un addr{};
    addr.sun_family = AF_UNIX;
    const std::string path = dir + "/" + e->d_name;
    ASSERT_LT(path.size(), sizeof addr.sun_path);
    std::memcpy(addr.sun_path, path.c_str(), path.size() + 1);
    for (const std::string junk : {"hello", "RGC1 but far too long for a frame..."}) {
      sent += ::sendto(fd, junk.data(), junk.size(), 0, reinterpret_cast<sockaddr*>(&addr), sizeof addr) > 0;
    }
  }
  ::closedir(d);
  ::close(fd);
  EXPECT_EQ(sent, 4);
  a.send(Frame(0x55, {5}), kWait);
  EXPECT_EQ(*b.receive(kWait), Frame(0x55, {5}));
}

TEST_F(VirtualBusTest, BadNamesAreRefusedWithTheName) {
  for (const char* bad : {"a/b", "", "..", "sp ace"}) {
    try {
      VirtualBus bus(bad);
      FAIL() << bad;
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find(std::string("\"") + bad + "\""), std::string::npos) << e.what();
    }
  }
}

}  // namespace
}  // namespace robogene::can
