// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// libFuzzer target: jointData (a controlboard's stateExt:o message, which remote_controlboard
// decodes) from arbitrary wire bytes. Anything must end as JointData or a robogene::Error naming
// the item; decoded data survives its message's binary round trip unchanged
// (decode(from_bytes(to_bytes(m))) == decode(m)).
#include <cstddef>
#include <cstdint>

#include "robogene/bottle.hpp"
#include "robogene/dev/joint_data.hpp"
#include "robogene/error.hpp"

using namespace robogene;
using namespace robogene::dev;

namespace {

template <class T>
bool same(const JointDataField<T>& a, const JointDataField<T>& b) {
  if (a.valid != b.valid || a.values.size() != b.values.size()) return false;
  for (std::size_t i = 0; i < a.values.size(); ++i) {
    // NaN compares unequal to itself: compare the bits' meaning instead.
    if (!(a.values[i] == b.values[i]) && !(a.values[i] != a.values[i] && b.values[i] != b.values[i])) return false;
  }
  return true;
}

bool same(const JointData& a, const JointData& b) {
  return same(a.position, b.position) && same(a.velocity, b.velocity) && same(a.acceleration, b.acceleration) &&
         same(a.motor_position, b.motor_position) && same(a.motor_velocity, b.motor_velocity) &&
         same(a.motor_acceleration, b.motor_acceleration) && same(a.torque, b.torque) && same(a.pwm, b.pwm) &&
         same(a.current, b.current) && same(a.control_mode, b.control_mode) &&
         same(a.interaction_mode, b.interaction_mode);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  Bottle message;
  try {
    DecodeLimits limits;
    limits.max_bytes = 1u << 20;
    message = Bottle::from_bytes(data, size, limits);
  } catch (const ParseError&) {
    return 0;
  }
  JointData decoded;
  try {
    decoded = decode_joint_data(message);
  } catch (const Error&) {
    return 0;  // named what is wrong: remote_controlboard drops the message
  }
  const JointData again = decode_joint_data(Bottle::from_bytes(message.to_bytes()));
  if (!same(decoded, again)) __builtin_trap();
  return 0;
}
