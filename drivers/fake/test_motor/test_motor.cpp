// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "test_motor.hpp"

#include <cmath>
#include <limits>

#include "robogene/dev/driver_registrar.hpp"

namespace robogene::dev {
namespace {

bool finite(double v) { return std::isfinite(v); }
bool positive(double v) { return std::isfinite(v) && v > 0.0; }

}  // namespace

bool TestMotor::open(const Searchable& config) {
  std::lock_guard<std::mutex> lock(mutex_);
  const int n = config.get_int("axes", 4, 1, 64);
  const double speed = config.get_float("ref_speed", 10.0, 1e-9, 1e9);
  const double acc = config.get_float("ref_acceleration", 50.0, 1e-9, 1e9);
  const double max_torque = config.get_float("max_torque", 5.0, 1e-9, 1e9);
  const double inertia = config.get_float("inertia", 0.01, 1e-9, 1e9);
  const double damping = config.get_float("damping", 0.5, 1e-9, 1e9);
  clock_.configure(config);
  axes_.assign(static_cast<std::size_t>(n), AxisMotion{});
  for (auto& axis : axes_) {
    axis.set_ref_speed(speed);
    axis.set_ref_acceleration(acc);
    axis.set_dynamics(inertia, damping);
  }
  max_torque_ = max_torque;
  modes_.assign(static_cast<std::size_t>(n), ControlMode::position);
  pids_.assign(static_cast<std::size_t>(n), AxisPids{});
  last_ = clock_.now();
  open_ = true;
  return true;
}

bool TestMotor::close() {
  std::lock_guard<std::mutex> lock(mutex_);
  open_ = false;
  axes_.clear();
  modes_.clear();
  pids_.clear();
  return true;
}

void TestMotor::catch_up() {
  const double t = clock_.now();
  const double dt = t - last_;
  if (dt > 0.0) {
    for (auto& axis : axes_) axis.step(dt);
    last_ = t;
  }
}

double TestMotor::now() {
  std::lock_guard<std::mutex> lock(mutex_);
  return clock_.now();
}

bool TestMotor::advance(double seconds) {
  std::lock_guard<std::mutex> lock(mutex_);
  if (!open_ || !clock_.advance(seconds)) return false;
  catch_up();
  return true;
}

// ---- shared ------------------------------------------------------------------------------------

bool TestMotor::getAxes(std::int32_t& ax) {
  std::lock_guard<std::mutex> lock(mutex_);
  if (!open_) return false;
  ax = static_cast<std::int32_t>(axes_.size());
  return true;
}

bool TestMotor::setRefAcceleration(int j, double acc) {
  return positive(acc) && on_axis(j, [&](AxisMotion& a, std::size_t) {
           a.set_ref_acceleration(acc);
           return true;
         });
}

bool TestMotor::setRefAccelerations(const std::vector<double>& accs) {
  return on_all(accs, [](AxisMotion& a, ControlMode&, double v) {
    if (!positive(v)) return false;
    a.set_ref_acceleration(v);
    return true;
  });
}

bool TestMotor::getRefAcceleration(int j, double& acc) {
  return on_axis(j, [&](AxisMotion& a, std::size_t) {
    acc = a.ref_acceleration();
    return true;
  });
}

bool TestMotor::getRefAccelerations(std::vector<double>& accs) {
  return read_all(accs, [](const AxisMotion& a, std::size_t) { return a.ref_acceleration(); });
}

bool TestMotor::stop(int j) {
  return on_axis(j, [](AxisMotion& a, std::size_t) {
    a.stop();
    return true;
  });
}

bool TestMotor::stop() {
  std::lock_guard<std::mutex> lock(mutex_);
  if (!open_) return false;
  catch_up();
  for (auto& a : axes_) a.stop();
  return true;
}

// ---- IEncoders ---------------------------------------------------------------------------------

bool TestMotor::getEncoder(int j, double& v) {
  return on_axis(j, [&](AxisMotion& a, std::size_t) {
    v = a.position();
    return true;
  });
}

bool TestMotor::getEncoders(std::vector<double>& vs) {
  return read_all(vs, [](const AxisMotion& a, std::size_t) { return a.position(); });
}

bool TestMotor::getEncoderSpeed(int j, double& sp) {
  return on_axis(j, [&](AxisMotion& a, std::size_t) {
    sp = a.velocity();
    return true;
  });
}

bool TestMotor::getEncoderSpeeds(std::vector<double>& sps) {
  return read_all(sps, [](const AxisMotion& a, std::size_t) { return a.velocity(); });
}

bool TestMotor::getEncoderAcceleration(int j, double& acc) {
  return on_axis(j, [&](AxisMotion& a, std::size_t) {
    acc = a.acceleration();
    return true;
  });
}

bool TestMotor::getEncoderAccelerations(std::vector<double>& accs) {
  return read_all(accs, [](const AxisMotion& a, std::size_t) { return a.acceleration(); });
}

bool TestMotor::resetEncoder(int j) { return setEncoder(j, 0.0); }

bool TestMotor::resetEncoders() {
  std::lock_guard<std::mutex> lock(mutex_);
  if (!open_) return false;
  catch_up();
  for (auto& a : axes_) a.set_position(0.0);
  return true;
}

bool TestMotor::setEncoder(int j, double val) {
  return finite(val) && on_axis(j, [&](AxisMotion& a, std::size_t) {
           a.set_position(val);
           return true;
         });
}

bool TestMotor::setEncoders(const std::vector<double>& vals) {
  return on_all(vals, [](AxisMotion& a, ControlMode&, double v) {
    if (!finite(v)) return false;
    a.set_position(v);
    return true;
  });
}

// ---- IPositionControl --------------------------------------------------------------------------

bool TestMotor::positionMove(int j, double ref) {
  return finite(ref) && on_axis(j, [&](AxisMotion& a, std::size_t i) {
           a.move_to(ref);
           modes_[i] = ControlMode::position;
           return true;
         });
}

bool TestMotor::positionMove(const std::vector<double>& refs) {
  return on_all(refs, [](AxisMotion& a, ControlMode& m, double v) {
    if (!finite(v)) return false;
    a.move_to(v);
    m = ControlMode::position;
    return true;
  });
}

bool TestMotor::relativeMove(int j, double delta) {
  return finite(delta) && on_axis(j, [&](AxisMotion& a, std::size_t i) {
           a.move_to((a.goal() == AxisMotion::Goal::Position ? a.target() : a.position()) + delta);
           modes_[i] = ControlMode::position;
           return true;
         });
}

bool TestMotor::relativeMove(const std::vector<double>& deltas) {
  return on_all(deltas, [](AxisMotion& a, ControlMode& m, double d) {
    if (!finite(d)) return false;
    a.move_to((a.goal() == AxisMotion::Goal::Position ? a.target() : a.position()) + d);
    m = ControlMode::position;
    return true;
  });
}

bool TestMotor::checkMotionDone(int j, bool& flag) {
  return on_axis(j, [&](AxisMotion& a, std::size_t) {
    flag = a.done();
    return true;
  });
}

bool TestMotor::checkMotionDone(bool& flag) {
  std::vector<bool> each;
  if (!read_all(each, [](const AxisMotion& a, std::size_t) { return a.done(); })) return false;
  flag = std::all_of(each.begin(), each.end(), [](bool d) { return d; });
  return true;
}

bool TestMotor::setRefSpeed(int j, double sp) {
  return positive(sp) && on_axis(j, [&](AxisMotion& a, std::size_t) {
           a.set_ref_speed(sp);
           return true;
         });
}

bool TestMotor::setRefSpeeds(const std::vector<double>& sps) {
  return on_all(sps, [](AxisMotion& a, ControlMode&, double v) {
    if (!positive(v)) return false;
    a.set_ref_speed(v);
    return true;
  });
}

bool TestMotor::getRefSpeed(int j, double& sp) {
  return on_axis(j, [&](AxisMotion& a, std::size_t) {
    sp = a.ref_speed();
    return true;
  });
}

bool TestMotor::getRefSpeeds(std::vector<double>& sps) {
  return read_all(sps, [](const AxisMotion& a, std::size_t) { return a.ref_speed(); });
}

bool TestMotor::getTargetPosition(int j, double& ref) {
  return on_axis(j, [&](AxisMotion& a, std::size_t) {
    ref = a.target();
    return true;
  });
}

bool TestMotor::getTargetPositions(std::vector<double>& refs) {
  return read_all(refs, [](const AxisMotion& a, std::size_t) { return a.target(); });
}

// ---- IVelocityControl --------------------------------------------------------------------------

bool TestMotor::velocityMove(int j, double sp) {
  return finite(sp) && on_axis(j, [&](AxisMotion& a, std::size_t i) {
           a.move_at(sp);
           modes_[i] = ControlMode::velocity;
           return true;
         });
}

bool TestMotor::velocityMove(const std::vector<double>& sps) {
  return on_all(sps, [](AxisMotion& a, ControlMode& m, double v) {
    if (!finite(v)) return false;
    a.move_at(v);
    m = ControlMode::velocity;
    return true;
  });
}

bool TestMotor::getRefVelocity(int j, double& vel) {
  return on_axis(j, [&](AxisMotion& a, std::size_t) {
    vel = a.ref_velocity();
    return true;
  });
}

bool TestMotor::getRefVelocities(std::vector<double>& vels) {
  return read_all(vels, [](const AxisMotion& a, std::size_t) { return a.ref_velocity(); });
}

// ---- IControlMode ------------------------------------------------------------------------------

namespace {

// Applies a mode to one axis; test_motor simulates idle, position, velocity and torque.
bool apply_mode(AxisMotion& a, ControlMode& current, ControlMode mode) {
  switch (mode) {
    case ControlMode::idle:
      a.idle();
      break;
    case ControlMode::position:
      if (current != ControlMode::position) {
        // Brake at the reference acceleration and hold where the axis comes to rest.
        a.move_to(a.position());
        a.stop();
      }
      break;
    case ControlMode::velocity:
      if (current != ControlMode::velocity) a.move_at(0.0);
      break;
    case ControlMode::torque:
      if (current != ControlMode::torque) a.push(0.0);  // no torque until one is asked for
      break;
    default:
      return false;
  }
  current = mode;
  return true;
}

}  // namespace

bool TestMotor::getControlMode(int j, ControlMode& mode) {
  return on_axis(j, [&](AxisMotion&, std::size_t i) {
    mode = modes_[i];
    return true;
  });
}

bool TestMotor::getControlModes(std::vector<ControlMode>& modes) {
  return read_all(modes, [this](const AxisMotion&, std::size_t i) { return modes_[i]; });
}

bool TestMotor::setControlMode(int j, ControlMode mode) {
  return on_axis(j, [&](AxisMotion& a, std::size_t i) { return apply_mode(a, modes_[i], mode); });
}

bool TestMotor::setControlModes(const std::vector<ControlMode>& modes) {
  return on_all(modes, [](AxisMotion& a, ControlMode& m, ControlMode wanted) {
    return apply_mode(a, m, wanted);
  });
}

ROBOGENE_REGISTER_DRIVER(test_motor,
                         "simulated control board: position, velocity and torque control, encoders, PID gains",
                         TestMotor);

}  // namespace robogene::dev
