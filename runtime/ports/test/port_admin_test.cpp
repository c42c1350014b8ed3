// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// Admin messages byte for byte as `yarp connect` / `yarp disconnect` exchange them
// (write_connect_read.flows.txt), and the binary 'a' form.
#include <gtest/gtest.h>

#include <thread>

#include "robogene/testing/wire_helpers.hpp"
#include "robogene/testing/port_test_util.hpp"

using namespace robogene;
using namespace robogene::test;
using namespace std::chrono_literals;

TEST(PortAdmin, YarpConnectAndDisconnectTranscript) {
  PortTable t;
  Port w, r;
  open_local(w, "/w", t);
  open_local(r, "/r", t);
  EXPECT_EQ(admin_text(w, "[list] [out] \"/r\""), "\r\n<ACK>\r\n");
  EXPECT_EQ(admin_text(w, "[add] \"tcp://r\""),
            "0 \"Added connection from /w to tcp://r\\r\\n\"\r\n<ACK>\r\n");
  EXPECT_EQ(w.output_names(), std::vector<std::string>{"/r"});
  EXPECT_EQ(admin_text(w, "[list] [out] \"/r\""), "(from \"/w\") (to \"/r\") (carrier tcp)\r\n<ACK>\r\n");
  EXPECT_EQ(admin_text(w, "[list] [out]"), "\"/r\"\r\n<ACK>\r\n");
  // The new connection works: data written on /w reaches /r.
  std::thread writer([&] { w.write(Bottle::from_text("1 2.5 hi [set]")); });
  Bottle b;
  ASSERT_TRUE(r.read(b, false, 5000ms));
  writer.join();
  EXPECT_EQ(b.to_text(), "1 2.5 hi [set]");
  // YARP lists every input by sender name, the admin connection asking included.
  EXPECT_EQ(admin_text(r, "[list] [in]"), "\"/w\" admin\r\n<ACK>\r\n");
  EXPECT_EQ(admin_text(w, "[del] \"/r\""),
            "0 \"Removed connection from /w to /r\\r\\n\"\r\n<ACK>\r\n");
  EXPECT_TRUE(w.output_names().empty());
}

TEST(PortAdmin, AddWithCarrierArgumentAndUnknownTarget) {
  PortTable t;
  Port w, r;
  open_local(w, "/w", t);
  open_local(r, "/r", t);
  EXPECT_EQ(admin_text(w, "[add] /r udp"), "0 \"Added connection from /w to udp://r\\r\\n\"\r\n<ACK>\r\n");
  EXPECT_EQ(admin_text(w, "[list] [out] /r"),
            "(from \"/w\") (to \"/r\") (carrier udp) (connectionless 1)\r\n<ACK>\r\n");
  EXPECT_EQ(admin_text(w, "[add] /ghost"), "-1 \"Do not know how to connect to /ghost\\r\\n\"\r\n<ACK>\r\n");
  EXPECT_EQ(admin_text(w, "[del] /ghost"),
            "-1 \"Could not find an outgoing connection to /ghost\\r\\nCould not find an incoming "
            "connection from /ghost\\r\\n\"\r\n<ACK>\r\n");
}

TEST(PortAdmin, VerHelpAndUnknownOverText) {
  Port p;
  p.open_at("/p", {"127.0.0.1", 0});
  EXPECT_EQ(admin_text(p, "[ver]"), "[ver] 1 2 3\r\n<ACK>\r\n");
  EXPECT_EQ(admin_text(p, "ver"), "[ver] 1 2 3\r\n<ACK>\r\n");
  std::string help = admin_text(p, "[help]");
  EXPECT_EQ(help.rfind("[many] ", 0), 0u) << help;
  EXPECT_NE(help.find("[add] $portname"), std::string::npos);
  EXPECT_EQ(admin_text(p, "[bogus]"), "[fail] \"send [help] for list of valid commands\"\r\n<ACK>\r\n");
}

TEST(PortAdmin, BinaryAdminVerRepliesRawBottleThenAck) {
  Port p;
  p.open_at("/p", {"127.0.0.1", 0});
  auto s = net::TcpStream::connect({"127.0.0.1", p.contact().port});
  send(s, hex("59 41 e4 1e 00 00 52 50 06 00 00 00 61 64 6d 69 6e 00"));  // sender "admin"
  read_n(s, 8);
  // Index [8, 12, 0], PortCommand 'a', Bottle [ver] (homogeneous vocab list).
  send(s, hex("59 41 0a 00 00 00 52 50 02 01 ff ff ff ff ff ff ff ff 08 00 00 00 0c 00 00 00 00 00"
              "00 00 00 00 00 00 7e 61 00 01 09 01 00 00 01 00 00 00 76 65 72 00"));
  EXPECT_EQ(read_n(s, 40 + 8),
            hex("00 01 00 00 04 00 00 00 09 00 00 00 76 65 72 00 01 00 00 00 01 00 00 00 01 00 00"
                "00 02 00 00 00 01 00 00 00 03 00 00 00 59 41 00 00 00 00 52 50"));
}

TEST(PortAdmin, RemoteControlboardStyleAddOfUdpInput) {
  // remote_controlboard asks /motors/stateExt:o to [add] "udp://mc/stateExt:i".
  PortTable t;
  Port out, in;
  open_local(out, "/motors/stateExt:o", t);
  open_local(in, "/mc/stateExt:i", t);
  EXPECT_EQ(admin_text(out, "[add] \"udp://mc/stateExt:i\""),
            "0 \"Added connection from /motors/stateExt:o to udp://mc/stateExt:i\\r\\n\"\r\n<ACK>\r\n");
  std::atomic<bool> got{false};
  in.set_reader([&](const Bottle& b, const MessageInfo& info, Bottle*) {
    EXPECT_EQ(info.carrier, "udp");
    EXPECT_EQ(b.size(), 4u);
    got = true;
  });
  for (int i = 0; i < 100 && !got; ++i) {
    out.write(Bottle{1.0, 2.0, 3.0, 4.0});
    std::this_thread::sleep_for(10ms);
  }
  EXPECT_TRUE(got);
}
