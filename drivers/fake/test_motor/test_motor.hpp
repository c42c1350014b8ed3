// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// test_motor: a simulated control board (paper section 3.3). Each axis follows position and
// velocity moves at the reference speed and acceleration in simulated time, or a torque
// reference as a damped rigid body; the encoders report that motion. A move or a torque reference
// switches its axis to the matching control mode, as YARP's test_motor lets the paper's example
// do; `idle` frees an axis where it is. Each axis keeps the gains and error limits of its four
// PID controllers; its loops are the motion above (docs/devices.md, test_motor). A loop can be
// disabled: an axis never runs a disabled loop (disabling the loop it runs frees it, and a request
// that would run one is refused), whichever method asks (on_axis and on_all check it).
//
// Configuration: axes (1-64, default 4), ref_speed (deg/s, default 10), ref_acceleration
// (deg/s^2, default 50), max_torque (N m, default 5), inertia (kg m^2, default 0.01), damping
// (N m s/rad, default 0.5), clock (wall or manual, default wall).
#pragma once

#include <array>
#include <memory>
#include <mutex>
#include <optional>
#include <vector>

#include "axis_motion.hpp"
#include "robogene/dev/device_driver.hpp"
#include "robogene/dev/generated/icontrolmode.hpp"
#include "robogene/dev/generated/iencoders.hpp"
#include "robogene/dev/generated/ipidcontrol.hpp"
#include "robogene/dev/generated/ipositioncontrol.hpp"
#include "robogene/dev/generated/itorquecontrol.hpp"
#include "robogene/dev/generated/ivelocitycontrol.hpp"
#include "robogene/dev/simulation_clock.hpp"
#include "common/sim_clock.hpp"

namespace robogene::dev {

class TestMotor final : public DeviceDriver,
                        public IEncoders,
                        public IPositionControl,
                        public IVelocityControl,
                        public IControlMode,
                        public ITorqueControl,
                        public IPidControl,
                        public ISimulationClock {
 public:
  bool open(const Searchable& config) override;
  bool close() override;

  // ISimulationClock
  double now() override;
  bool advance(double seconds) override;

  // Shared by IEncoders, IPositionControl, IVelocityControl and ITorqueControl.
  bool getAxes(std::int32_t& ax) override;
  bool setRefAcceleration(int j, double acc) override;
  bool setRefAccelerations(const std::vector<double>& accs) override;
  bool getRefAcceleration(int j, double& acc) override;
  bool getRefAccelerations(std::vector<double>& accs) override;
  bool stop(int j) override;
  bool stop() override;

  // IEncoders
  bool getEncoder(int j, double& v) override;
  bool getEncoders(std::vector<double>& vs) override;
  bool getEncoderSpeed(int j, double& sp) override;
  bool getEncoderSpeeds(std::vector<double>& sps) override;
  bool getEncoderAcceleration(int j, double& acc) override;
  bool getEncoderAccelerations(std::vector<double>& accs) override;
  bool resetEncoder(int j) override;
  bool resetEncoders() override;
  bool setEncoder(int j, double val) override;
  bool setEncoders(const std::vector<double>& vals) override;

  // IPositionControl
  bool positionMove(int j, double ref) override;
  bool positionMove(const std::vector<double>& refs) override;
  bool relativeMove(int j, double delta) override;
  bool relativeMove(const std::vector<double>& deltas) override;
  bool checkMotionDone(int j, bool& flag) override;
  bool checkMotionDone(bool& flag) override;
  bool setRefSpeed(int j, double sp) override;
  bool setRefSpeeds(const std::vector<double>& sps) override;
  bool getRefSpeed(int j, double& sp) override;
  bool getRefSpeeds(std::vector<double>& sps) override;
  bool getTargetPosition(int j, double& ref) override;
  bool getTargetPositions(std::vector<double>& refs) override;

  // IVelocityControl
  bool velocityMove(int j, double sp) override;
  bool velocityMove(const std::vector<double>& sps) override;
  bool getRefVelocity(int j, double& vel) override;
  bool getRefVelocities(std::vector<double>& vels) override;

  // IControlMode
  bool getControlMode(int j, ControlMode& mode) override;
  bool getControlModes(std::vector<ControlMode>& modes) override;
  bool setControlMode(int j, ControlMode mode) override;
  bool setControlModes(const std::vector<ControlMode>& modes) override;

  // ITorqueControl (test_motor_torque_pid.cpp)
  bool getTorque(int j, double& t) override;
  bool getTorques(std::vector<double>& ts) override;
  bool setRefTorque(int j, double t) override;
  bool setRefTorques(const std::vector<double>& ts) override;
  bool getRefTorque(int j, double& t) override;
  bool getRefTorques(std::vector<double>& ts) override;
  bool getTorqueRange(int j, double& min, double& max) override;
  bool getTorqueRanges(std::vector<double>& mins, std::vector<double>& maxs) override;

  // IPidControl (test_motor_torque_pid.cpp)
  bool setPid(PidType pidtype, int j, const Pid& pid) override;
  bool setPids(PidType pidtype, const std::vector<Pid>& pids) override;
  bool getPid(PidType pidtype, int j, Pid& pid) override;
  bool getPids(PidType pidtype, std::vector<Pid>& pids) override;
  bool setPidReference(PidType pidtype, int j, double ref) override;
  bool setPidReferences(PidType pidtype, const std::vector<double>& refs) override;
  bool getPidReference(PidType pidtype, int j, double& ref) override;
  bool getPidReferences(PidType pidtype, std::vector<double>& refs) override;
  bool setPidErrorLimit(PidType pidtype, int j, double limit) override;
  bool setPidErrorLimits(PidType pidtype, const std::vector<double>& limits) override;
  bool getPidErrorLimit(PidType pidtype, int j, double& limit) override;
  bool getPidErrorLimits(PidType pidtype, std::vector<double>& limits) override;
  bool getPidError(PidType pidtype, int j, double& err) override;
  bool getPidErrors(PidType pidtype, std::vector<double>& errs) override;
  bool getPidOutput(PidType pidtype, int j, double& out) override;
  bool getPidOutputs(PidType pidtype, std::vector<double>& outs) override;
  // IPidControl: offset, enable, disable, reset (test_motor_pid_switches.cpp)
  bool setPidOffset(PidType pidtype, int j, double v) override;
  bool enablePid(PidType pidtype, int j) override;
  bool disablePid(PidType pidtype, int j) override;
  bool resetPid(PidType pidtype, int j) override;
  bool isPidEnabled(PidType pidtype, int j, bool& enabled) override;

 private:
  // The controllers of one axis, indexed by PidType (position, velocity, torque, current).
  struct AxisPids {
    std::array<Pid, 4> gains{};
    std::array<double, 4> error_limits{};
    std::array<bool, 4> enabled{{true, true, true, false}};  // there is no current loop to enable
  };
  // The index of a PidType in AxisPids; nullopt for a value outside the enum.
  static std::optional<std::size_t> pid_index(PidType t);
  // The index of a loop the model has (position, velocity, torque); nullopt for current.
  static std::optional<std::size_t> loop_index(PidType t);
  // False when axis i, in `mode`, would run a disabled loop; with mutex_ held.
  bool loop_allowed(std::size_t i, ControlMode mode) const;
  // What a running loop follows and what it measures; nullopt when the axis runs another loop.
  struct LoopState {
    double reference;
    double measured;
  };
  std::optional<LoopState> loop(PidType pidtype, std::size_t i) const;  // with mutex_ held

  // Runs `f(axis)` on axis j with the motion brought up to the present; false for a bad j.
  template <class F>
  bool on_axis(int j, F&& f);
  // Runs `f(axis, value)` for every axis; false unless `values` has one entry per axis.
  template <class T, class F>
  bool on_all(const std::vector<T>& values, F&& f);
  template <class T, class F>
  bool read_all(std::vector<T>& out, F&& f);
  // As read_all, with `f` returning std::optional<T>: false if it has no value for some axis.
  template <class T, class F>
  bool read_all_or_fail(std::vector<T>& out, F&& f);
  void catch_up();  // with mutex_ held

  std::mutex mutex_;
  SimClock clock_;
  double last_ = 0.0;
  bool open_ = false;
  double max_torque_ = 5.0;
  std::vector<AxisMotion> axes_;
  std::vector<ControlMode> modes_;
  std::vector<AxisPids> pids_;
};

// ---- access templates, shared by test_motor.cpp and test_motor_torque_pid.cpp -----------------

template <class F>
bool TestMotor::on_axis(int j, F&& f) {
  std::lock_guard<std::mutex> lock(mutex_);
  if (!open_ || j < 0 || static_cast<std::size_t>(j) >= axes_.size()) return false;
  catch_up();
  const auto i = static_cast<std::size_t>(j);
  const AxisMotion axis = axes_[i];
  const ControlMode mode = modes_[i];
  if (!f(axes_[i], i)) return false;
  if (!loop_allowed(i, modes_[i])) {  // the request would run a disabled loop: undo it
    axes_[i] = axis;
    modes_[i] = mode;
    return false;
  }
  return true;
}

template <class T, class F>
bool TestMotor::on_all(const std::vector<T>& values, F&& f) {
  std::lock_guard<std::mutex> lock(mutex_);
  if (!open_ || values.size() != axes_.size()) return false;
  catch_up();
  // Check every value before changing anything, so a bad entry leaves all axes as they were.
  std::vector<AxisMotion> trial = axes_;
  std::vector<ControlMode> trial_modes = modes_;
  for (std::size_t i = 0; i < axes_.size(); ++i) {
    if (!f(trial[i], trial_modes[i], values[i]) || !loop_allowed(i, trial_modes[i])) return false;
  }
  axes_ = std::move(trial);
  modes_ = std::move(trial_modes);
  return true;
}

template <class T, class F>
bool TestMotor::read_all(std::vector<T>& out, F&& f) {
  std::lock_guard<std::mutex> lock(mutex_);
  if (!open_) return false;
  catch_up();
  out.clear();
  for (std::size_t i = 0; i < axes_.size(); ++i) out.push_back(f(axes_[i], i));
  return true;
}

template <class T, class F>
bool TestMotor::read_all_or_fail(std::vector<T>& out, F&& f) {
  std::lock_guard<std::mutex> lock(mutex_);
  if (!open_) return false;
  catch_up();
  std::vector<T> values;
  for (std::size_t i = 0; i < axes_.size(); ++i) {
    std::optional<T> v = f(axes_[i], i);
    if (!v) return false;
    values.push_back(*v);
  }
  out = std::move(values);
  return true;
}

}  // namespace robogene::dev
