// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
#include <gtest/gtest.h>

#include <map>
#include <thread>

#include "robogene/testing/wire_helpers.hpp"
#include "robogene/testing/port_test_util.hpp"
#include "robogene/error.hpp"
#include "robogene/network.hpp"

using namespace robogene;
using namespace robogene::test;
using namespace std::chrono_literals;

namespace {

// A minimal name server answering queries from a table, old-style text replies.
class TableServer {
 public:
  explicit TableServer(std::map<std::string, Contact> t) : table_(std::move(t)) {
    thread_ = std::thread([this] {
      for (;;) {
        auto s = listener_.accept();
        if (!s) return;
        std::string req = read_until(*s, "\n");
        std::string name = req.substr(req.rfind(' ') + 1);
        while (!name.empty() && (name.back() == '\n' || name.back() == '\r')) name.pop_back();
        std::string out;
        auto it = table_.find(name);
        if (it != table_.end()) {
          out = "registration name " + name + " ip 127.0.0.1 port " + std::to_string(it->second.port) +
                " type tcp\r\n";
        }
        send(*s, out + "*** end of message\r\n");
      }
    });
  }
  ~TableServer() {
    listener_.interrupt();
    thread_.join();
  }
  net::Endpoint at() const { return listener_.local(); }

 private:
  std::map<std::string, Contact> table_;
  net::TcpListener listener_ = net::TcpListener::listen({"127.0.0.1", 0});
  std::thread thread_;
};

}  // namespace

TEST(Network, ConnectDisconnectAndRpcLikeTheYarpTools) {
  PortTable t;
  Port w, r;
  open_local(w, "/w", t);
  open_local(r, "/r", t);
  r.set_reader([](const Bottle& b, const MessageInfo& info, Bottle* reply) {
    if (reply) *reply = Bottle{Value(info.from), Value(static_cast<std::int32_t>(b.size()))};
  });
  TableServer ns({{"/w", w.contact()}, {"/r", r.contact()}});
  NameClient names(ns.at());
  auto added = network::connect(names, "/w", "/r");
  EXPECT_TRUE(added.ok);
  EXPECT_EQ(added.message, "Added connection from /w to tcp://r");
  EXPECT_EQ(w.output_names(), std::vector<std::string>{"/r"});
  auto removed = network::disconnect(names, "/w", "/r");
  EXPECT_TRUE(removed.ok);
  EXPECT_EQ(removed.message, "Removed connection from /w to /r");
  EXPECT_FALSE(network::disconnect(names, "/w", "/r").ok);
  EXPECT_THROW(network::connect(names, "/w", "/ghost"), Error);
  EXPECT_EQ(network::rpc(r.contact(), Bottle::from_text("1 2 3")).to_text(), "anon_rpc 3");
  EXPECT_EQ(network::rpc(r.contact(), Bottle::from_text("1 2"), "text_ack", "typist").to_text(),
            "typist 2");
}
