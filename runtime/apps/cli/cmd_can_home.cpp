// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// `robogene can-home`: home the head's joints that have no absolute encoder (the eyes) against
// their hard stops, through the boards' firmware (calibrate_encoder), and report each one.
#include <cstdio>

#include "commands.hpp"
#include "robogene/can/homing.hpp"
#include "robogene/can/bus.hpp"
#include "robogene/dev/property.hpp"

namespace robogene::cli {

int cmd_can_home(Args& args) {
  const auto bus_spec = args.option("--bus");
  const auto from = args.option("--from");
  const std::vector<std::string> joints = args.positional();
  if (!bus_spec) throw UsageError("--bus is required (virtual:NAME or socketcan:IFACE)");
  if (!from) throw UsageError("--from is required (the head's board config, e.g. drivers/can/generated/head.ini)");
  const can::HeadConfig head = can::read_head_config(dev::Property::from_ini_file(*from));
  const auto results = can::home_joints(can::open_bus(*bus_spec), head, joints, [](const std::string& line) {
    std::printf("can-home: %s\n", line.c_str());
    std::fflush(stdout);
  });
  int failed = 0;
  for (const auto& r : results) {
    if (r.homed) {
      std::printf("can-home: %s homed, now at %.2f deg\n", r.joint.c_str(), r.degrees);
    } else {
      std::printf("can-home: %s NOT homed: %s\n", r.joint.c_str(), r.detail.c_str());
      ++failed;
    }
  }
  return failed == 0 ? 0 : 1;
}

}  // namespace robogene::cli
