// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// SimulatedHead: every board of a head configuration on one bus, as firmware would run them.
// A thread runs the 1 kHz control loop in real time: it takes the host's commands off the bus,
// lets the addressed board answer, steps every board and sends their broadcasts. A late tick is
// caught up (the model always advances in whole control periods), so simulated time keeps pace
// with the wall clock on a busy machine.
#pragma once

#include <atomic>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "robogene/can/bus.hpp"
#include "robogene/can/head_config.hpp"
#include "robogene/can/sim/board_sim.hpp"

namespace robogene::can::sim {

class SimulatedHead {
 public:
  // Starts the control loop at once. With a `flash_dir`, each board keeps its application region
  // of flash in <flash_dir>/board-<address>-<name>.flash across runs (BoardSim, SimFlash).
  SimulatedHead(const HeadConfig& head, std::unique_ptr<Bus> bus, const MotorParameters& motor = {},
                const std::string& flash_dir = {});
  ~SimulatedHead();
  SimulatedHead(const SimulatedHead&) = delete;
  SimulatedHead& operator=(const SimulatedHead&) = delete;

  void stop();
  // For tests and tools: the joint-side angle of a board's motor m, its axis's counts, its mode.
  double motor_degrees(int board, int motor);
  std::int32_t measured_counts(int board, int axis);
  // A power-on reset of one board with its motors at these joint-side angles (BoardSim::power_up_at).
  void power_up_at(int board, double motor0_degrees, double motor1_degrees);
  // Whether a board runs its bootloader, and a power cycle of it (BoardSim::power_cycle).
  bool in_bootloader(int board);
  void power_cycle(int board);
  // Whether a board's motor m has a holding brake, and whether it holds now (BoardSim::brake_holding).
  // Each change is logged at info level, naming the board and the joint.
  bool has_brake(int board, int motor);
  bool brake_holding(int board, int motor);
  // A board's joint encoders (BoardSim::joint_encoder_magnet, set_joint_encoder_fault,
  // set_stored_joint_zero): faults apply from the next frame, a stored zero at the next power-up.
  std::uint16_t joint_encoder_magnet(int board, int axis);
  void set_joint_encoder_fault(int board, int axis, JointEncoderFault fault);
  void set_stored_joint_zero(int board, int axis, std::optional<std::uint16_t> zero);
  std::optional<std::uint16_t> stored_joint_zero(int board, int axis);
  // Backlash between a board's motor and its joint, a joint encoder mounted reversed, and the joint's
  // angle beyond the backlash (BoardSim::set_backlash, set_joint_encoder_reversed, joint_degrees).
  void set_backlash(int board, int motor, double degrees);
  void set_joint_encoder_reversed(int board, int axis, bool reversed);
  double joint_degrees(int board, int motor);
  // Control periods run so far, and how many frames were not commands the boards understood.
  std::uint64_t ticks() const { return ticks_; }
  std::uint64_t rejected_frames() const { return rejected_; }

 private:
  void loop();
  void take_commands();
  void send(const Envelope& e);
  void log_brake_changes(BoardSim& b);
  BoardSim& board(int address);

  std::unique_ptr<Bus> bus_;
  HeadConfig head_;
  double period_s_;
  std::mutex mutex_;
  std::vector<BoardSim> boards_;
  std::atomic<bool> running_{true};
  std::atomic<std::uint64_t> ticks_{0}, rejected_{0};
  std::thread thread_;
};

}  // namespace robogene::can::sim
