// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// `robogene can-zero`: the joints' absolute encoders as their boards read them, and storing a joint's
// zero (the raw angle at which it is at 0 deg) in its board's flash: what a lab does once per built
// head, with each joint held at its zero pose (docs/fabricate.md "Homing").
#include <cstdio>
#include <string>

#include "commands.hpp"
#include "robogene/can/bus.hpp"
#include "robogene/can/joint_encoders.hpp"
#include "robogene/dev/property.hpp"

namespace robogene::cli {
namespace {

void print(const can::JointEncoderReading& r) {
  std::printf("can-zero: %s: encoder %s, raw %u (%.2f deg), ", r.joint.c_str(), r.state.c_str(), r.raw, r.raw_degrees);
  if (r.zero_stored) {
    std::printf("zero %u stored, %s, joint at %.2f deg\n", r.zero, r.homed ? "homed" : "NOT homed", *r.joint_degrees);
  } else {
    std::printf("no zero stored, NOT homed\n");
  }
}

// JOINT or JOINT=RAW.
std::pair<std::string, std::optional<std::uint16_t>> store_spec(const std::string& text) {
  const auto eq = text.find('=');
  if (eq == std::string::npos) return {text, std::nullopt};
  const std::string raw = text.substr(eq + 1);
  std::size_t used = 0;
  unsigned long v = 0;
  try {
    v = std::stoul(raw, &used, 10);
  } catch (const std::exception&) {
    used = 0;
  }
  if (raw.empty() || used != raw.size() || v > 65535) {
    throw UsageError("--store " + text + ": the zero '" + raw + "' is not a raw encoder count (0..16383 for 14 bits)");
  }
  return {text.substr(0, eq), static_cast<std::uint16_t>(v)};
}

}  // namespace

int cmd_can_zero(Args& args) {
  const auto bus_spec = args.option("--bus");
  const auto from = args.option("--from");
  const auto store = args.option("--store");
  const std::vector<std::string> joints = args.positional();
  if (!bus_spec) throw UsageError("--bus is required (virtual:NAME or socketcan:IFACE)");
  if (!from) throw UsageError("--from is required (the head's board config, e.g. drivers/can/generated/head.ini)");
  if (store && !joints.empty()) throw UsageError("--store names its joint itself: no other JOINT arguments");
  const can::HeadConfig head = can::read_head_config(dev::Property::from_ini_file(*from));
  if (store) {
    for (const auto& r : can::store_joint_encoder_zeros(can::open_bus(*bus_spec), head, {store_spec(*store)})) print(r);
    return 0;
  }
  int unhomed = 0;
  for (const auto& r : can::read_joint_encoders(can::open_bus(*bus_spec), head, joints)) {
    print(r);
    if (!r.homed) ++unhomed;
  }
  return unhomed == 0 ? 0 : 1;
}

}  // namespace robogene::cli
