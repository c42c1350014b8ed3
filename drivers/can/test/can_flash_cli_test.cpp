// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
#include <cstdlib>

#include "cli_flash_session.hpp"
#include "socketcan_env.hpp"
#include "test_bus_dir.hpp"

namespace robogene::can {
namespace {

TEST(CanFlashOverVirtualBus, RefusesWrongImagesAndSurvivesAnInterruptedUpdate) {
  testing::TempBusDir dir;
  testing::run_flash_session("virtual:update", dir.path());
}

// Inside the test VM (make test-can-vm): the same over the kernel's vcan0, files in
// ROBOGENE_CAN_LOG_DIR (the VM's only writable place).
TEST(CanFlashOverSocketCan, RefusesWrongImagesAndSurvivesAnInterruptedUpdate) {
  const std::string iface = testing::vcan_or_skip();
  if (iface.empty()) GTEST_SKIP() << testing::kSkipReason;
  const char* logs = std::getenv("ROBOGENE_CAN_LOG_DIR");
  ASSERT_NE(logs, nullptr) << "set ROBOGENE_CAN_LOG_DIR";
  const std::string scratch = std::string(logs) + "/can-flash";
  ::mkdir(scratch.c_str(), 0755);
  testing::run_flash_session("socketcan:" + iface, scratch);
}

TEST(CanFlashCli, CanSimRefusesAFlashDirThatIsTheVirtualBussOwn) {
  testing::TempBusDir dir;
  const std::string bus_dir = dir.path() + "/update";
  ::mkdir(bus_dir.c_str(), 0755);
  const auto r = testing::run_command(testing::robogene_bin() + " can-sim --bus virtual:update --from " + testing::head_ini_path() +
                                      " --duration 1 --flash-dir " + bus_dir);
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find("is the virtual bus's own directory; give another"), std::string::npos) << r.output;
}

TEST(CanFlashCli, UsageErrorsAreNamed) {
  const auto none = testing::run_command(testing::robogene_bin() + " can-flash --bus virtual:x");
  EXPECT_EQ(none.status, 2);
  EXPECT_NE(none.output.find("give one image"), std::string::npos) << none.output;
  const auto no_bus = testing::run_command(testing::robogene_bin() + " can-flash image.bin");
  EXPECT_EQ(no_bus.status, 2);
  EXPECT_NE(no_bus.output.find("--bus is required"), std::string::npos) << no_bus.output;
  const auto missing = testing::run_command(testing::robogene_bin() + " can-flash --bus virtual:x /nonexistent/image.bin");
  EXPECT_EQ(missing.status, 1);
  EXPECT_NE(missing.output.find("robogene can-flash: /nonexistent/image.bin: cannot open the image"), std::string::npos)
      << missing.output;
}

}  // namespace
}  // namespace robogene::can
