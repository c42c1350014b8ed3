// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// robogene_can: the PID and control-mode interfaces.
#include <cmath>

#include "robogene_can_calls.hpp"

namespace robogene::can {
namespace {

using driver_detail::finite_value;

ControlMode to_board(dev::ControlMode m) {
  switch (m) {
    case dev::ControlMode::idle: return ControlMode::idle;
    case dev::ControlMode::position: return ControlMode::position;
    case dev::ControlMode::velocity: return ControlMode::velocity;
    case dev::ControlMode::position_direct: return ControlMode::direct;
    case dev::ControlMode::torque: return ControlMode::torque;
    case dev::ControlMode::current: return ControlMode::current;
    case dev::ControlMode::pwm: return ControlMode::open_loop;
    case dev::ControlMode::unknown: break;
  }
  throw Error("control mode unknown cannot be set");
}

dev::ControlMode from_board(ControlMode m) {
  switch (m) {
    case ControlMode::idle:
    case ControlMode::force_idle: return dev::ControlMode::idle;
    case ControlMode::position: return dev::ControlMode::position;
    case ControlMode::velocity: return dev::ControlMode::velocity;
    case ControlMode::direct: return dev::ControlMode::position_direct;
    case ControlMode::torque: return dev::ControlMode::torque;
    case ControlMode::current: return dev::ControlMode::current;
    case ControlMode::open_loop: return dev::ControlMode::pwm;
    default: return dev::ControlMode::unknown;
  }
}


std::int16_t to_i16(double v, const char* field) {
  if (!std::isfinite(v) || v < -32768 || v > 32767 || v != std::floor(v)) {
    throw Error(std::string("PID ") + field + " " + std::to_string(v) + " is not an integer in -32768..32767 (board units)");
  }
  return static_cast<std::int16_t>(v);
}

// Why the boards cannot take these gains ("" when they can).
std::string pid_problem(const dev::Pid& pid) {
  try {
    to_i16(pid.kp, "kp");
    to_i16(pid.ki, "ki");
    to_i16(pid.kd, "kd");
    to_i16(pid.offset, "offset");
    to_i16(pid.max_output, "max_output");
    to_i16(pid.max_int, "max_int");
  } catch (const Error& e) {
    return e.what();
  }
  if (!(pid.scale >= 0 && pid.scale <= 15 && pid.scale == std::floor(pid.scale))) {
    return "PID scale (shift) " + std::to_string(pid.scale) + " is not an integer in 0..15";
  }
  return "";
}


}  // namespace

// ---- IPidControl: the boards close one loop, on position ---------------------------------------

void RobogeneCan::only_position(dev::PidType type) const {
  if (type != dev::PidType::position) {
    throw Error(std::string("the head's boards have no ") + dev::name_of(type) + " PID, only a position PID");
  }
}

bool RobogeneCan::setPid(dev::PidType pidtype, int j, const dev::Pid& pid) {
  return guarded("setPid", j, [&] {
    only_position(pidtype);
    const std::string problem = pid_problem(pid);
    if (!problem.empty()) throw Error(problem);
    const SetPositionPid gains{to_i16(pid.kp, "kp"), to_i16(pid.ki, "ki"), to_i16(pid.kd, "kd"), static_cast<std::uint8_t>(pid.scale)};
    const SetPositionPidLimits limits{to_i16(pid.offset, "offset"), to_i16(pid.max_output, "max_output"),
                                      to_i16(pid.max_int, "max_int")};
    send(j, gains);
    send(j, limits);
  });
}
bool RobogeneCan::setPids(dev::PidType pidtype, const std::vector<dev::Pid>& pids) {
  return for_each("setPids", pids, pid_problem, [&](int j, const dev::Pid& p) { return setPid(pidtype, j, p); });
}
bool RobogeneCan::getPid(dev::PidType pidtype, int j, dev::Pid& pid) {
  return guarded("getPid", j, [&] {
    only_position(pidtype);
    const auto g = std::get<GetPositionPidReply>(request(j, GetPositionPid{}).message);
    const auto l = std::get<GetPositionPidLimitsReply>(request(j, GetPositionPidLimits{}).message);
    pid = dev::Pid{};
    pid.kp = g.kp;
    pid.ki = g.ki;
    pid.kd = g.kd;
    pid.scale = g.shift;
    pid.offset = l.offset;
    pid.max_output = l.output_limit;
    pid.max_int = l.integral_limit;
  });
}
bool RobogeneCan::getPids(dev::PidType pidtype, std::vector<dev::Pid>& pids) {
  return read_each(pids, [&](int j, dev::Pid& p) { return getPid(pidtype, j, p); });
}
bool RobogeneCan::setPidReference(dev::PidType pidtype, int j, double ref) {
  // The position loop's reference is the trajectory's: a target reached at once is a position move
  // at the joint's top speed.
  return guarded("setPidReference", j, [&] {
    only_position(pidtype);
    if (!std::isfinite(ref)) throw Error("reference is not finite");
    ensure_mode(j, ControlMode::position);
    send(j, PositionMove{static_cast<std::int32_t>(std::lround(ref * joint(j).counts_per_degree)),
                         speed_counts(j, joint(j).max_velocity)});
  });
}
bool RobogeneCan::setPidReferences(dev::PidType pidtype, const std::vector<double>& refs) {
  return for_each("setPidReferences", refs, finite_value, [&](int j, double r) { return setPidReference(pidtype, j, r); });
}
bool RobogeneCan::getPidReference(dev::PidType pidtype, int j, double& ref) {
  return guarded("getPidReference", j, [&] {
    only_position(pidtype);
    ref = std::get<GetDesiredPositionReply>(request(j, GetDesiredPosition{}).message).position / joint(j).counts_per_degree;
  });
}
bool RobogeneCan::getPidReferences(dev::PidType pidtype, std::vector<double>& refs) {
  return read_each(refs, [&](int j, double& r) { return getPidReference(pidtype, j, r); });
}
bool RobogeneCan::setPidErrorLimit(dev::PidType, int j, double) {
  return guarded("setPidErrorLimit", j, [&] { throw Error("the boards' protocol has no PID error limit"); });
}
bool RobogeneCan::setPidErrorLimits(dev::PidType pidtype, const std::vector<double>& limits) {
  return for_each("setPidErrorLimits", limits, finite_value, [&](int j, double l) { return setPidErrorLimit(pidtype, j, l); });
}
bool RobogeneCan::getPidErrorLimit(dev::PidType, int j, double&) {
  return guarded("getPidErrorLimit", j, [&] { throw Error("the boards' protocol has no PID error limit"); });
}
bool RobogeneCan::getPidErrorLimits(dev::PidType pidtype, std::vector<double>& limits) {
  return read_each(limits, [&](int j, double& l) { return getPidErrorLimit(pidtype, j, l); });
}
bool RobogeneCan::getPidError(dev::PidType pidtype, int j, double& err) {
  // The target less the measured position: the error the loop works off when the trajectory ends.
  return guarded("getPidError", j, [&] {
    only_position(pidtype);
    const double target = std::get<GetDesiredPositionReply>(request(j, GetDesiredPosition{}).message).position;
    const auto s = fresh_state(j);
    err = (target - s.position[static_cast<std::size_t>(joint(j).axis)]) / joint(j).counts_per_degree;
  });
}
bool RobogeneCan::getPidErrors(dev::PidType pidtype, std::vector<double>& errs) {
  return read_each(errs, [&](int j, double& e) { return getPidError(pidtype, j, e); });
}
bool RobogeneCan::getPidOutput(dev::PidType pidtype, int j, double& out) {
  return guarded("getPidOutput", j, [&] {
    only_position(pidtype);
    out = std::get<GetPidOutputReply>(request(j, GetPidOutput{}).message).output;
  });
}
bool RobogeneCan::getPidOutputs(dev::PidType pidtype, std::vector<double>& outs) {
  return read_each(outs, [&](int j, double& o) { return getPidOutput(pidtype, j, o); });
}

// The offset travels with the output and integral limits (set_position_pid_limits): read the
// other two back so that only the offset changes.
bool RobogeneCan::setPidOffset(dev::PidType pidtype, int j, double v) {
  return guarded("setPidOffset", j, [&] {
    only_position(pidtype);
    const std::int16_t offset = to_i16(v, "offset");
    const auto l = std::get<GetPositionPidLimitsReply>(request(j, GetPositionPidLimits{}).message);
    send(j, SetPositionPidLimits{offset, l.output_limit, l.integral_limit});
  });
}
// The boards' protocol has no command to switch the position loop on or off, to reset it, or to
// report whether it runs (only control modes, which the boards change themselves on faults).
bool RobogeneCan::enablePid(dev::PidType, int j) {
  return guarded("enablePid", j, [&] {
    joint(j);
    throw Error("the boards' protocol has no command to switch a PID on or off (use setControlMode)");
  });
}
bool RobogeneCan::disablePid(dev::PidType, int j) {
  return guarded("disablePid", j, [&] {
    joint(j);
    throw Error("the boards' protocol has no command to switch a PID on or off (use setControlMode)");
  });
}
bool RobogeneCan::resetPid(dev::PidType, int j) {
  return guarded("resetPid", j, [&] {
    joint(j);
    throw Error("the boards' protocol has no command to reset a PID");
  });
}
bool RobogeneCan::isPidEnabled(dev::PidType, int j, bool&) {
  return guarded("isPidEnabled", j, [&] {
    joint(j);
    throw Error("the boards' protocol does not report whether a PID is switched on (getControlMode says what runs)");
  });
}

// ---- IControlMode ------------------------------------------------------------------------------

bool RobogeneCan::getControlMode(int j, dev::ControlMode& mode) {
  return guarded("getControlMode", j, [&] {
    const ControlMode m = std::get<GetControlModeReply>(request(j, GetControlMode{}).message).mode;
    mode = from_board(m);
    std::lock_guard<std::mutex> lock(mutex_);
    commanded_mode_[static_cast<std::size_t>(j)] = m;
  });
}
bool RobogeneCan::getControlModes(std::vector<dev::ControlMode>& modes) {
  return read_each(modes, [&](int j, dev::ControlMode& m) { return getControlMode(j, m); });
}
bool RobogeneCan::setControlMode(int j, dev::ControlMode mode) {
  return guarded("setControlMode", j, [&] {
    const ControlMode wanted = to_board(mode);
    if (wanted == ControlMode::position || wanted == ControlMode::velocity) require_homed(j);
    send(j, SetControlMode{wanted});
    // Setting a mode has no reply: ask, so a mode the board refuses is reported, not assumed.
    const ControlMode now = std::get<GetControlModeReply>(request(j, GetControlMode{}).message).mode;
    {
      std::lock_guard<std::mutex> lock(mutex_);
      commanded_mode_[static_cast<std::size_t>(j)] = now;
      if (now != ControlMode::velocity) ref_velocity_[static_cast<std::size_t>(j)] = 0.0;
    }
    if (now != wanted) {
      throw Error(std::string("board ") + std::to_string(joint(j).board) + " stayed in mode " + to_string(now) +
                  " instead of " + to_string(wanted));
    }
  });
}
bool RobogeneCan::setControlModes(const std::vector<dev::ControlMode>& modes) {
  return for_each("setControlModes", modes, [](dev::ControlMode m) { return m == dev::ControlMode::unknown ? std::string("mode unknown cannot be set") : std::string(); }, [&](int j, dev::ControlMode m) { return setControlMode(j, m); });
}


}  // namespace robogene::can
