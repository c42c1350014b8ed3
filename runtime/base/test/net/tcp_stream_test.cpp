// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
#include <gtest/gtest.h>

#include <chrono>
#include <cstring>
#include <string>
#include <thread>
#include <vector>

#include "robogene/error.hpp"
#include "robogene/net/stream_reader.hpp"
#include "robogene/net/tcp_listener.hpp"
#include "robogene/net/tcp_stream.hpp"
#include "robogene/net/udp_socket.hpp"

using namespace robogene;
using namespace robogene::net;
using namespace std::chrono_literals;

namespace {

struct Pair {
  TcpListener listener;
  TcpStream client;
  TcpStream server;
};

Pair connected_pair() {
  Pair p;
  p.listener = TcpListener::listen({"127.0.0.1", 0});
  p.client = TcpStream::connect(p.listener.local());
  auto s = p.listener.accept(2000ms);
  EXPECT_TRUE(s.has_value());
  p.server = std::move(*s);
  return p;
}

}  // namespace

TEST(TcpStream, EphemeralListenReportsRealPortAndPeers) {
  auto p = connected_pair();
  EXPECT_GT(p.listener.local().port, 0);
  EXPECT_EQ(p.listener.local().host, "127.0.0.1");
  EXPECT_EQ(p.client.peer().port, p.listener.local().port);
  EXPECT_EQ(p.server.peer().port, p.client.local().port);
}

TEST(TcpStream, WritevArrivesInOrderAsOneStream) {
  auto p = connected_pair();
  std::string a = "hello ", b(300000, 'x'), c = " end";
  iovec iov[3] = {{a.data(), a.size()}, {b.data(), b.size()}, {c.data(), c.size()}};
  std::thread writer([&] { p.client.writev_all(iov, 3); });
  std::vector<char> got(a.size() + b.size() + c.size());
  p.server.read_exact(got.data(), got.size());
  writer.join();
  EXPECT_EQ(std::string(got.begin(), got.end()), a + b + c);
}

TEST(TcpStream, ReadExactReportsTruncationWithCounts) {
  auto p = connected_pair();
  p.client.write_all("abc", 3);
  p.client.close();
  char buf[8];
  try {
    p.server.read_exact(buf, 8);
    FAIL() << "expected NetworkError";
  } catch (const NetworkError& e) {
    EXPECT_NE(std::string(e.what()).find("after 3 of 8"), std::string::npos) << e.what();
  }
}

TEST(TcpStream, ReadTimeoutIsAnErrorNotAHang) {
  auto p = connected_pair();
  p.server.set_read_timeout(100ms);
  char buf[1];
  auto start = std::chrono::steady_clock::now();
  EXPECT_THROW(p.server.read_exact(buf, 1), NetworkError);
  EXPECT_LT(std::chrono::steady_clock::now() - start, 5s);
}

TEST(TcpStream, WriteToClosedPeerThrowsInsteadOfSigpipe) {
  auto p = connected_pair();
  p.server.close();
  std::string big(1 << 20, 'z');
  EXPECT_THROW(
      {
        for (int i = 0; i < 50; ++i) p.client.write_all(big.data(), big.size());
      },
      NetworkError);
}

TEST(TcpStream, ConnectToClosedPortNamesTheAddress) {
  auto l = TcpListener::listen({"127.0.0.1", 0});
  Endpoint gone = l.local();
  l.close();
  try {
    TcpStream::connect(gone, 1000ms);
    FAIL();
  } catch (const NetworkError& e) {
    EXPECT_NE(std::string(e.what()).find(gone.to_string()), std::string::npos) << e.what();
  }
}

TEST(TcpListener, InterruptWakesAcceptFromAnotherThread) {
  auto l = TcpListener::listen({"127.0.0.1", 0});
  std::thread t([&] {
    std::this_thread::sleep_for(50ms);
    l.interrupt();
  });
  EXPECT_FALSE(l.accept().has_value());
  t.join();
}

TEST(TcpListener, ListeningTwiceOnOnePortFailsWithTheAddress) {
  auto l = TcpListener::listen({"127.0.0.1", 0});
  try {
    TcpListener::listen(l.local());
    FAIL();
  } catch (const NetworkError& e) {
    EXPECT_NE(std::string(e.what()).find(l.local().to_string()), std::string::npos) << e.what();
  }
}

TEST(StreamReader, LinesDropCarriageReturnsAndMixWithBinary) {
  auto p = connected_pair();
  const char msg[] = "CONNECT foo\r\nd\n\x01\x02\x03rest\n";
  p.client.write_all(msg, sizeof msg - 1);
  StreamReader r(p.server);
  EXPECT_EQ(r.read_line(100), "CONNECT foo");
  EXPECT_EQ(r.read_line(100), "d");
  std::uint8_t bin[3];
  r.read_exact(bin, 3);
  EXPECT_EQ(bin[0], 1);
  EXPECT_EQ(bin[2], 3);
  EXPECT_EQ(r.read_line(100), "rest");
}

TEST(StreamReader, OverlongLineIsRejectedWithTheLimit) {
  auto p = connected_pair();
  std::string junk(5000, 'a');
  p.client.write_all(junk.data(), junk.size());
  StreamReader r(p.server);
  try {
    r.read_line(1000);
    FAIL();
  } catch (const NetworkError& e) {
    EXPECT_NE(std::string(e.what()).find("1000"), std::string::npos) << e.what();
  }
}

TEST(StreamReader, LargeExactReadBypassesBufferIntact) {
  auto p = connected_pair();
  std::vector<std::uint8_t> data(1 << 20);
  for (std::size_t i = 0; i < data.size(); ++i) data[i] = static_cast<std::uint8_t>(i * 7);
  std::thread w([&] {
    p.client.write_all("x\n", 2);
    p.client.write_all(data.data(), data.size());
  });
  StreamReader r(p.server);
  EXPECT_EQ(r.read_line(10), "x");
  std::vector<std::uint8_t> got(data.size());
  r.read_exact(got.data(), got.size());
  w.join();
  EXPECT_EQ(got, data);
}

TEST(UdpSocket, DatagramRoundTripAndTimeout) {
  auto a = UdpSocket::bind({"127.0.0.1", 0});
  auto b = UdpSocket::bind({"127.0.0.1", 0});
  a.send_to(b.local(), "ping", 4);
  char buf[16];
  Endpoint from;
  auto n = b.receive(buf, sizeof buf, 2000ms, &from);
  ASSERT_TRUE(n.has_value());
  EXPECT_EQ(std::string(buf, *n), "ping");
  EXPECT_EQ(from.port, a.local().port);
  EXPECT_FALSE(b.receive(buf, sizeof buf, 50ms).has_value());
}

TEST(UdpSocket, OversizedDatagramIsAnErrorNamingSizes) {
  auto a = UdpSocket::bind({"127.0.0.1", 0});
  auto b = UdpSocket::bind({"127.0.0.1", 0});
  std::string big(100, 'q');
  a.send_to(b.local(), big.data(), big.size());
  char buf[10];
  try {
    b.receive(buf, sizeof buf, 2000ms);
    FAIL();
  } catch (const NetworkError& e) {
    EXPECT_NE(std::string(e.what()).find("100 bytes"), std::string::npos) << e.what();
  }
}
