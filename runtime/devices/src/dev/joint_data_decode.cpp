// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// Decoding YARP 3's jointData (the stateExt:o message), for remote_controlboard in C++ and, through
// the binding, in Python.
#include <string>
#include <type_traits>

#include "robogene/dev/joint_data.hpp"
#include "robogene/error.hpp"

namespace robogene::dev {
namespace {

// The fields in wire order, as YARP's jointData names them.
constexpr const char* kFieldNames[] = {
    "jointPosition", "jointVelocity", "jointAcceleration", "motorPosition", "motorVelocity",
    "motorAcceleration", "torque", "pwmDutycycle", "current", "controlMode", "interactionMode"};
constexpr std::size_t kFields = sizeof(kFieldNames) / sizeof(kFieldNames[0]);

[[noreturn]] void fail(std::size_t item, std::size_t field, const std::string& what) {
  throw Error("jointData item " + std::to_string(item) + " (" + kFieldNames[field] + "): " + what);
}

bool read_flag(const Value& v, std::size_t item, std::size_t field) {
  if (v.is_vocab() && v.as_vocab() == vocab("ok")) return true;
  if (v.is_vocab() && v.as_vocab() == vocab("fail")) return false;
  fail(item, field, "expected the flag [ok] or [fail], got " + v.to_text());
}

template <class T>
JointDataField<T> read_field(const Bottle& message, std::size_t field) {
  const std::size_t item = 2 * field;
  const Value& list = message[item];
  if (!list.is_list()) fail(item, field, "expected a list of values, got " + list.to_text());
  JointDataField<T> out;
  for (std::size_t k = 0; k < list.as_list().size(); ++k) {
    const Value& v = list.as_list()[k];
    if constexpr (std::is_same_v<T, double>) {
      if (!v.is_number()) fail(item, field, "value " + std::to_string(k) + " is not a number: " + v.to_text());
      out.values.push_back(v.as_float64());
    } else {
      if (!v.is_int() && !v.is_vocab()) {
        fail(item, field, "value " + std::to_string(k) + " is not an integer or a vocab: " + v.to_text());
      }
      out.values.push_back(v.is_vocab() ? static_cast<std::int32_t>(v.as_vocab()) : v.as_int32());
    }
  }
  out.valid = read_flag(message[item + 1], item + 1, field);
  return out;
}

}  // namespace

JointData decode_joint_data(const Bottle& message) {
  if (message.size() != 2 * kFields) {
    throw Error("jointData has " + std::to_string(message.size()) + " items, expected " +
                std::to_string(2 * kFields) + " (11 fields, each followed by [ok] or [fail])");
  }
  JointData d;
  JointDataField<double>* doubles[] = {&d.position,       &d.velocity,           &d.acceleration,
                                       &d.motor_position, &d.motor_velocity,     &d.motor_acceleration,
                                       &d.torque,         &d.pwm,                &d.current};
  std::size_t field = 0;
  for (auto* f : doubles) *f = read_field<double>(message, field++);
  d.control_mode = read_field<std::int32_t>(message, field++);
  d.interaction_mode = read_field<std::int32_t>(message, field++);

  const std::size_t axes = d.position.values.size();
  const std::size_t sizes[] = {d.position.values.size(),       d.velocity.values.size(),
                               d.acceleration.values.size(),   d.motor_position.values.size(),
                               d.motor_velocity.values.size(), d.motor_acceleration.values.size(),
                               d.torque.values.size(),         d.pwm.values.size(),
                               d.current.values.size(),        d.control_mode.values.size(),
                               d.interaction_mode.values.size()};
  for (std::size_t f = 1; f < kFields; ++f) {
    if (sizes[f] != axes) {
      fail(2 * f, f, "has " + std::to_string(sizes[f]) + " values, but jointPosition has " + std::to_string(axes));
    }
  }
  return d;
}

}  // namespace robogene::dev
