// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// A log recorded by can-utils' own candump (inside the test VM, while the simulated head ran)
// is read by our reader: the two agree on the format. ROBOGENE_CAN_CANDUMP_LOG names the log.
#include <cstdlib>
#include <fstream>
#include <set>
#include <string>

#include <gtest/gtest.h>

#include "robogene/can/candump_log.hpp"

namespace robogene::can {
namespace {

TEST(CandumpInterop, ReadsALogCandumpRecorded) {
  const char* path = std::getenv("ROBOGENE_CAN_CANDUMP_LOG");
  if (!path) GTEST_SKIP() << "set ROBOGENE_CAN_CANDUMP_LOG to a `candump -L` recording (make test-can-vm does)";
  const auto entries = read_candump_log(path);
  ASSERT_GT(entries.size(), 100U) << path << " holds too little of a head session";
  std::set<std::uint16_t> ids;
  for (const auto& e : entries) {
    ASSERT_TRUE(e.frame || e.error);
    if (e.frame) ids.insert(e.frame->id);
  }
  // Our writer prints every line exactly as candump printed it.
  std::ifstream in(path);
  std::string line;
  for (int n = 1; std::getline(in, line); ++n) {
    EXPECT_EQ(format_log_line(parse_log_line(line)), line) << path << ":" << n;
  }
  EXPECT_GE(ids.size(), 4U) << "commands, replies and broadcasts of several boards expected";
}

}  // namespace
}  // namespace robogene::can
