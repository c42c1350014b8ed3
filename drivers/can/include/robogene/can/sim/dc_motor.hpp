// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// A brushed DC motor behind a gearbox, driven by an H-bridge's PWM. The electrical time constant
// (L/R, tens of microseconds) is far below the 1 ms control period, so current follows voltage
// at once: i = (V - ke w) / R, cut at the bridge's own overcurrent limit (the board's firmware
// limits it lower, per axis). The mechanics integrate J dw/dt = kt i - b w in sub-steps; a joint
// with hard stops is held at them (an inelastic stop). A holding brake, while applied, stops and
// locks the motor's shaft: an ideal brake, it holds whatever the bridge drives (the current then
// flows as at stall). Defaults: a 12 V Faulhaber 2342-class motor (R 1.9 ohm, kt 13.4 mNm/A,
// rotor 5.6 g cm^2) and a load of 5e-3 kg m^2 at the joint.
//
// Backlash (a gearhead's play, a stretched belt): a dead band of `backlash` degrees between the gear's
// output (motor angle / reduction) and the joint. The joint follows the output only while the output
// pushes on a flank (|output - joint| > backlash / 2); inside the gap friction holds it where it is,
// and the motor turns its rotor alone. Meeting a flank is an inelastic impact: the rotor's momentum is
// shared with the load. The hard stops are the joint's; the output may turn half the gap beyond them.
#pragma once

#include <algorithm>
#include <cmath>

namespace robogene::can::sim {

struct MotorParameters {
  double supply_voltage = 12.0;     // V
  double resistance = 1.9;          // ohm
  double torque_constant = 0.0134;  // Nm/A, also the back-EMF constant in V s/rad
  double rotor_inertia = 5.6e-7;    // kg m^2
  double load_inertia = 5e-3;       // kg m^2 at the joint
  double viscous_friction = 2e-6;   // Nm s/rad at the motor
  double gear_ratio = 100.0;        // motor turns per joint turn
  double bridge_current_limit = 3.6;  // A, the DRV8872's overcurrent protection
  double backlash = 0.0;            // deg at the joint, between the gear's output and the joint
  bool hard_stops = false;          // the joint stops at [stop_min, stop_max] degrees
  double stop_min = 0.0, stop_max = 0.0;
};

class DcMotor {
 public:
  explicit DcMotor(const MotorParameters& p = {}) : p_(p) {}

  // Applies duty (-1..1) for dt seconds.
  void step(double duty, double dt) {
    duty = std::clamp(duty, -1.0, 1.0);
    const double load = p_.load_inertia / (p_.gear_ratio * p_.gear_ratio);
    constexpr int kSubSteps = 10;
    const double h = dt / kSubSteps;
    for (int i = 0; i < kSubSteps; ++i) {
      const double volts = duty * p_.supply_voltage;
      current_ = std::clamp((volts - p_.torque_constant * speed_) / p_.resistance, -p_.bridge_current_limit,
                            p_.bridge_current_limit);
      if (braked_) continue;
      // Without backlash the load always rides on the rotor; with it, only while a flank drives it.
      const bool driving = p_.backlash <= 0.0 || contact_ * speed_ > 0.0;
      const double inertia = p_.rotor_inertia + (driving ? load : 0.0);
      const double torque = p_.torque_constant * current_ - p_.viscous_friction * speed_;
      speed_ += torque / inertia * h;
      angle_ += speed_ * h;
      follow_output(load);
      if (p_.hard_stops) hold_at_stops();
    }
  }

  // The gear's output, motor angle / reduction: what the motor encoder sees, in joint degrees.
  double output_degrees() const { return angle_ / p_.gear_ratio * 180.0 / M_PI; }
  // The joint (the load side of the backlash): what a joint encoder sees.
  double joint_degrees() const { return p_.backlash > 0.0 ? joint_ : output_degrees(); }
  // The gear output's speed (the joint's too, but inside a backlash gap, where the joint stands still).
  double joint_degrees_per_second() const { return speed_ / p_.gear_ratio * 180.0 / M_PI; }
  double current_amps() const { return current_; }
  // Puts output and joint at `deg`, the output in the middle of the gap.
  void set_joint_degrees(double deg) {
    angle_ = deg * M_PI / 180.0 * p_.gear_ratio;
    joint_ = deg;
    contact_ = 0;
  }
  // A new width of the backlash (deg): the joint where the output is, in the middle of the gap.
  void set_backlash(double degrees) {
    p_.backlash = degrees;
    joint_ = output_degrees();
    contact_ = 0;
  }
  // Applies (true) or releases (false) the holding brake; a motor without one is never braked.
  void set_braked(bool braked) {
    braked_ = braked;
    if (braked_) speed_ = 0.0;
  }
  bool braked() const { return braked_; }
  const MotorParameters& parameters() const { return p_; }

 private:
  // The joint taken along by whichever flank the output pushes on; on meeting a flank the rotor shares
  // its momentum with the load.
  void follow_output(double load) {
    if (p_.backlash <= 0.0) return;
    const double half = 0.5 * p_.backlash, gap = output_degrees() - joint_;
    const int contact = gap > half ? 1 : (gap < -half ? -1 : 0);
    if (contact != 0) {
      if (contact_ != contact) speed_ *= p_.rotor_inertia / (p_.rotor_inertia + load);
      joint_ = output_degrees() - contact * half;
    }
    contact_ = contact;
  }

  // The stops hold the joint; the output may go on by half the gap, to the far flank.
  void hold_at_stops() {
    const double half = p_.backlash > 0.0 ? 0.5 * p_.backlash : 0.0;
    const double joint = joint_degrees();
    if (joint >= p_.stop_min && joint <= p_.stop_max) return;
    const double stop = std::clamp(joint, p_.stop_min, p_.stop_max);
    if (p_.backlash > 0.0) joint_ = stop;
    const double out = std::clamp(output_degrees(), stop - half, stop + half);
    angle_ = out * M_PI / 180.0 * p_.gear_ratio;
    speed_ = 0.0;
  }

  MotorParameters p_;
  double angle_ = 0.0;  // rad at the motor
  double joint_ = 0.0;  // deg, the joint behind the backlash (used only with backlash)
  int contact_ = 0;     // the flank the output pushes on: +1 driving the joint up, -1 down, 0 in the gap
  double speed_ = 0.0;  // rad/s at the motor
  double current_ = 0.0;
  bool braked_ = false;
};

}  // namespace robogene::can::sim
