// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// The message of a control board's stateExt:o port, YARP 3's jointData (reference section 5.6):
// eleven per-axis vectors, each followed by a validity flag ([ok] valid, [fail] not), in this
// order: joint position, velocity, acceleration; motor position, velocity, acceleration; torque;
// PWM duty cycle; current (float64 lists); control mode, interaction mode (int32 lists holding
// vocabs). remote_controlboard reads its encoders from here, not by RPC.
#pragma once

#include <cstdint>
#include <vector>

#include "robogene/bottle.hpp"
#include "robogene/dev/device_driver.hpp"

namespace robogene::dev {

// One field of a jointData message: one value per axis, and the server's validity flag.
template <class T>
struct JointDataField {
  std::vector<T> values;
  bool valid = false;
};

// A decoded jointData message. The mode fields hold the vocabs' codes (ControlMode's values).
struct JointData {
  JointDataField<double> position, velocity, acceleration;
  JointDataField<double> motor_position, motor_velocity, motor_acceleration;
  JointDataField<double> torque, pwm, current;
  JointDataField<std::int32_t> control_mode, interaction_mode;
};

// Fills `out` from whatever the device implements: IEncoders gives the joint fields, ITorqueControl
// the torques, IControlMode the modes. Fields the device has no interface for (motor encoders,
// PWM, current, interaction mode) are zeros marked invalid. False when the device has no
// IEncoders or cannot report its axes.
bool encode_joint_data(DeviceDriver& device, Bottle& out);

// Reads a jointData message (joint_data_decode.cpp): 22 items, each field a list of numbers
// (integers for the modes) followed by [ok] or [fail], every field with the same number of
// values. Throws robogene::Error naming the item and the field that is wrong.
JointData decode_joint_data(const Bottle& message);

}  // namespace robogene::dev
