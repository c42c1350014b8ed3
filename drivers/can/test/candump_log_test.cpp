// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
#include <fstream>

#include <gtest/gtest.h>

#include "robogene/can/candump_log.hpp"
#include "robogene/can/logging_bus.hpp"
#include "robogene/can/virtual_bus.hpp"
#include "test_bus_dir.hpp"

namespace robogene::can {
namespace {

TEST(CandumpLog, LinesAreCandumpsFormat) {
  LogEntry e;
  e.time = 1700000000.123456;
  e.interface = "vcan0";
  e.frame = Frame(0x123, {0xDE, 0xAD, 0xBE, 0xEF});
  EXPECT_EQ(format_log_line(e), "(1700000000.123456) vcan0 123#DEADBEEF");
  LogEntry err;
  err.time = 5.000001;
  err.interface = "can0";
  err.error = make_error_frame(BusErrorKind::bus_off);
  EXPECT_EQ(format_log_line(err), "(0000000005.000001) can0 20000040#0000000000000000");
}

TEST(CandumpLog, ParsesWhatCandumpWrites) {
  const LogEntry e = parse_log_line("(1700000000.500000) vcan0 0B1#1401FF");
  EXPECT_DOUBLE_EQ(e.time, 1700000000.5);
  EXPECT_EQ(e.interface, "vcan0");
  ASSERT_TRUE(e.frame);
  EXPECT_EQ(*e.frame, Frame(0x0B1, {0x14, 0x01, 0xFF}));
  const LogEntry empty = parse_log_line("(1.000000) can1 7FF#");
  EXPECT_EQ(empty.frame->len, 0);
  const LogEntry err = parse_log_line("(1.000000) can1 20000004#0020000000008000");
  ASSERT_TRUE(err.error);
  EXPECT_EQ(decode_error_frame("can1", *err.error).kind(), BusErrorKind::error_passive);
}

TEST(CandumpLog, BadLinesNameTheColumnAndWhatWasExpected) {
  struct Case {
    const char* line;
    std::size_t column;
    const char* expected;
  };
  for (const Case& c : {Case{"1.0) vcan0 123#00", 1, "'('"}, Case{"(1.0) vcan0 1234#00", 13, "3-digit"},
                        Case{"(1.0) vcan0 123#0", 17, "two hex digits"},
                        Case{"(1.0) vcan0 123#R", 17, "classic data frame"},
                        Case{"(1.0) vcan0 123#000102030405060708", 33, "at most 8"},
                        Case{"(1.0) vcan0 12345678#00", 13, "standard id"},
                        Case{"(1.0) vcan0 923#00", 13, "7FF"},
                        // Found by can_frame_fuzz: read, then written back as garbage.
                        Case{"(70001700000000.5) can0 123#00", 2, "timestamp"},
                        Case{"(1.2.3) can0 123#00", 2, "timestamp"}, Case{"(.) can0 123#00", 2, "timestamp"}}) {
    try {
      parse_log_line(c.line);
      FAIL() << c.line;
    } catch (const ParseError& e) {
      EXPECT_EQ(e.position(), c.column) << c.line << ": " << e.what();
      EXPECT_NE(std::string(e.what()).find(c.expected), std::string::npos) << c.line << ": " << e.what();
    }
  }
}

TEST(CandumpLog, WriterAndReaderRoundTripAndReaderNamesTheLine) {
  testing::TempBusDir dir;
  const std::string path = dir.path() + "/session.log";
  {
    CandumpWriter w(path);
    w.write("vcan0", Frame(0x010, {0x1B}));
    w.write("vcan0", make_error_frame(BusErrorKind::no_ack));
  }
  const auto entries = read_candump_log(path);
  ASSERT_EQ(entries.size(), 2U);
  EXPECT_EQ(*entries[0].frame, Frame(0x010, {0x1B}));
  EXPECT_EQ(decode_error_frame("x", *entries[1].error).kind(), BusErrorKind::no_ack);
  EXPECT_NEAR(entries[0].time, wall_time(), 60.0);

  std::ofstream(path, std::ios::app) << "(1.0) vcan0 12#00\n";
  try {
    read_candump_log(path);
    FAIL();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find(path + ":3:13: expected"), std::string::npos) << e.what();
  }
  EXPECT_THROW(read_candump_log(dir.path() + "/missing.log"), Error);
}

TEST(CandumpLog, LoggingBusRecordsSentReceivedAndErrorFrames) {
  testing::TempBusDir dir;
  const std::string path = dir.path() + "/node.log";
  auto log = std::make_shared<CandumpWriter>(path);
  LoggingBus node(std::make_unique<VirtualBus>("l"), log);
  VirtualBus peer("l");
  node.send(Frame(0x001, {0x14}), Millis(500));
  peer.send(Frame(0x011, {0x14, 0, 0, 0, 0}), Millis(500));
  ASSERT_TRUE(node.receive(Millis(1000)));
  peer.inject_error(make_error_frame(BusErrorKind::bus_off));
  EXPECT_THROW(node.receive(Millis(1000)), BusError);
  const auto entries = read_candump_log(path);
  ASSERT_EQ(entries.size(), 3U);
  EXPECT_EQ(entries[0].interface, "l");
  EXPECT_EQ(entries[0].frame->id, 0x001);
  EXPECT_EQ(entries[1].frame->id, 0x011);
  EXPECT_TRUE(entries[2].error);
}

}  // namespace
}  // namespace robogene::can
