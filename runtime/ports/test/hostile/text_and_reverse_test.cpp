// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// Attack: a text message of a hundred thousand short lines (each line used to make the port
// re-check all the text so far: quadratic time); and hundreds of peers that turn their
// connection around with 'r' and hang up (each used to leave an output and its socket behind
// for good on a port that never writes).
#include <gtest/gtest.h>

#include <sys/resource.h>

#include "robogene/testing/hostile_util.hpp"
#include "robogene/log.hpp"

using namespace robogene;
using namespace robogene::test;
using namespace std::chrono_literals;

namespace {

double cpu_seconds() {
  rusage u{};
  ::getrusage(RUSAGE_SELF, &u);
  return static_cast<double>(u.ru_utime.tv_sec + u.ru_stime.tv_sec) +
         static_cast<double>(u.ru_utime.tv_usec + u.ru_stime.tv_usec) / 1e6;
}

}  // namespace

TEST(HostileText, ManyLinesCostTimeLinearInTheirBytes) {
  log::set_level(log::Level::Error);
  Port r;
  r.open_at("/r", {"127.0.0.1", 0});
  // One bottle spread over 150,000 lines: "(" then one number a line, then ")": 1.2 MB.
  const int lines = 150000;
  std::string text = "CONNECT /lines\r\nd\r\n(\r\n";
  for (int i = 0; i < lines; ++i) text += std::to_string(i % 1000) + "\r\n";
  text += ")\r\n";
  const double cpu_before = cpu_seconds();
  auto s = connect_to(r);
  std::thread sender([&] { send(s, text); });
  Bottle b;
  // Re-reading the text after every line took minutes for this; linear work takes well under
  // a second of CPU. The bound below is generous for a loaded CI machine.
  const bool got = r.read(b, false, 60000ms);
  const double cpu = cpu_seconds() - cpu_before;
  sender.join();
  ASSERT_TRUE(got);
  ASSERT_EQ(b.size(), 1u);
  EXPECT_EQ(b.get(0).as_list().size(), static_cast<std::size_t>(lines));
  EXPECT_LT(cpu, 4.0) << "reading " << lines << " lines of one text message took " << cpu << " s of CPU";
  EXPECT_TRUE(legit_client_served(r));
}

TEST(HostileReverse, ReversedConnectionsThatHangUpAreDropped) {
  log::set_level(log::Level::Error);
  Port r;  // never writes
  r.open_at("/r", {"127.0.0.1", 0});
  const ProcessUsage before = ProcessUsage::now();
  for (int i = 0; i < 200; ++i) {
    auto s = connect_to(r);
    send(s, std::string("CONNECT /rev" + std::to_string(i) + "\r\nr\r\n"));
    read_until(s, "\r\n");  // "Welcome /revN"
  }  // and hang up
  const ProcessUsage after = usage_when([&](const ProcessUsage& u) {
    return u.fds <= before.fds + 4 && u.threads <= before.threads + 4;
  });
  EXPECT_LE(after.fds, before.fds + 4) << "before: " << before.text() << "; after: " << after.text();
  EXPECT_LE(after.threads, before.threads + 4) << "before: " << before.text() << "; after: " << after.text();
  EXPECT_TRUE(wait_until([&] { return r.output_names().empty(); }))
      << r.output_names().size() << " reversed outputs kept after their readers left";
  EXPECT_TRUE(legit_client_served(r));
}

TEST(HostileReverse, ReversedReaderThatStaysKeepsReceiving) {
  log::set_level(log::Level::Error);
  Port r;
  r.open_at("/r", {"127.0.0.1", 0});
  auto s = connect_to(r);
  send(s, std::string("CONNECT /reader\r\nr\r\n"));
  read_until(s, "Welcome /reader\r\n");
  ASSERT_TRUE(wait_until([&] { return r.output_names().size() == 1; }));
  std::this_thread::sleep_for(500ms);  // the watch on the reversed output must not drop it
  ASSERT_EQ(r.output_names().size(), 1u);
  r.write(Bottle{Value(42)});
  EXPECT_NE(read_until(s, "42\r\n").find("42"), std::string::npos);
}
