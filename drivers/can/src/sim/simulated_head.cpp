// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "robogene/can/sim/simulated_head.hpp"

#include <chrono>

#include "robogene/log.hpp"

namespace robogene::can::sim {
namespace {

constexpr int kMaxCatchUpTicks = 50;  // past this the loop gives up on real time instead of spinning

std::string describe(const BrakeChange& c) {
  if (c.released) {
    return "brake released, its bridge on for " + std::to_string(c.bridge_periods) + (c.bridge_periods == 1 ? " period" : " periods");
  }
  return std::string("brake applied, its bridge ") + (c.bridge_on ? "still on" : "off");
}

}  // namespace

SimulatedHead::SimulatedHead(const HeadConfig& head, std::unique_ptr<Bus> bus, const MotorParameters& motor,
                             const std::string& flash_dir)
    : bus_(std::move(bus)), head_(head), period_s_(head.control_period_us / 1e6) {
  for (const auto& b : head.boards) {
    const std::string flash =
        flash_dir.empty() ? "" : flash_dir + "/board-" + std::to_string(b.address) + "-" + b.name + ".flash";
    boards_.emplace_back(head, b, motor, flash);
  }
  // The host's commands (source 0) of the motor-control and bootloader classes: the only frames
  // boards act on.
  bus_->set_filters({{0x000, 0x7F0}, {0x700, 0x7F0}});
  thread_ = std::thread([this] { loop(); });
}

SimulatedHead::~SimulatedHead() { stop(); }

void SimulatedHead::stop() {
  running_ = false;
  if (thread_.joinable()) thread_.join();
}

BoardSim& SimulatedHead::board(int address) {
  for (auto& b : boards_) {
    if (b.address() == address) return b;
  }
  throw Error("simulated head: no board at address " + std::to_string(address));
}

double SimulatedHead::motor_degrees(int address, int motor) {
  std::lock_guard<std::mutex> lock(mutex_);
  return board(address).motor_degrees(motor);
}

std::int32_t SimulatedHead::measured_counts(int address, int axis) {
  std::lock_guard<std::mutex> lock(mutex_);
  return board(address).measured_counts(axis);
}

void SimulatedHead::power_up_at(int address, double motor0_degrees, double motor1_degrees) {
  std::lock_guard<std::mutex> lock(mutex_);
  board(address).power_up_at(motor0_degrees, motor1_degrees);
}

bool SimulatedHead::has_brake(int address, int motor) {
  std::lock_guard<std::mutex> lock(mutex_);
  return board(address).has_brake(motor);
}

bool SimulatedHead::brake_holding(int address, int motor) {
  std::lock_guard<std::mutex> lock(mutex_);
  return board(address).brake_holding(motor);
}

// Each brake change as a log line (info) naming the board and the joint, so a user of `robogene
// can-sim` sees the brakes work (ROBOGENE_LOG=info).
void SimulatedHead::log_brake_changes(BoardSim& b) {
  for (const BrakeChange& c : b.take_brake_changes()) {
    const BoardConfig* config = head_.board(b.address());
    const int joint = config ? config->joints[static_cast<std::size_t>(c.motor & 1)] : -1;
    const std::string who = "simulated board " + std::to_string(b.address()) + (config ? " (" + config->name + ")" : "") +
                            (joint >= 0 ? " " + head_.joints[static_cast<std::size_t>(joint)].name : "");
    log::info(bus_->name(), who + ": " + describe(c));
  }
}

bool SimulatedHead::in_bootloader(int address) {
  std::lock_guard<std::mutex> lock(mutex_);
  return board(address).in_bootloader();
}

std::uint16_t SimulatedHead::joint_encoder_magnet(int address, int axis) {
  std::lock_guard<std::mutex> lock(mutex_);
  return board(address).joint_encoder_magnet(axis);
}

void SimulatedHead::set_joint_encoder_fault(int address, int axis, JointEncoderFault fault) {
  std::lock_guard<std::mutex> lock(mutex_);
  board(address).set_joint_encoder_fault(axis, fault);
}

void SimulatedHead::set_stored_joint_zero(int address, int axis, std::optional<std::uint16_t> zero) {
  std::lock_guard<std::mutex> lock(mutex_);
  board(address).set_stored_joint_zero(axis, zero);
}

std::optional<std::uint16_t> SimulatedHead::stored_joint_zero(int address, int axis) {
  std::lock_guard<std::mutex> lock(mutex_);
  return board(address).stored_joint_zero(axis);
}

void SimulatedHead::set_backlash(int address, int motor, double degrees) {
  std::lock_guard<std::mutex> lock(mutex_);
  board(address).set_backlash(motor, degrees);
}

void SimulatedHead::set_joint_encoder_reversed(int address, int axis, bool reversed) {
  std::lock_guard<std::mutex> lock(mutex_);
  board(address).set_joint_encoder_reversed(axis, reversed);
}

double SimulatedHead::joint_degrees(int address, int motor) {
  std::lock_guard<std::mutex> lock(mutex_);
  return board(address).joint_degrees(motor);
}

void SimulatedHead::power_cycle(int address) {
  std::lock_guard<std::mutex> lock(mutex_);
  board(address).power_cycle();
}

void SimulatedHead::send(const Envelope& e) {
  try {
    bus_->send(encode(e), Millis(10));
  } catch (const Error& err) {
    log::warn(bus_->name(), std::string("simulated board could not send: ") + err.what());
  }
}

void SimulatedHead::take_commands() {
  for (int n = 0; n < 256; ++n) {  // bounded, so a flood cannot starve the control loop
    std::optional<Frame> f;
    try {
      f = bus_->receive(Millis(0));
    } catch (const BusError& e) {
      log::warn(bus_->name(), std::string("simulated head: ") + e.what());
      continue;
    }
    if (!f) return;
    Envelope e;
    try {
      e = decode(*f);
    } catch (const CodecError& err) {
      ++rejected_;
      log::debug(bus_->name(), std::string("simulated head ignores ") + err.what());
      continue;
    }
    if (message_kind(e.message) != MessageKind::request) continue;
    std::lock_guard<std::mutex> lock(mutex_);
    for (auto& b : boards_) {
      if (e.destination != b.address() && e.destination != kBroadcastAddress) continue;
      if (auto reply = b.handle(e)) send(*reply);
      log_brake_changes(b);
    }
  }
}

void SimulatedHead::loop() {
  using clock = std::chrono::steady_clock;
  const auto period = std::chrono::duration_cast<clock::duration>(std::chrono::duration<double>(period_s_));
  auto next = clock::now();
  std::vector<Envelope> out;
  while (running_) {
    take_commands();
    int steps = 0;
    const auto now = clock::now();
    while (next <= now && steps < kMaxCatchUpTicks) {
      out.clear();
      {
        std::lock_guard<std::mutex> lock(mutex_);
        const double t = static_cast<double>(ticks_ + 1) * period_s_;
        for (auto& b : boards_) {
          b.step(t, period_s_, out);
          log_brake_changes(b);
        }
      }
      ++ticks_;
      for (const auto& e : out) send(e);
      next += period;
      ++steps;
    }
    if (steps == kMaxCatchUpTicks) next = clock::now() + period;
    std::this_thread::sleep_until(next);
  }
}

}  // namespace robogene::can::sim
