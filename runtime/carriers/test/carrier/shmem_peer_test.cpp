// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// Attack by a local shmem peer: it rewrites the ring's capacity and head in the shared segment
// after the handshake (the acceptor used to read both on every operation: a division by zero,
// reads outside the ring); and many handshakes that never confirm, each of which used to
// create a 9 MB segment.
#include <gtest/gtest.h>

#include <fcntl.h>
#include <sys/mman.h>
#include <unistd.h>

#include "../../src/carrier/shm_segment.hpp"
#include "robogene/testing/hostile_util.hpp"
#include "robogene/log.hpp"

using namespace robogene;
using namespace robogene::test;
using namespace std::chrono_literals;

namespace {

constexpr std::int32_t kShmemSpecifier = 7777 + 14;

// The initiator's half of a shmem handshake, by hand; `confirm` false leaves it unfinished.
struct RawShmemPeer {
  net::TcpStream tcp;
  std::unique_ptr<carrier::detail::ShmSegment> seg;

  RawShmemPeer(const Port& p, const std::string& sender, bool confirm) : tcp(connect_to(p)) {
    send(tcp, hello(kShmemSpecifier, sender));
    auto n = read_n(tcp, 8);
    auto len = carrier::read_yarp_number(n.data());
    if (!len) throw Error("no YA <n> RP");
    auto name = read_n(tcp, static_cast<std::size_t>(*len));
    if (confirm) {
      seg = carrier::detail::ShmSegment::open(std::string(name.begin(), name.end() - 1));
      auto ack = carrier::make_yarp_number(0);
      tcp.write_all(ack.data(), ack.size());
    }
  }
};

std::size_t segments_of_this_process() {
  const std::string prefix = "robogene-shmem-" + std::to_string(::getpid()) + "-";
  std::size_t n = 0;
  if (DIR* d = ::opendir("/dev/shm")) {
    while (dirent* e = ::readdir(d)) {
      if (std::string(e->d_name).rfind(prefix, 0) == 0) ++n;
    }
    ::closedir(d);
  }
  return n;
}

}  // namespace

TEST(HostileShmem, PeerRewritingCapacityAndHeadCannotCrashTheReader) {
  log::set_level(log::Level::Error);
  Port r;
  r.open_at("/r", {"127.0.0.1", 0});
  {
    RawShmemPeer peer(r, "/evil", true);
    ASSERT_TRUE(wait_until([&] { return r.input_names().size() == 1; }));
    auto& ring = peer.seg->ring(0);  // initiator to acceptor
    ring.capacity = 0;               // was a SIGFPE in the acceptor (head % capacity)
    ring.head.store(100);
    std::this_thread::sleep_for(300ms);
  }
  {
    RawShmemPeer peer(r, "/evil2", true);
    ASSERT_TRUE(wait_until([&] { return r.input_names().size() == 1; }));
    peer.seg->ring(0).head.store(std::uint64_t{1} << 40);  // far more than the ring holds
    EXPECT_TRUE(wait_until([&] { return r.input_names().empty(); })) << "the lying peer is dropped";
  }
  EXPECT_TRUE(legit_client_served(r));
}

TEST(HostileShmem, UnconfirmedHandshakesCreateABoundedNumberOfSegments) {
  log::set_level(log::Level::Error);
  ResourceLimits l = resource_limits();
  l.max_shmem_segments = 8;
  ScopedLimits scoped(l);
  Port r;
  r.open_at("/r", {"127.0.0.1", 0});
  const ProcessUsage before = ProcessUsage::now();
  std::vector<std::unique_ptr<RawShmemPeer>> peers;
  for (int i = 0; i < 40; ++i) {
    try {
      peers.push_back(std::make_unique<RawShmemPeer>(r, "/hold" + std::to_string(i), false));
    } catch (const std::exception&) {
      // Refused: no segment for this one.
    }
  }
  EXPECT_LE(segments_of_this_process(), 8u);
  EXPECT_LE(peers.size(), 8u);
  peers.clear();
  const ProcessUsage after = usage_when(
      [&](const ProcessUsage& u) { return u.threads <= before.threads + kDeadlineTimerThread; });
  EXPECT_LE(after.threads, before.threads + kDeadlineTimerThread) << after.text();
  EXPECT_EQ(segments_of_this_process(), 0u);
  EXPECT_TRUE(legit_client_served(r));
}
