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
  bool hard_stops = false;          // the joint stops at [stop_min, stop_max] degrees
  double stop_min = 0.0, stop_max = 0.0;
};

class DcMotor {
 public:
  explicit DcMotor(const MotorParameters& p = {}) : p_(p) {}

  // Applies duty (-1..1) for dt seconds.
  void step(double duty, double dt) {
    duty = std::clamp(duty, -1.0, 1.0);
    const double inertia = p_.rotor_inertia + p_.load_inertia / (p_.gear_ratio * p_.gear_ratio);
    constexpr int kSubSteps = 10;
    const double h = dt / kSubSteps;
    for (int i = 0; i < kSubSteps; ++i) {
      const double volts = duty * p_.supply_voltage;
      current_ = std::clamp((volts - p_.torque_constant * speed_) / p_.resistance, -p_.bridge_current_limit,
                            p_.bridge_current_limit);
      if (braked_) continue;
      const double torque = p_.torque_constant * current_ - p_.viscous_friction * speed_;
      speed_ += torque / inertia * h;
      angle_ += speed_ * h;
      if (p_.hard_stops) hold_at_stops();
    }
  }

  double joint_degrees() const { return angle_ / p_.gear_ratio * 180.0 / M_PI; }
  double joint_degrees_per_second() const { return speed_ / p_.gear_ratio * 180.0 / M_PI; }
  double current_amps() const { return current_; }
  void set_joint_degrees(double deg) { angle_ = deg * M_PI / 180.0 * p_.gear_ratio; }
  // Applies (true) or releases (false) the holding brake; a motor without one is never braked.
  void set_braked(bool braked) {
    braked_ = braked;
    if (braked_) speed_ = 0.0;
  }
  bool braked() const { return braked_; }
  const MotorParameters& parameters() const { return p_; }

 private:
  void hold_at_stops() {
    const double lo = p_.stop_min * M_PI / 180.0 * p_.gear_ratio, hi = p_.stop_max * M_PI / 180.0 * p_.gear_ratio;
    if (angle_ < lo || angle_ > hi) {
      angle_ = std::clamp(angle_, lo, hi);
      speed_ = 0.0;
    }
  }

  MotorParameters p_;
  double angle_ = 0.0;  // rad at the motor
  double speed_ = 0.0;  // rad/s at the motor
  double current_ = 0.0;
  bool braked_ = false;
};

}  // namespace robogene::can::sim
