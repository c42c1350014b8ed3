// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// Attacks on a name client by a peer that only pretends to be a name server: an answer that never
// ends ("*** end of message" never comes) used to be collected line after line without bound, and
// an answer dripped a line at a time held the client for as long as the peer liked. Now the whole
// answer is bounded in size and in time, and the client says which.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <string>
#include <thread>

#include "robogene/error.hpp"
#include "robogene/name_client.hpp"
#include "robogene/net/tcp_listener.hpp"

using namespace robogene;
using namespace std::chrono_literals;

namespace {

// Accepts one client, reads its request, then writes `line` every `pause` until `for_at_most`
// has passed or the client goes, and finally the end marker (so an unbounded client returns
// instead of hanging the test).
class PretendNameServer {
 public:
  PretendNameServer(std::string line, std::chrono::milliseconds pause, std::chrono::milliseconds for_at_most)
      : thread_([this, line, pause, for_at_most] {
          auto s = listener_.accept(5000ms);
          if (!s) return;
          char c = 0;
          while (s->read_some(&c, 1) == 1 && c != '\n') {}
          const auto stop = std::chrono::steady_clock::now() + for_at_most;
          try {
            while (std::chrono::steady_clock::now() < stop) {
              s->write_all(line.data(), line.size());
              sent_ += line.size();
              if (pause.count() > 0) std::this_thread::sleep_for(pause);
            }
            const std::string end = "*** end of message\r\n";
            s->write_all(end.data(), end.size());
          } catch (const Error&) {
            // the client hung up: what this test wants
          }
        }) {}
  ~PretendNameServer() {
    listener_.interrupt();
    thread_.join();
  }
  net::Endpoint at() const { return listener_.local(); }
  std::size_t sent() const { return sent_; }

 private:
  net::TcpListener listener_ = net::TcpListener::listen({"127.0.0.1", 0});
  std::atomic<std::size_t> sent_{0};
  std::thread thread_;
};

std::string failure_of(NameClient& client) {
  try {
    client.request("NAME_SERVER list\n");
  } catch (const NetworkError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(HostileNameServer, AnAnswerThatNeverEndsIsCutAtItsSizeBound) {
  const std::string line = "registration name /a-name-that-is-not-short ip 127.0.0.1 port 10002 type tcp\r\n";
  PretendNameServer fake(line, 0ms, 20s);
  NameClient client(fake.at(), 5000ms);
  const std::string why = failure_of(client);
  EXPECT_NE(why.find("answer longer than 16777216 bytes"), std::string::npos) << why;
  EXPECT_NE(why.find(fake.at().to_string()), std::string::npos) << why;
}

TEST(HostileNameServer, AnAnswerDrippedALineAtATimeEndsAtTheDeadline) {
  PretendNameServer fake("registration name /slow ip 127.0.0.1 port 10002 type tcp\r\n", 50ms, 10s);
  NameClient client(fake.at(), 200ms);
  const auto start = std::chrono::steady_clock::now();
  const std::string why = failure_of(client);
  const auto took = std::chrono::steady_clock::now() - start;
  EXPECT_NE(why.find("answer not complete after 800 ms"), std::string::npos) << why;
  EXPECT_LT(took, 3s) << "the client waited on the drip";
}
