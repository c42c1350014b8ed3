// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// test_motor's torque control and PID controllers. A torque reference drives its axis as a damped
// rigid body (AxisMotion::push) and switches it to torque mode. Each axis keeps the gains and the
// error limit of its four controllers; the loops themselves are the simulated motion, so a loop's
// reference, error and output exist only while its axis runs it: the position loop follows the
// target position, the velocity loop the commanded velocity, the torque loop the torque
// reference, and every loop's output is the torque the motor exerts.
#include <cmath>
#include <optional>

#include "test_motor.hpp"

namespace robogene::dev {
namespace {

bool finite(double v) { return std::isfinite(v); }

bool finite_pid(const Pid& p) {
  for (double v : {p.kp, p.kd, p.ki, p.max_int, p.max_output, p.offset, p.scale, p.stiction_up_val,
                   p.stiction_down_val, p.kff}) {
    if (!finite(v)) return false;
  }
  return true;
}

bool valid_limit(double v) { return finite(v) && v >= 0.0; }

}  // namespace

std::optional<std::size_t> TestMotor::pid_index(PidType t) {
  switch (t) {
    case PidType::position:
      return 0;
    case PidType::velocity:
      return 1;
    case PidType::torque:
      return 2;
    case PidType::current:
      return 3;
  }
  return std::nullopt;
}

// ---- ITorqueControl ----------------------------------------------------------------------------

bool TestMotor::getTorque(int j, double& t) {
  return on_axis(j, [&](AxisMotion& a, std::size_t) {
    t = a.torque();
    return true;
  });
}

bool TestMotor::getTorques(std::vector<double>& ts) {
  return read_all(ts, [](const AxisMotion& a, std::size_t) { return a.torque(); });
}

bool TestMotor::setRefTorque(int j, double t) {
  return finite(t) && std::fabs(t) <= max_torque_ && on_axis(j, [&](AxisMotion& a, std::size_t i) {
           a.push(t);
           modes_[i] = ControlMode::torque;
           return true;
         });
}

bool TestMotor::setRefTorques(const std::vector<double>& ts) {
  const double limit = max_torque_;
  return on_all(ts, [limit](AxisMotion& a, ControlMode& m, double t) {
    if (!finite(t) || std::fabs(t) > limit) return false;
    a.push(t);
    m = ControlMode::torque;
    return true;
  });
}

bool TestMotor::getRefTorque(int j, double& t) {
  return on_axis(j, [&](AxisMotion& a, std::size_t) {
    t = a.ref_torque();
    return true;
  });
}

bool TestMotor::getRefTorques(std::vector<double>& ts) {
  return read_all(ts, [](const AxisMotion& a, std::size_t) { return a.ref_torque(); });
}

bool TestMotor::getTorqueRange(int j, double& min, double& max) {
  return on_axis(j, [&](AxisMotion&, std::size_t) {
    min = -max_torque_;
    max = max_torque_;
    return true;
  });
}

bool TestMotor::getTorqueRanges(std::vector<double>& mins, std::vector<double>& maxs) {
  return read_all(mins, [this](const AxisMotion&, std::size_t) { return -max_torque_; }) &&
         read_all(maxs, [this](const AxisMotion&, std::size_t) { return max_torque_; });
}

// ---- IPidControl: gains and error limits -------------------------------------------------------

bool TestMotor::setPid(PidType pidtype, int j, const Pid& pid) {
  const auto k = pid_index(pidtype);
  return k && finite_pid(pid) && on_axis(j, [&](AxisMotion&, std::size_t i) {
           pids_[i].gains[*k] = pid;
           return true;
         });
}

bool TestMotor::setPids(PidType pidtype, const std::vector<Pid>& pids) {
  const auto k = pid_index(pidtype);
  std::lock_guard<std::mutex> lock(mutex_);
  if (!k || !open_ || pids.size() != pids_.size()) return false;
  for (const Pid& p : pids) {
    if (!finite_pid(p)) return false;
  }
  for (std::size_t i = 0; i < pids.size(); ++i) pids_[i].gains[*k] = pids[i];
  return true;
}

bool TestMotor::getPid(PidType pidtype, int j, Pid& pid) {
  const auto k = pid_index(pidtype);
  return k && on_axis(j, [&](AxisMotion&, std::size_t i) {
           pid = pids_[i].gains[*k];
           return true;
         });
}

bool TestMotor::getPids(PidType pidtype, std::vector<Pid>& pids) {
  const auto k = pid_index(pidtype);
  return k && read_all(pids, [&](const AxisMotion&, std::size_t i) { return pids_[i].gains[*k]; });
}

bool TestMotor::setPidErrorLimit(PidType pidtype, int j, double limit) {
  const auto k = pid_index(pidtype);
  return k && valid_limit(limit) && on_axis(j, [&](AxisMotion&, std::size_t i) {
           pids_[i].error_limits[*k] = limit;
           return true;
         });
}

bool TestMotor::setPidErrorLimits(PidType pidtype, const std::vector<double>& limits) {
  const auto k = pid_index(pidtype);
  std::lock_guard<std::mutex> lock(mutex_);
  if (!k || !open_ || limits.size() != pids_.size()) return false;
  for (double v : limits) {
    if (!valid_limit(v)) return false;
  }
  for (std::size_t i = 0; i < limits.size(); ++i) pids_[i].error_limits[*k] = limits[i];
  return true;
}

bool TestMotor::getPidErrorLimit(PidType pidtype, int j, double& limit) {
  const auto k = pid_index(pidtype);
  return k && on_axis(j, [&](AxisMotion&, std::size_t i) {
           limit = pids_[i].error_limits[*k];
           return true;
         });
}

bool TestMotor::getPidErrorLimits(PidType pidtype, std::vector<double>& limits) {
  const auto k = pid_index(pidtype);
  return k && read_all(limits, [&](const AxisMotion&, std::size_t i) { return pids_[i].error_limits[*k]; });
}

// ---- IPidControl: the loops --------------------------------------------------------------------

std::optional<TestMotor::LoopState> TestMotor::loop(PidType pidtype, std::size_t i) const {
  const AxisMotion& a = axes_[i];
  const ControlMode mode = modes_[i];
  if (pidtype == PidType::position && mode == ControlMode::position) return LoopState{a.target(), a.position()};
  if (pidtype == PidType::velocity && mode == ControlMode::velocity) {
    return LoopState{a.ref_velocity(), a.velocity()};
  }
  if (pidtype == PidType::torque && mode == ControlMode::torque) return LoopState{a.ref_torque(), a.torque()};
  return std::nullopt;  // not running, or a current loop, which the model does not have
}

// Setting a loop's reference directly, bypassing the trajectories, is not simulated.
bool TestMotor::setPidReference(PidType, int, double) { return false; }
bool TestMotor::setPidReferences(PidType, const std::vector<double>&) { return false; }

bool TestMotor::getPidReference(PidType pidtype, int j, double& ref) {
  return on_axis(j, [&](AxisMotion&, std::size_t i) {
    const auto s = loop(pidtype, i);
    if (s) ref = s->reference;
    return s.has_value();
  });
}

bool TestMotor::getPidReferences(PidType pidtype, std::vector<double>& refs) {
  return read_all_or_fail(refs, [&](const AxisMotion&, std::size_t i) -> std::optional<double> {
    const auto s = loop(pidtype, i);
    return s ? std::optional<double>(s->reference) : std::nullopt;
  });
}

bool TestMotor::getPidError(PidType pidtype, int j, double& err) {
  return on_axis(j, [&](AxisMotion&, std::size_t i) {
    const auto s = loop(pidtype, i);
    if (s) err = s->reference - s->measured;
    return s.has_value();
  });
}

bool TestMotor::getPidErrors(PidType pidtype, std::vector<double>& errs) {
  return read_all_or_fail(errs, [&](const AxisMotion&, std::size_t i) -> std::optional<double> {
    const auto s = loop(pidtype, i);
    return s ? std::optional<double>(s->reference - s->measured) : std::nullopt;
  });
}

bool TestMotor::getPidOutput(PidType pidtype, int j, double& out) {
  return on_axis(j, [&](AxisMotion& a, std::size_t i) {
    if (!loop(pidtype, i)) return false;
    out = a.torque();
    return true;
  });
}

bool TestMotor::getPidOutputs(PidType pidtype, std::vector<double>& outs) {
  return read_all_or_fail(outs, [&](const AxisMotion& a, std::size_t i) -> std::optional<double> {
    return loop(pidtype, i) ? std::optional<double>(a.torque()) : std::nullopt;
  });
}

}  // namespace robogene::dev
