// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// robogene_can: opening and closing, and the encoder, position and velocity interfaces.
#include <cmath>

#include "robogene/can/logging_bus.hpp"
#include "robogene/dev/driver_registrar.hpp"
#include "robogene_can_calls.hpp"

namespace robogene::can {
namespace {

using driver_detail::finite_value;
using driver_detail::kWho;
using driver_detail::positive_value;

// Scaled wire fields take multiples of their step; the codec rounds, these keep within range.
double round_to(double v, double step, double limit) { return std::clamp(std::round(v / step) * step, -limit, limit); }

}  // namespace


std::string RobogeneCan::last_error() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return last_error_;
}

const JointConfig& RobogeneCan::joint(int j) const {
  if (j < 0 || static_cast<std::size_t>(j) >= head_.joints.size()) {
    throw Error("no joint " + std::to_string(j) + " (the head has " + std::to_string(head_.joints.size()) + ")");
  }
  return head_.joints[static_cast<std::size_t>(j)];
}

void RobogeneCan::send(int j, const Message& m) { link_->send(joint(j).board, joint(j).axis, m); }
Envelope RobogeneCan::request(int j, const Message& m) { return link_->request(joint(j).board, joint(j).axis, m); }

double RobogeneCan::speed_counts(int j, double deg_per_s) const {
  const JointConfig& jc = joint(j);
  return round_to(std::clamp(deg_per_s, -jc.max_velocity, jc.max_velocity) * jc.counts_per_degree, 10, 327670);
}

double RobogeneCan::acceleration_counts(int j, double deg_per_s2) const {
  return round_to(deg_per_s2 * joint(j).counts_per_degree, 1000, 32767000);
}

void RobogeneCan::require_homed(int j) {
  const JointConfig& jc = joint(j);
  {
    // Homed once is not enough: a board that was reset, or given another zero, reports not_configured
    // in its status broadcast (sent on every change) until it has homed the joint again.
    const BoardLink::BoardState s = link_->state(jc.board);
    const bool unconfigured = s.status_time && s.mode[static_cast<std::size_t>(jc.axis)] == ControlMode::not_configured;
    std::lock_guard<std::mutex> lock(mutex_);
    if (homed_[static_cast<std::size_t>(j)] && !unconfigured) return;
    homed_[static_cast<std::size_t>(j)] = false;
  }
  const JointEncoderReading r = read_joint_encoder(*link_, head_, jc);
  if (!r.homed) {
    std::string why = "its joint encoder is " + r.state;
    if (!r.zero_stored) {
      why += ", and its board has no zero stored (measure and store it: robogene can-zero, docs/fabricate.md \"Homing\")";
    } else if (r.state == "ok" && r.joint_degrees) {
      why += ", but with the stored zero (" + std::to_string(r.zero) + ") it reads " + std::to_string(*r.joint_degrees) +
             " deg, outside the joint's range: a wrong zero or a slipped magnet";
    }
    throw Error("joint " + jc.name + " is not homed (board " + std::to_string(jc.board) + " keeps it not_configured): " + why);
  }
  std::lock_guard<std::mutex> lock(mutex_);
  homed_[static_cast<std::size_t>(j)] = true;
  // The board refused the modes sent while it was not homed: send the next one again.
  commanded_mode_[static_cast<std::size_t>(j)] = ControlMode::not_configured;
}

// A board that stopped a joint on a fault ignores moves until the host sends force_idle: say so, naming the faults,
// rather than send moves that do nothing.
void RobogeneCan::require_not_stopped(int j) {
  const JointConfig& jc = joint(j);
  const BoardLink::BoardState s = link_->state(jc.board);
  const auto axis = static_cast<std::size_t>(jc.axis);
  if (!s.status_time || s.mode[axis] != ControlMode::hardware_fault) return;
  // The broadcast may predate a force_idle just sent: the board's own answer decides.
  if (std::get<GetControlModeReply>(request(j, GetControlMode{}).message).mode != ControlMode::hardware_fault) return;
  const std::string faults = axis_faults::names(s.faults[axis]);
  throw Error("joint " + jc.name + " was stopped by board " + std::to_string(jc.board) + " (hardware_fault: " +
              (faults.empty() ? "no fault bit" : faults) + "); setControlMode force_idle clears it");
}

JointEncoderReading RobogeneCan::joint_encoder(int j) { return read_joint_encoder(*link_, head_, joint(j)); }

JointEncoderReading RobogeneCan::store_joint_encoder_zero(int j, std::uint16_t zero) {
  const JointConfig& jc = joint(j);
  {
    // Whether the board homes the joint from the new zero or not, it is asked again before the next move.
    std::lock_guard<std::mutex> lock(mutex_);
    homed_[static_cast<std::size_t>(j)] = jc.joint_encoder_bits == 0;
  }
  return can::store_joint_encoder_zero(*link_, head_, jc, zero);
}

void RobogeneCan::ensure_mode(int j, ControlMode mode) {
  require_homed(j);
  require_not_stopped(j);
  {
    std::lock_guard<std::mutex> lock(mutex_);
    if (commanded_mode_[static_cast<std::size_t>(j)] == mode) return;
  }
  send(j, SetControlMode{mode});
  std::lock_guard<std::mutex> lock(mutex_);
  commanded_mode_[static_cast<std::size_t>(j)] = mode;
  if (mode != ControlMode::velocity) ref_velocity_[static_cast<std::size_t>(j)] = 0.0;
}

BoardLink::BoardState RobogeneCan::fresh_state(int j) const {
  if (auto fault = link_->fault()) throw Error(*fault);
  const BoardLink::BoardState s = link_->state(joint(j).board);
  const auto max_age = Millis(head_.reply_timeout_ms);
  if (!s.position_time || BoardLink::Clock::now() - *s.position_time > max_age) {
    throw BusError(BusErrorKind::timeout, link_->bus_name() + ": board " + std::to_string(joint(j).board) +
                                              " has broadcast no position for over " + std::to_string(max_age.count()) + " ms");
  }
  return s;
}

// ---- open / close ------------------------------------------------------------------------------

void RobogeneCan::configure_boards(double ref_acceleration) {
  for (const auto& b : head_.boards) {
    const Envelope e = link_->request(b.address, 0, GetFirmwareVersion{static_cast<std::uint8_t>(head_.protocol_major),
                                                                        static_cast<std::uint8_t>(head_.protocol_minor)});
    const auto& v = std::get<GetFirmwareVersionReply>(e.message);
    if (!v.compatible) {
      throw Error(link_->bus_name() + ": board " + std::to_string(b.address) + " (" + b.name + ") speaks protocol " +
                  std::to_string(v.protocol_major) + "." + std::to_string(v.protocol_minor) + ", the config asks for " +
                  std::to_string(head_.protocol_major) + "." + std::to_string(head_.protocol_minor));
    }
    link_->send(b.address, 0, SetBroadcastPolicy{head_.broadcast_policy});
  }
  for (std::size_t i = 0; i < head_.joints.size(); ++i) {
    const int j = static_cast<int>(i);
    const JointConfig& jc = head_.joints[i];
    const auto counts = [&](double deg) { return static_cast<std::int32_t>(std::lround(deg * jc.counts_per_degree)); };
    send(j, SetVelocityTimeout{static_cast<std::int16_t>(head_.velocity_timeout_ms)});
    send(j, SetPositionPid{static_cast<std::int16_t>(jc.pid.kp), static_cast<std::int16_t>(jc.pid.ki),
                           static_cast<std::int16_t>(jc.pid.kd), static_cast<std::uint8_t>(jc.pid.shift)});
    send(j, SetPositionPidLimits{static_cast<std::int16_t>(jc.pid.offset), static_cast<std::int16_t>(jc.pid.output_limit),
                                 static_cast<std::int16_t>(jc.pid.integral_limit)});
    send(j, SetMinPosition{counts(jc.min)});
    send(j, SetMaxPosition{counts(jc.max)});
    send(j, SetMaxVelocity{round_to(jc.max_velocity * jc.counts_per_degree, 10, 327670)});
    send(j, SetCurrentLimit{static_cast<std::int32_t>(std::lround(jc.current_limit))});
    send(j, SetDesiredAcceleration{acceleration_counts(j, ref_acceleration)});
    send(j, SetControlMode{ControlMode::position});
  }
}

bool RobogeneCan::open(const dev::Searchable& config) {
  close();
  head_ = read_head_config(config);
  const std::string spec = config.get_string("bus", "socketcan:" + head_.device);
  const std::string log_path = config.get_string("can_log", "");
  const double speed = config.get_float("ref_speed", 10.0, 1e-6, 1e5);
  const double acceleration = config.get_float("ref_acceleration", 50.0, 1e-3, 1e6);
  std::unique_ptr<Bus> bus = open_bus(spec);
  if (!log_path.empty()) bus = std::make_unique<LoggingBus>(std::move(bus), std::make_shared<CandumpWriter>(log_path));
  link_ = std::make_unique<BoardLink>(std::move(bus), Millis(head_.reply_timeout_ms));
  const std::size_t n = head_.joints.size();
  ref_speed_.assign(n, speed);
  ref_acceleration_.assign(n, acceleration);
  ref_velocity_.assign(n, 0.0);
  commanded_mode_.assign(n, ControlMode::position);
  homed_.assign(n, true);
  for (std::size_t j = 0; j < n; ++j) homed_[j] = head_.joints[j].joint_encoder_bits == 0;
  try {
    configure_boards(acceleration);
    // Every board must be heard before the device counts as open.
    const auto deadline = BoardLink::Clock::now() + Millis(head_.reply_timeout_ms);
    for (const auto& b : head_.boards) {
      while (!link_->state(b.address).position_time && BoardLink::Clock::now() < deadline) std::this_thread::sleep_for(Millis(2));
      if (!link_->state(b.address).position_time) {
        throw BusError(BusErrorKind::timeout, link_->bus_name() + ": board " + std::to_string(b.address) + " (" + b.name +
                                                  ") sends no position broadcasts");
      }
    }
  } catch (...) {
    link_.reset();
    throw;
  }
  // The joints their boards could not home from their joint encoders stay not_configured: say so now.
  for (std::size_t j = 0; j < n; ++j) {
    if (homed_[j]) continue;
    try {
      require_homed(static_cast<int>(j));
    } catch (const Error& e) {
      log::warn(kWho, e.what());
    }
  }
  running_ = true;
  refresher_ = std::thread([this] { refresh_velocities(); });
  return true;
}

bool RobogeneCan::close() {
  running_ = false;
  if (refresher_.joinable()) refresher_.join();
  if (link_) {
    // Leave the head still: idle would let the neck drop, so hold position where it is.
    for (std::size_t j = 0; j < head_.joints.size(); ++j) {
      try {
        send(static_cast<int>(j), StopTrajectory{});
      } catch (const Error& e) {
        log::warn(kWho, std::string("closing: ") + e.what());
        break;
      }
    }
  }
  link_.reset();
  return true;
}

// The boards stop an axis whose velocity command is older than the velocity timeout, so a host
// that dies leaves the head still; while the device lives, velocity commands are repeated.
void RobogeneCan::refresh_velocities() {
  const auto period = Millis(std::max(5, head_.velocity_timeout_ms / 4));
  while (running_) {
    std::this_thread::sleep_for(period);
    if (link_->fault()) continue;  // commands fail with the fault already; no need to log it 40 times a second
    for (std::size_t j = 0; j < head_.joints.size(); ++j) {
      double v = 0;
      {
        std::lock_guard<std::mutex> lock(mutex_);
        if (commanded_mode_[j] != ControlMode::velocity || ref_velocity_[j] == 0.0) continue;
        v = ref_velocity_[j];
      }
      const int i = static_cast<int>(j);
      guarded("velocity refresh", i, [&] {
        send(i, VelocityMove{speed_counts(i, v), acceleration_counts(i, ref_acceleration_[j])});
      });
    }
  }
}

// ---- shared ------------------------------------------------------------------------------------

bool RobogeneCan::getAxes(std::int32_t& ax) {
  return guarded("getAxes", -1, [&] { ax = static_cast<std::int32_t>(head_.joints.size()); });
}

bool RobogeneCan::setRefAcceleration(int j, double acc) {
  return guarded("setRefAcceleration", j, [&] {
    if (!std::isfinite(acc) || acc <= 0) throw Error("acceleration " + std::to_string(acc) + " must be positive");
    send(j, SetDesiredAcceleration{acceleration_counts(j, acc)});
    std::lock_guard<std::mutex> lock(mutex_);
    ref_acceleration_[static_cast<std::size_t>(j)] = acc;
  });
}
bool RobogeneCan::setRefAccelerations(const std::vector<double>& accs) {
  return for_each("setRefAccelerations", accs, positive_value, [&](int j, double a) { return setRefAcceleration(j, a); });
}
bool RobogeneCan::getRefAcceleration(int j, double& acc) {
  return guarded("getRefAcceleration", j, [&] {
    joint(j);
    std::lock_guard<std::mutex> lock(mutex_);
    acc = ref_acceleration_[static_cast<std::size_t>(j)];
  });
}
bool RobogeneCan::getRefAccelerations(std::vector<double>& accs) {
  return read_each(accs, [&](int j, double& a) { return getRefAcceleration(j, a); });
}

bool RobogeneCan::stop(int j) {
  return guarded("stop", j, [&] {
    send(j, StopTrajectory{});
    std::lock_guard<std::mutex> lock(mutex_);
    ref_velocity_[static_cast<std::size_t>(j)] = 0.0;
  });
}
bool RobogeneCan::stop() {
  bool ok = true;
  for (std::size_t j = 0; j < head_.joints.size(); ++j) ok = stop(static_cast<int>(j)) && ok;
  return ok && link_;
}

// ---- IEncoders ---------------------------------------------------------------------------------

bool RobogeneCan::getEncoder(int j, double& v) {
  return guarded("getEncoder", j, [&] {
    const auto s = fresh_state(j);
    v = s.position[static_cast<std::size_t>(joint(j).axis)] / joint(j).counts_per_degree;
  });
}
bool RobogeneCan::getEncoders(std::vector<double>& vs) {
  return read_each(vs, [&](int j, double& v) { return getEncoder(j, v); });
}
bool RobogeneCan::getEncoderSpeed(int j, double& sp) {
  return guarded("getEncoderSpeed", j, [&] {
    if (head_.broadcast_policy & broadcast_mask::velocity) {
      const auto s = fresh_state(j);
      sp = s.speed[static_cast<std::size_t>(joint(j).axis)] / joint(j).counts_per_degree;
    } else {
      const auto r = std::get<GetEncoderPositionReply>(request(j, GetEncoderPosition{}).message);
      sp = r.speed / joint(j).counts_per_degree;
    }
  });
}
bool RobogeneCan::getEncoderSpeeds(std::vector<double>& sps) {
  return read_each(sps, [&](int j, double& v) { return getEncoderSpeed(j, v); });
}
bool RobogeneCan::getEncoderAcceleration(int j, double& acc) {
  return guarded("getEncoderAcceleration", j, [&] {
    if (!(head_.broadcast_policy & broadcast_mask::velocity)) {
      throw Error("the broadcast policy has no velocity broadcast, which carries accelerations");
    }
    const auto s = fresh_state(j);
    acc = s.acceleration[static_cast<std::size_t>(joint(j).axis)] / joint(j).counts_per_degree;
  });
}
bool RobogeneCan::getEncoderAccelerations(std::vector<double>& accs) {
  return read_each(accs, [&](int j, double& v) { return getEncoderAcceleration(j, v); });
}
bool RobogeneCan::resetEncoder(int j) { return setEncoder(j, 0.0); }
bool RobogeneCan::resetEncoders() {
  return setEncoders(std::vector<double>(head_.joints.size(), 0.0));
}
bool RobogeneCan::setEncoder(int j, double val) {
  return guarded("setEncoder", j, [&] {
    if (!std::isfinite(val)) throw Error("position is not finite");
    send(j, SetEncoderPosition{static_cast<std::int32_t>(std::lround(val * joint(j).counts_per_degree))});
  });
}
bool RobogeneCan::setEncoders(const std::vector<double>& vals) {
  return for_each("setEncoders", vals, finite_value, [&](int j, double v) { return setEncoder(j, v); });
}

// ---- IPositionControl --------------------------------------------------------------------------

bool RobogeneCan::positionMove(int j, double ref) {
  return guarded("positionMove", j, [&] {
    if (!std::isfinite(ref)) throw Error("target is not finite");
    ensure_mode(j, ControlMode::position);
    double speed = 0;
    {
      std::lock_guard<std::mutex> lock(mutex_);
      speed = ref_speed_[static_cast<std::size_t>(j)];
    }
    send(j, PositionMove{static_cast<std::int32_t>(std::lround(ref * joint(j).counts_per_degree)), speed_counts(j, speed)});
  });
}
bool RobogeneCan::positionMove(const std::vector<double>& refs) {
  return for_each("positionMove", refs, finite_value, [&](int j, double r) { return positionMove(j, r); });
}
bool RobogeneCan::relativeMove(int j, double delta) {
  double target = 0;
  return getTargetPosition(j, target) && positionMove(j, target + delta);
}
bool RobogeneCan::relativeMove(const std::vector<double>& deltas) {
  return for_each("relativeMove", deltas, finite_value, [&](int j, double d) { return relativeMove(j, d); });
}
bool RobogeneCan::checkMotionDone(int j, bool& flag) {
  return guarded("checkMotionDone", j, [&] { flag = std::get<MotionDoneReply>(request(j, MotionDone{}).message).done; });
}
bool RobogeneCan::checkMotionDone(bool& flag) {
  bool ok = true;
  flag = true;
  for (std::size_t j = 0; j < head_.joints.size(); ++j) {  // every axis asked, so a failing board shows
    bool f = false;
    ok = checkMotionDone(static_cast<int>(j), f) && ok;
    flag = flag && f;
  }
  return ok;
}
bool RobogeneCan::setRefSpeed(int j, double sp) {
  return guarded("setRefSpeed", j, [&] {
    joint(j);
    if (!std::isfinite(sp) || sp <= 0) throw Error("speed " + std::to_string(sp) + " must be positive");
    std::lock_guard<std::mutex> lock(mutex_);
    ref_speed_[static_cast<std::size_t>(j)] = sp;
  });
}
bool RobogeneCan::setRefSpeeds(const std::vector<double>& sps) {
  return for_each("setRefSpeeds", sps, positive_value, [&](int j, double s) { return setRefSpeed(j, s); });
}
bool RobogeneCan::getRefSpeed(int j, double& sp) {
  return guarded("getRefSpeed", j, [&] {
    joint(j);
    std::lock_guard<std::mutex> lock(mutex_);
    sp = ref_speed_[static_cast<std::size_t>(j)];
  });
}
bool RobogeneCan::getRefSpeeds(std::vector<double>& sps) {
  return read_each(sps, [&](int j, double& s) { return getRefSpeed(j, s); });
}
bool RobogeneCan::getTargetPosition(int j, double& ref) {
  return guarded("getTargetPosition", j, [&] {
    ref = std::get<GetDesiredPositionReply>(request(j, GetDesiredPosition{}).message).position / joint(j).counts_per_degree;
  });
}
bool RobogeneCan::getTargetPositions(std::vector<double>& refs) {
  return read_each(refs, [&](int j, double& r) { return getTargetPosition(j, r); });
}

// ---- IVelocityControl --------------------------------------------------------------------------

bool RobogeneCan::velocityMove(int j, double sp) {
  return guarded("velocityMove", j, [&] {
    if (!std::isfinite(sp)) throw Error("speed is not finite");
    ensure_mode(j, ControlMode::velocity);
    double acc = 0;
    {
      std::lock_guard<std::mutex> lock(mutex_);
      acc = ref_acceleration_[static_cast<std::size_t>(j)];
    }
    send(j, VelocityMove{speed_counts(j, sp), acceleration_counts(j, acc)});
    std::lock_guard<std::mutex> lock(mutex_);
    ref_velocity_[static_cast<std::size_t>(j)] = sp;
  });
}
bool RobogeneCan::velocityMove(const std::vector<double>& sps) {
  return for_each("velocityMove", sps, finite_value, [&](int j, double s) { return velocityMove(j, s); });
}
bool RobogeneCan::getRefVelocity(int j, double& vel) {
  return guarded("getRefVelocity", j, [&] {
    joint(j);
    std::lock_guard<std::mutex> lock(mutex_);
    vel = ref_velocity_[static_cast<std::size_t>(j)];
  });
}
bool RobogeneCan::getRefVelocities(std::vector<double>& vels) {
  return read_each(vels, [&](int j, double& v) { return getRefVelocity(j, v); });
}

ROBOGENE_REGISTER_DRIVER(robogene_can, "the head's CAN motor boards (SocketCAN or virtual bus): encoders, position, velocity, PID, control mode",
                         RobogeneCan);

}  // namespace robogene::can
