// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// One simulated two-motor board: the firmware's control core (hardware/electronics/firmware/core,
// C) on a host HAL whose hardware is two DC motor models with their encoders and current sense.
// Everything a board decides (commands, replies, trajectories, position loops, current limits,
// faults, homing, broadcasts) is the firmware's own code; this class only turns envelopes into
// frames and back, and advances the motors by the PWM the core set.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "motor_control.hpp"
#include "robogene/can/head_config.hpp"
#include "robogene/can/sim/dc_motor.hpp"

namespace robogene::can::sim {

// A holding brake that applied or released, with the state of its motor's bridge at that moment: the
// order the firmware keeps (released only once the bridge has held for a period, applied while the
// bridge is still on) is visible here.
struct BrakeChange {
  std::uint64_t period = 0;         // control periods stepped before the change
  int motor = 0;
  bool released = false;            // false: applied
  bool bridge_on = false;           // the bridge was driving the motor
  std::uint32_t bridge_periods = 0; // whole periods it had been on
};

// What an axis's simulated AS5048A joint encoder does wrong (set_joint_encoder_fault).
enum class JointEncoderFault {
  none,
  missing,     // not fitted or unplugged: the board's pull-down reads 0x0000 on every frame
  bad_parity,  // frames damaged on the cable: one bit flipped
  error_flag   // the sensor reports an error in an earlier frame (sticky until power-off)
};

class BoardSim {
 public:
  // Throws robogene::Error when the board's configuration cannot be run by the firmware (a
  // coupling it does not implement). The board's application region of flash is kept in
  // `flash_path` when given (see SimFlash), else in memory; at first power-up it holds an image
  // stamped for this board (make_stamped_image: the simulator runs the control core natively, so
  // the image's code is filler). At power-up the board runs its application when that region
  // holds an image for it that checks (header and CRC), else its bootloader, as on the board.
  BoardSim(const HeadConfig& head, const BoardConfig& board, const MotorParameters& motor,
           const std::string& flash_path = {});
  ~BoardSim();
  BoardSim(BoardSim&&) noexcept;
  BoardSim& operator=(BoardSim&&) noexcept;

  int address() const;
  // Handles a command addressed to this board; returns the reply when the command has one.
  std::optional<Envelope> handle(const Envelope& command);
  // Advances one control period of dt seconds ending at `now`; appends due broadcasts to `out`.
  // dt must be the head's control period: the firmware counts its time in periods.
  void step(double now, double dt, std::vector<Envelope>& out);

  // For tests: the angle of motor m's gear output (motor / reduction, degrees: what its encoder sees), an
  // axis's measured counts and mode, and conditions of the board's hardware.
  double motor_degrees(int m) const;
  // The joint motor m drives (degrees), beyond the backlash: what its joint encoder reads. Without
  // backlash it is motor_degrees(m).
  double joint_degrees(int m) const;
  // A dead band of `degrees` at the joint between motor m's gear output and its joint (DcMotor): the
  // joint follows the output only when a flank pushes it. 0 (the default): none. Set now, the joint
  // is where the output is, in the middle of the gap. Throws for a negative width.
  void set_backlash(int m, double degrees);
  // Joint encoder `axis` mounted the other way round: it counts down as its joint turns up (its stored
  // zero still reads 0 deg at the joint's 0, as a lab would have measured it).
  void set_joint_encoder_reversed(int axis, bool reversed);
  std::int32_t measured_counts(int axis) const;
  ControlMode mode(int axis) const;
  void set_supply_voltage(double volts);
  // A power-on reset with the motors at these joint-side angles: the board counts from 0 there,
  // as a board without absolute encoders does until it homes; an axis with a joint encoder takes its
  // position from it at once.
  void power_up_at(double motor0_degrees, double motor1_degrees);
  // The AS5048A of an axis with a joint encoder (joint_encoder_bits in the configuration): the raw
  // angle it reads with the joint at 0 deg (its magnet is bonded at an arbitrary angle, fixed per
  // simulated board), and a fault to simulate from the next frame on. The board's settings flash holds
  // the matching zero from the start (a calibrated head); set_stored_joint_zero changes what it holds,
  // nullopt: none stored (an uncalibrated board), which the core reads at its next power-up.
  std::uint16_t joint_encoder_magnet(int axis) const;
  void set_joint_encoder_fault(int axis, JointEncoderFault fault);
  void set_stored_joint_zero(int axis, std::optional<std::uint16_t> zero);
  std::optional<std::uint16_t> stored_joint_zero(int axis) const;
  void set_bridge_fault(bool asserted);
  // The power-off holding brake of motor m: whether the motor has one (its axis's brake in the
  // configuration, on an uncoupled board), and whether it holds the motor now. It holds from
  // power-up, while the firmware keeps its gate applied, in the bootloader and without supply; a
  // motor it holds does not turn, whatever its bridge drives. take_brake_changes returns the changes
  // since the last call, oldest first.
  bool has_brake(int m) const;
  bool brake_holding(int m) const;
  std::vector<BrakeChange> take_brake_changes();
  // The bootloader runs (after enter_bootloader, or at power-up without a valid image).
  bool in_bootloader() const;
  // A power cycle: the reset path of the bootloader decides what runs.
  void power_cycle();

  struct Model;

 private:
  std::unique_ptr<Model> model_;  // the core keeps pointers into it: its address must not move
};

}  // namespace robogene::can::sim
