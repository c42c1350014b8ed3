// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// robogene_can: the head's CAN motor boards as one device with the interfaces of test_motor
// (encoders, position, velocity, control mode) plus PID, so `robogene dev --device robogene_can
// --from head.ini` serves the real head exactly as it serves the simulated one.
//
// Configuration: the head's board config (drivers/can/generated/head.ini: [CAN], [GENERAL], [LIMITS],
// [VELOCITY], [PIDS], [COUPLING_n]) plus, at top level: bus (socketcan:IFACE or virtual:NAME,
// default socketcan:<[CAN] device>), can_log (a candump log of this node's traffic),
// ref_speed (deg/s, default 10), ref_acceleration (deg/s^2, default 50).
//
// Units: degrees at the joint; the boards' counts are converted with [GENERAL] encoder. The eye
// board couples version and vergence to the two eye motors itself (as the reference MC4 does),
// with the [COUPLING_3] matrices the driver checks and the simulator uses.
#pragma once

#include <atomic>
#include <memory>
#include <mutex>
#include <thread>
#include <vector>

#include "board_link.hpp"
#include "robogene/can/head_config.hpp"
#include "robogene/can/joint_encoders.hpp"
#include "robogene/dev/device_driver.hpp"
#include "robogene/dev/generated/icontrolmode.hpp"
#include "robogene/dev/generated/iencoders.hpp"
#include "robogene/dev/generated/ipidcontrol.hpp"
#include "robogene/dev/generated/ipositioncontrol.hpp"
#include "robogene/dev/generated/ivelocitycontrol.hpp"

namespace robogene::can {

class RobogeneCan final : public dev::DeviceDriver,
                          public dev::IEncoders,
                          public dev::IPositionControl,
                          public dev::IVelocityControl,
                          public dev::IPidControl,
                          public dev::IControlMode {
 public:
  ~RobogeneCan() override { close(); }

  // Throws dev::ConfigError naming a bad field, or robogene::Error (BusError) naming the bus
  // and the board that did not answer or speaks another protocol.
  bool open(const dev::Searchable& config) override;
  bool close() override;

  // The last failure, as logged ("" when none): what a false return meant.
  std::string last_error() const;

  // A joint's absolute encoder as its board reads it (raw angle, state, stored zero, homed), and
  // storing its zero in the board's flash (robogene/can/joint_encoders.hpp); both throw robogene::Error
  // naming the joint (no encoder, a zero beyond its bits, the board not taking it).
  JointEncoderReading joint_encoder(int j);
  JointEncoderReading store_joint_encoder_zero(int j, std::uint16_t zero);

  bool getAxes(std::int32_t& ax) override;
  bool setRefAcceleration(int j, double acc) override;
  bool setRefAccelerations(const std::vector<double>& accs) override;
  bool getRefAcceleration(int j, double& acc) override;
  bool getRefAccelerations(std::vector<double>& accs) override;
  bool stop(int j) override;
  bool stop() override;

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

  bool velocityMove(int j, double sp) override;
  bool velocityMove(const std::vector<double>& sps) override;
  bool getRefVelocity(int j, double& vel) override;
  bool getRefVelocities(std::vector<double>& vels) override;

  bool setPid(dev::PidType pidtype, int j, const dev::Pid& pid) override;
  bool setPids(dev::PidType pidtype, const std::vector<dev::Pid>& pids) override;
  bool getPid(dev::PidType pidtype, int j, dev::Pid& pid) override;
  bool getPids(dev::PidType pidtype, std::vector<dev::Pid>& pids) override;
  bool setPidReference(dev::PidType pidtype, int j, double ref) override;
  bool setPidReferences(dev::PidType pidtype, const std::vector<double>& refs) override;
  bool getPidReference(dev::PidType pidtype, int j, double& ref) override;
  bool getPidReferences(dev::PidType pidtype, std::vector<double>& refs) override;
  bool setPidErrorLimit(dev::PidType pidtype, int j, double limit) override;
  bool setPidErrorLimits(dev::PidType pidtype, const std::vector<double>& limits) override;
  bool getPidErrorLimit(dev::PidType pidtype, int j, double& limit) override;
  bool getPidErrorLimits(dev::PidType pidtype, std::vector<double>& limits) override;
  bool getPidError(dev::PidType pidtype, int j, double& err) override;
  bool getPidErrors(dev::PidType pidtype, std::vector<double>& errs) override;
  bool getPidOutput(dev::PidType pidtype, int j, double& out) override;
  bool getPidOutputs(dev::PidType pidtype, std::vector<double>& outs) override;
  bool setPidOffset(dev::PidType pidtype, int j, double v) override;
  bool enablePid(dev::PidType pidtype, int j) override;
  bool disablePid(dev::PidType pidtype, int j) override;
  bool resetPid(dev::PidType pidtype, int j) override;
  bool isPidEnabled(dev::PidType pidtype, int j, bool& enabled) override;

  bool getControlMode(int j, dev::ControlMode& mode) override;
  bool getControlModes(std::vector<dev::ControlMode>& modes) override;
  bool setControlMode(int j, dev::ControlMode mode) override;
  bool setControlModes(const std::vector<dev::ControlMode>& modes) override;

 private:
  // Runs f(), turning a thrown robogene::Error into a logged false return.
  template <class F>
  bool guarded(const char* what, int j, F&& f);
  // Checks every value with check() (a problem, or ""), then runs f(j, value) for each joint.
  template <class T, class Check, class F>
  bool for_each(const char* what, const std::vector<T>& values, Check&& check, F&& f);
  template <class T, class F>
  bool read_each(std::vector<T>& out, F&& f);
  const JointConfig& joint(int j) const;
  void send(int j, const Message& m);
  Envelope request(int j, const Message& m);
  void ensure_mode(int j, ControlMode mode);
  // A joint with a joint encoder runs only once its board has homed it from it; throws naming why not.
  void require_not_stopped(int j);
  void require_homed(int j);
  double speed_counts(int j, double deg_per_s) const;
  double acceleration_counts(int j, double deg_per_s2) const;
  BoardLink::BoardState fresh_state(int j) const;
  void only_position(dev::PidType type) const;
  void configure_boards(double ref_acceleration);
  void refresh_velocities();

  HeadConfig head_;
  std::unique_ptr<BoardLink> link_;
  mutable std::mutex mutex_;
  std::vector<double> ref_speed_, ref_acceleration_, ref_velocity_;
  std::vector<ControlMode> commanded_mode_;
  std::vector<bool> homed_;  // per joint: homed by its board (always true without a joint encoder)
  std::string last_error_;
  std::atomic<bool> running_{false};
  std::thread refresher_;
};

}  // namespace robogene::can
