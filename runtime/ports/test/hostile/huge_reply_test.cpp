// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// Attacks on a writer's memory through replies: readers (or RPC servers) that answer a 'd'
// message with a huge reply. A binary reply announcing a 32 MB blob, 3 MB of which arrive,
// used to be held outside the process's bytes-in-transit budget, so 16 such readers held 48 MB;
// a text reply that never sends its "<ACK>" line grew without any bound. Now replies count in
// the budget while they arrive, and a text reply is bounded by the message size.
#include <gtest/gtest.h>

#include <malloc.h>

#include <atomic>

#include "robogene/testing/hostile_util.hpp"
#include "robogene/carrier/registry.hpp"
#include "robogene/log.hpp"
#include "robogene/net/tcp_listener.hpp"

using namespace robogene;
using namespace robogene::test;
using namespace std::chrono_literals;

namespace {

void put(std::vector<std::uint8_t>& out, std::int32_t v) {
  std::uint8_t n[4];
  carrier::put_int32(n, v);
  out.insert(out.end(), n, n + 4);
}

// The reader's side of a tcp handshake: the writer's header and name, then our answer.
void accept_tcp_writer(net::TcpStream& s, int port) {
  read_n(s, 8);
  auto len = read_n(s, 4);
  read_n(s, static_cast<std::size_t>(carrier::get_int32(len.data())));
  auto answer = carrier::make_yarp_number(port);
  s.write_all(answer.data(), answer.size());
}

// Waits until `stop`, or until the writer hangs up.
void hold(net::TcpStream& s, const std::atomic<bool>& stop) {
  s.set_read_timeout(100ms);
  char buf[4096];
  while (!stop) {
    try {
      if (s.read_some(buf, sizeof buf) == 0) return;
    } catch (const NetworkError&) {
      // timed out: keep holding
    }
  }
}

std::string what_of(const std::exception_ptr& e) {
  try {
    if (e) std::rethrow_exception(e);
  } catch (const std::exception& x) {
    return x.what();
  }
  return "";
}

}  // namespace

TEST(HostileReply, ProcessWideBudgetCutsReadersHoldingPartlySentReplies) {
  log::set_level(log::Level::Error);
  ResourceLimits l = resource_limits();
  l.max_receiving_bytes = 8u << 20;
  ScopedLimits scoped(l);
  // Big buffers straight from mmap and back to the system when freed: resident memory then
  // shows what the writers hold, not what glibc's per-thread arenas keep for later.
  mallopt(M_MMAP_THRESHOLD, 64 * 1024);
  // A reply announcing one 32 MB blob, of which 3 MB are sent; made once, before the baseline.
  std::vector<std::uint8_t> partial;
  put(partial, 0x100);  // a bottle of tagged items
  put(partial, 1);
  put(partial, 12);     // a blob
  put(partial, 32 << 20);
  partial.insert(partial.end(), 3u << 20, 0x5a);

  constexpr int kReaders = 16;
  auto listener = net::TcpListener::listen({"127.0.0.1", 0});
  std::atomic<bool> stop{false};
  std::thread readers([&] {
    std::vector<std::thread> each;
    for (int i = 0; i < kReaders; ++i) {
      auto s = listener.accept(5000ms);
      if (!s) break;
      each.emplace_back([&, s = std::move(*s)]() mutable {
        try {
          accept_tcp_writer(s, listener.local().port);
          char buf[4096];
          s.set_read_timeout(5000ms);
          s.read_some(buf, sizeof buf);  // the 'd' message
          s.set_write_timeout(2000ms);
          s.write_all(partial.data(), partial.size());
        } catch (const std::exception&) {
          // cut by the writer while answering: the budget is full
        }
        hold(s, stop);
      });
    }
    for (auto& t : each) t.join();
  });

  carrier::ConnectContext ctx;
  ctx.sender_name = "/w";
  ctx.target_name = "/evil";
  ctx.timeout = 4000ms;
  std::vector<std::unique_ptr<carrier::OutboundConnection>> conns;
  for (int i = 0; i < kReaders; ++i) {
    conns.push_back(carrier::open_connection(listener.local(), "tcp", ctx));
  }
  ProcessUsage::reset_peak_rss();
  const ProcessUsage before = ProcessUsage::now();
  const Bottle question{Value("get"), Value("image")};
  std::vector<std::exception_ptr> errors(kReaders);
  std::vector<std::thread> writers;
  for (int i = 0; i < kReaders; ++i) {
    writers.emplace_back([&, i] {
      try {
        carrier::OutboundMessage m;
        m.key = 'd';
        m.bottle = &question;
        conns[i]->write_message(m);
        Bottle reply;
        conns[i]->await_completion(&reply);
      } catch (...) {
        errors[i] = std::current_exception();
      }
    });
  }
  // The writers cut by the budget fail at once; the others wait for the rest of their reply.
  std::this_thread::sleep_for(1500ms);
  const ProcessUsage during = ProcessUsage::now();
  const std::size_t in_transit = ResourceUsage::global().receiving_bytes();
  stop = true;
  for (auto& c : conns) c->interrupt();
  for (auto& t : writers) t.join();
  readers.join();
  int cut = 0;
  for (auto& e : errors) {
    if (what_of(e).find("ROBOGENE_MAX_RECEIVING_BYTES") != std::string::npos) ++cut;
  }
  // At most 8 MB worth of them (2 whole, a third partly) may be held.
  EXPECT_GE(cut, 12) << "writers whose replies pass the process budget are cut; first error: " << what_of(errors[0]);
  EXPECT_LE(in_transit, 8u << 20);
  EXPECT_LT(during.peak_rss_kb, before.rss_kb + 28 * 1024)
      << "before: " << before.text() << "; during: " << during.text();
  conns.clear();
  EXPECT_EQ(ResourceUsage::global().receiving_bytes(), 0u) << "every reply's bytes are returned";

  // An honest RPC server is still answered in full.
  Port server, client;
  server.open_at("/server", {"127.0.0.1", 0});
  server.set_reader([](const Bottle&, const MessageInfo&, Bottle* reply) {
    if (reply) *reply = Bottle{Value::blob(std::vector<std::uint8_t>(1u << 20, 7))};
  });
  client.open_at("/client", {"127.0.0.1", 0});
  client.add_output(Contact{"/server", "tcp", "127.0.0.1", server.contact().port});
  Bottle reply;
  EXPECT_TRUE(client.write(question, reply));
  ASSERT_EQ(reply.size(), 1u);
  EXPECT_EQ(reply[0].as_blob().size(), 1u << 20);
}

TEST(HostileReply, TextReplyWithoutEndIsBoundedByTheMessageSize) {
  log::set_level(log::Level::Error);
  // A text_ack "reader" that welcomes the writer, then answers its message with lines that
  // never end in "<ACK>": 128 MB of them unless the writer hangs up first.
  auto listener = net::TcpListener::listen({"127.0.0.1", 0});
  std::atomic<std::size_t> sent{0};
  std::thread reader([&] {
    auto s = listener.accept(5000ms);
    if (!s) return;
    try {
      read_until(*s, "\r\n");
      send(*s, std::string("Welcome /w\r\n"));
      read_until(*s, "\r\n");  // "d"
      const std::string line = std::string(1000, '7') + "\r\n";
      std::string chunk;
      for (int i = 0; i < 64; ++i) chunk += line;
      s->set_write_timeout(3000ms);
      while (sent < (128u << 20)) {
        send(*s, chunk);
        sent += chunk.size();
      }
    } catch (const std::exception&) {
      // the writer hung up
    }
  });
  carrier::ConnectContext ctx;
  ctx.sender_name = "/w";
  ctx.target_name = "/evil";
  ctx.max_message_size = 4u << 20;
  ctx.timeout = 4000ms;
  auto conn = carrier::open_connection(listener.local(), "text_ack", ctx);
  ProcessUsage::reset_peak_rss();
  const ProcessUsage before = ProcessUsage::now();
  std::string error;
  try {
    const Bottle question{Value("get")};
    carrier::OutboundMessage m;
    m.key = 'd';
    m.bottle = &question;
    conn->write_message(m);
    Bottle reply;
    conn->await_completion(&reply);
  } catch (const std::exception& e) {
    error = e.what();
  }
  const ProcessUsage after = ProcessUsage::now();
  conn.reset();
  reader.join();
  EXPECT_NE(error.find("more than the 4194304-byte limit of a reply"), std::string::npos) << error;
  EXPECT_LT(sent.load(), 64u << 20) << "the writer stops reading long before the reader stops sending";
  EXPECT_LT(after.peak_rss_kb, before.rss_kb + 24 * 1024)
      << "before: " << before.text() << "; after: " << after.text();
  EXPECT_EQ(ResourceUsage::global().receiving_bytes(), 0u);
}
