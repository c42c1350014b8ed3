// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// test_motor: a simulated control board (paper section 3.3). Each axis follows position and
// velocity moves at the reference speed and acceleration in simulated time; the encoders report
// that motion. A move switches its axis to the matching control mode, as YARP's test_motor lets
// the paper's example do; `idle` frees an axis where it is.
//
// Configuration: axes (1-64, default 4), ref_speed (deg/s, default 10), ref_acceleration
// (deg/s^2, default 50), clock (wall or manual, default wall).
#pragma once

#include <memory>
#include <mutex>
#include <vector>

#include "axis_motion.hpp"
#include "robogene/dev/device_driver.hpp"
#include "robogene/dev/generated/icontrolmode.hpp"
#include "robogene/dev/generated/iencoders.hpp"
#include "robogene/dev/generated/ipositioncontrol.hpp"
#include "robogene/dev/generated/ivelocitycontrol.hpp"
#include "robogene/dev/simulation_clock.hpp"
#include "common/sim_clock.hpp"

namespace robogene::dev {

class TestMotor final : public DeviceDriver,
                        public IEncoders,
                        public IPositionControl,
                        public IVelocityControl,
                        public IControlMode,
                        public ISimulationClock {
 public:
  bool open(const Searchable& config) override;
  bool close() override;

  // ISimulationClock
  double now() override;
  bool advance(double seconds) override;

  // Shared by IEncoders, IPositionControl and IVelocityControl.
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
  bool checkMotionDone(std::vector<bool>& flags) override;
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

 private:
  // Runs `f(axis)` on axis j with the motion brought up to the present; false for a bad j.
  template <class F>
  bool on_axis(int j, F&& f);
  // Runs `f(axis, value)` for every axis; false unless `values` has one entry per axis.
  template <class T, class F>
  bool on_all(const std::vector<T>& values, F&& f);
  template <class T, class F>
  bool read_all(std::vector<T>& out, F&& f);
  void catch_up();  // with mutex_ held

  std::mutex mutex_;
  SimClock clock_;
  double last_ = 0.0;
  bool open_ = false;
  std::vector<AxisMotion> axes_;
  std::vector<ControlMode> modes_;
};

}  // namespace robogene::dev
