// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "cli_head_session.hpp"
#include "socketcan_env.hpp"
#include "test_bus_dir.hpp"

namespace robogene::can {
namespace {

TEST(CanHeadOverVirtualBus, CanSimProcessAndDriverMoveEveryJoint) {
  testing::TempBusDir dir;
  testing::run_head_session("virtual:session", dir.path());
}

// Inside the test VM (make test-can-vm): the same session over the kernel's vcan0, logs kept in
// ROBOGENE_CAN_LOG_DIR.
TEST(CanHeadOverSocketCan, CanSimProcessAndDriverMoveEveryJoint) {
  const std::string iface = testing::vcan_or_skip();
  if (iface.empty()) GTEST_SKIP() << testing::kSkipReason;
  const char* logs = std::getenv("ROBOGENE_CAN_LOG_DIR");
  ASSERT_NE(logs, nullptr) << "set ROBOGENE_CAN_LOG_DIR";
  testing::run_head_session("socketcan:" + iface, logs);
}

}  // namespace
}  // namespace robogene::can
