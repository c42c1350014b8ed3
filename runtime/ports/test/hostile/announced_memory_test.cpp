// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// Attacks on memory by announcement: a peer announces a big message (or a big ack skip, or a
// list whose items decode to far more memory than their bytes) and sends little or nothing of
// it. Memory must follow the bytes that arrive, within per-message and per-process limits.
#include <gtest/gtest.h>

#include <atomic>
#include <mutex>

#include "robogene/testing/hostile_util.hpp"
#include "robogene/log.hpp"
#include "robogene/net/tcp_listener.hpp"

using namespace robogene;
using namespace robogene::test;
using namespace std::chrono_literals;

namespace {

// The framing of one 'D' message whose payload is announced as `payload_size` bytes.
std::vector<std::uint8_t> message_head(std::int32_t payload_size) {
  std::vector<std::uint8_t> out;
  auto idx = carrier::make_yarp_number(carrier::kIndexLength);
  out.insert(out.end(), idx.begin(), idx.end());
  out.push_back(2);  // blocks in: the command, the payload
  out.push_back(1);  // blocks out: the reply slot
  out.insert(out.end(), 8, 0xff);
  std::uint8_t n[4];
  for (std::int32_t len : {8, payload_size, 0}) {
    carrier::put_int32(n, len);
    out.insert(out.end(), n, n + 4);
  }
  const std::uint8_t command[8] = {0, 0, 0, 0, '~', 'D', 0, 1};
  out.insert(out.end(), command, command + 8);
  return out;
}

void put(std::vector<std::uint8_t>& out, std::int32_t v) {
  std::uint8_t n[4];
  carrier::put_int32(n, v);
  out.insert(out.end(), n, n + 4);
}

// A tcp connection to `r` that has done its handshake.
net::TcpStream handshaken(const Port& r, const std::string& sender) {
  auto s = connect_to(r);
  send(s, hello(carrier::kTcpSpecifier, sender));
  read_n(s, 8);
  return s;
}

// A message announcing one blob of `blob_size` bytes, of which the first `sent` follow.
std::vector<std::uint8_t> announced_blob(std::int32_t blob_size, std::size_t sent) {
  auto out = message_head(16 + blob_size);
  put(out, 0x100);  // a bottle of tagged items
  put(out, 1);
  put(out, 12);     // a blob
  put(out, blob_size);
  out.insert(out.end(), sent, 0x5a);
  return out;
}

bool closed_by_port(net::TcpStream& s, std::chrono::milliseconds within) {
  s.set_read_timeout(within);
  char c;
  try {
    return s.read_some(&c, 1) == 0;
  } catch (const NetworkError& e) {
    return std::string(e.what()).find("timed out") == std::string::npos &&
           std::string(e.what()).find("Resource temporarily") == std::string::npos;
  }
}

}  // namespace

TEST(HostileAnnounce, BigAnnouncedMessagesCostOnlyWhatArrives) {
  log::set_level(log::Level::Error);
  Port r;
  r.open_at("/r", {"127.0.0.1", 0});
  ProcessUsage::reset_peak_rss();
  const ProcessUsage before = ProcessUsage::now();
  // 8 peers each announce a 60 MB image and send 44 bytes of it, then wait.
  std::vector<net::TcpStream> peers;
  for (int i = 0; i < 8; ++i) {
    peers.push_back(handshaken(r, "/big" + std::to_string(i)));
    send(peers.back(), announced_blob(60 << 20, 4));
  }
  std::this_thread::sleep_for(1000ms);
  const ProcessUsage after = ProcessUsage::now();
  // 64 KB of buffer per peer would be plenty; 32 MB in all leaves room for the allocator.
  EXPECT_LT(after.peak_rss_kb, before.rss_kb + 32 * 1024)
      << "before: " << before.text() << "; after: " << after.text();
  EXPECT_TRUE(legit_client_served(r));
  peers.clear();
}

TEST(HostileAnnounce, HugeAckSkipMakesNoWriterAllocate) {
  log::set_level(log::Level::Error);
  // A "reader" that answers the handshake and then acks the first message with a skip length
  // of 2 GB, and sends nothing more.
  auto listener = net::TcpListener::listen({"127.0.0.1", 0});
  std::thread reader([&] {
    auto s = listener.accept(5000ms);
    if (!s) return;
    try {
      read_n(*s, 8);
      auto len = read_n(*s, 4);
      read_n(*s, static_cast<std::size_t>(carrier::get_int32(len.data())));
      auto answer = carrier::make_yarp_number(listener.local().port);
      s->write_all(answer.data(), answer.size());
      char buf[4096];
      s->set_read_timeout(5000ms);
      s->read_some(buf, sizeof buf);  // the message
      auto ack = carrier::make_yarp_number(0x7fffffff);
      s->write_all(ack.data(), ack.size());
      s->read_some(buf, sizeof buf);  // until the writer gives up
    } catch (const std::exception&) {
    }
  });
  Port w;
  w.open_at("/w", {"127.0.0.1", 0});
  w.add_output(Contact{"/evil", "tcp", "127.0.0.1", listener.local().port});
  ProcessUsage::reset_peak_rss();
  const ProcessUsage before = ProcessUsage::now();
  w.write(Bottle{Value("hello")});
  const ProcessUsage after = ProcessUsage::now();
  reader.join();
  EXPECT_LT(after.peak_rss_kb, before.rss_kb + 32 * 1024)
      << "before: " << before.text() << "; after: " << after.text();
  EXPECT_TRUE(w.output_names().empty()) << "the reader with the absurd ack is dropped";

  Port r;
  r.open_at("/r", {"127.0.0.1", 0});
  EXPECT_TRUE(legit_client_served(r, "/w2"));
}

TEST(HostileAnnounce, ListOfTinyIntsDoesNotDecodeBeyondTheValueLimit) {
  log::set_level(log::Level::Error);
  Port r;
  r.open_at("/r", {"127.0.0.1", 0});
  std::atomic<std::size_t> biggest{0};
  r.set_reader([&](const Bottle& b, const MessageInfo&, Bottle*) {
    std::size_t n = b.size() == 1 && b.get(0).is_list() ? b.get(0).as_list().size() : b.size();
    if (n > biggest) biggest = n;
  });
  // 6 M int8s: 6 MB on the wire, 96 MB as Values; the default limit is 4 M values.
  const std::int32_t count = 6 << 20;
  std::vector<std::uint8_t> payload;
  put(payload, 0x100 | 32);  // a list of int8
  put(payload, count);
  payload.insert(payload.end(), static_cast<std::size_t>(count), 7);
  auto msg = message_head(static_cast<std::int32_t>(payload.size()));
  msg.insert(msg.end(), payload.begin(), payload.end());
  ProcessUsage::reset_peak_rss();
  const ProcessUsage before = ProcessUsage::now();
  {
    auto s = handshaken(r, "/ints");
    send(s, msg);
    std::this_thread::sleep_for(1000ms);
  }
  const ProcessUsage after = ProcessUsage::now();
  EXPECT_EQ(biggest.load(), 0u) << "a 6 M-item list passes the 4 M-value limit and is dropped";
  // The 6 MB received (a buffer of up to twice that) but not the 96 MB of Values.
  EXPECT_LT(after.peak_rss_kb, before.rss_kb + 48 * 1024)
      << "before: " << before.text() << "; after: " << after.text();
  r.set_reader({});
  EXPECT_TRUE(legit_client_served(r));
}

TEST(HostileAnnounce, ProcessWideBudgetCutsPeersHoldingPartlySentMessages) {
  log::set_level(log::Level::Error);
  ResourceLimits l = resource_limits();
  l.max_receiving_bytes = 8u << 20;
  ScopedLimits scoped(l);
  Port r;
  r.open_at("/r", {"127.0.0.1", 0});
  // The attackers live in this process too: one 3 MB message, made before the baseline, serves them
  // all, so the peak measures the port's buffers and not 16 copies of the attack.
  const auto partial = announced_blob(32 << 20, 3 << 20);
  ProcessUsage::reset_peak_rss();
  const ProcessUsage before = ProcessUsage::now();
  // 16 peers each send 3 MB of an announced 32 MB blob and stall: 48 MB held without limits.
  std::vector<net::TcpStream> peers;
  for (int i = 0; i < 16; ++i) {
    peers.push_back(handshaken(r, "/part" + std::to_string(i)));
    try {
      peers.back().set_write_timeout(2000ms);
      send(peers.back(), partial);
    } catch (const std::exception&) {
      // Cut while sending: the budget is already full.
    }
  }
  int cut = 0;
  for (auto& p : peers) cut += closed_by_port(p, 300ms) ? 1 : 0;
  const ProcessUsage after = ProcessUsage::now();
  // At most 8 MB worth of them (2 whole, a third partly) may be held.
  EXPECT_GE(cut, 12) << "peers over the process budget are disconnected";
  EXPECT_LT(after.peak_rss_kb, before.rss_kb + 28 * 1024)
      << "before: " << before.text() << "; after: " << after.text();
  peers.clear();
  EXPECT_TRUE(legit_client_served(r));
}
