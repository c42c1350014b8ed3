// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// test_motor's PID offset, enable, disable and reset (YARP's IPidControl requests beyond the gains).
// The model has three loops (position, velocity, torque), all enabled at open; the current loop
// does not exist, so these requests refuse it (its gains are still kept, offset included).
//   * setPidOffset sets the offset of the controller's gains (getPid shows it), the value YARP's
//     IPidControl adds to the output; the simulated loops track ideally, so it does not move the axis.
//   * disablePid switches a loop off: if its axis runs it, the axis is freed where it is (idle),
//     and until enablePid no request may make the axis run it (TestMotor::on_axis/on_all refuse).
//   * resetPid makes what a running loop measures its reference: the position loop holds the
//     present position (the move ends there, from standstill, as idle stops), the velocity loop
//     keeps the present velocity (the ramp ends), the torque loop already follows its reference.
//     A loop its axis does not run has nothing to reset and accepts.
#include <cmath>

#include "test_motor.hpp"

namespace robogene::dev {

std::optional<std::size_t> TestMotor::loop_index(PidType t) {
  const auto k = pid_index(t);
  return k && *k < 3 ? k : std::nullopt;
}

bool TestMotor::loop_allowed(std::size_t i, ControlMode mode) const {
  switch (mode) {
    case ControlMode::position:
      return pids_[i].enabled[0];
    case ControlMode::velocity:
      return pids_[i].enabled[1];
    case ControlMode::torque:
      return pids_[i].enabled[2];
    default:
      return true;  // idle runs no loop
  }
}

bool TestMotor::setPidOffset(PidType pidtype, int j, double v) {
  const auto k = pid_index(pidtype);
  return k && std::isfinite(v) && on_axis(j, [&](AxisMotion&, std::size_t i) {
           pids_[i].gains[*k].offset = v;
           return true;
         });
}

bool TestMotor::enablePid(PidType pidtype, int j) {
  const auto k = loop_index(pidtype);
  return k && on_axis(j, [&](AxisMotion&, std::size_t i) {
           pids_[i].enabled[*k] = true;
           return true;
         });
}

bool TestMotor::disablePid(PidType pidtype, int j) {
  const auto k = loop_index(pidtype);
  return k && on_axis(j, [&](AxisMotion& a, std::size_t i) {
           pids_[i].enabled[*k] = false;
           if (loop(pidtype, i)) {  // it drives the axis: free the axis where it is
             a.idle();
             modes_[i] = ControlMode::idle;
           }
           return true;
         });
}

bool TestMotor::resetPid(PidType pidtype, int j) {
  const auto k = loop_index(pidtype);
  return k && on_axis(j, [&](AxisMotion& a, std::size_t i) {
           if (!loop(pidtype, i)) return true;  // not running: nothing to reset
           if (pidtype == PidType::position) a.hold();
           if (pidtype == PidType::velocity) a.keep_velocity();
           return true;  // torque: the torque exerted is the reference already
         });
}

bool TestMotor::isPidEnabled(PidType pidtype, int j, bool& enabled) {
  const auto k = loop_index(pidtype);
  return k && on_axis(j, [&](AxisMotion&, std::size_t i) {
           enabled = pids_[i].enabled[*k];
           return true;
         });
}

}  // namespace robogene::dev
