// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// The message of a control board's stateExt:o port, YARP 3's jointData (reference section 5.6):
// eleven per-axis vectors, each followed by a validity flag ([ok] valid, [fail] not), in this
// order: joint position, velocity, acceleration; motor position, velocity, acceleration; torque;
// PWM duty cycle; current (float64 lists); control mode, interaction mode (int32 lists holding
// vocabs). remote_controlboard reads its encoders from here, not by RPC.
#pragma once

#include "robogene/bottle.hpp"
#include "robogene/dev/device_driver.hpp"

namespace robogene::dev {

// Fills `out` from whatever the device implements: IEncoders gives the joint fields, ITorqueControl
// the torques, IControlMode the modes. Fields the device has no interface for (motor encoders,
// PWM, current, interaction mode) are zeros marked invalid. False when the device has no
// IEncoders or cannot report its axes.
bool encode_joint_data(DeviceDriver& device, Bottle& out);

}  // namespace robogene::dev
