// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "axis_motion.hpp"

#include <algorithm>
#include <cmath>

namespace robogene::dev {
namespace {
constexpr double kMaxStep = 1e-3;  // seconds
constexpr double kDegPerRad = 57.29577951308232;  // 180 / pi
}  // namespace

void AxisMotion::step(double dt) {
  while (dt > 0.0) {
    const double h = std::min(dt, kMaxStep);
    substep(h);
    dt -= h;
  }
}

void AxisMotion::torque_substep(double h) {
  // J dw/dt = t - b w has w(h) = w_end + (w0 - w_end) e^(-h b/J), w_end = t / b; positions in degrees.
  const double k = damping_ / inertia_;
  const double w_end = kDegPerRad * ref_torque_ / damping_;
  const double decay = std::exp(-k * h);
  const double w0 = velocity_;
  velocity_ = w_end + (w0 - w_end) * decay;
  position_ += w_end * h + (w0 - w_end) * (1.0 - decay) / k;
  acceleration_ = kDegPerRad * ref_torque_ / inertia_ - k * velocity_;
}

void AxisMotion::substep(double h) {
  if (goal_ == Goal::Idle) return;
  if (goal_ == Goal::Torque) {
    torque_substep(h);
    return;
  }
  const double a = ref_acceleration_;
  double wanted = ref_velocity_;
  const double error = target_ - position_;
  if (goal_ == Goal::Position) {
    if (error == 0.0 && velocity_ == 0.0) {
      acceleration_ = 0.0;
      return;
    }
    // The fastest speed v1 to end this step with such that braking at `a` from there still
    // stops at the target: v1^2 = 2a (|error| - distance covered this step), the distance being
    // (v0 + v1) h / 2. Solving for the end of the step (not its start) avoids braking late.
    const double v0 = std::copysign(1.0, error) * velocity_;
    const double left = std::fabs(error) - 0.5 * v0 * h;
    const double braking =
        left > 0.0 ? 0.5 * (-a * h + std::sqrt(a * a * h * h + 8.0 * a * left)) : 0.0;
    wanted = std::copysign(std::min(ref_speed_, braking), error);
  }
  const double dv = std::clamp(wanted - velocity_, -a * h, a * h);
  const double v0 = velocity_;
  velocity_ += dv;
  acceleration_ = dv / h;
  position_ += 0.5 * (v0 + velocity_) * h;
  if (goal_ == Goal::Position) {
    const double after = target_ - position_;
    const bool crossed = (after == 0.0) || (std::signbit(after) != std::signbit(error));
    // Arriving slowly (within one step's worth of braking) means arrived; a fast crossing is an
    // overshoot that the next steps correct.
    if (crossed && std::fabs(velocity_) <= 2.0 * a * h) {
      position_ = target_;
      velocity_ = 0.0;
    }
  }
}

void AxisMotion::stop() {
  if (goal_ == Goal::Position) {
    // Brake at the reference acceleration: the axis comes to rest v^2 / 2a further on.
    target_ = position_ + velocity_ * std::fabs(velocity_) / (2.0 * ref_acceleration_);
  } else if (goal_ == Goal::Velocity) {
    ref_velocity_ = 0.0;
  } else if (goal_ == Goal::Torque) {
    ref_torque_ = 0.0;  // the damping brings the axis to rest
  }
}

double AxisMotion::torque() const {
  if (goal_ == Goal::Torque) return ref_torque_;
  return (inertia_ * acceleration_ + damping_ * velocity_) / kDegPerRad;
}

void AxisMotion::set_position(double p) {
  target_ += p - position_;
  position_ = p;
}

bool AxisMotion::done() const {
  if (velocity_ != 0.0) return false;
  return goal_ != Goal::Position || position_ == target_;
}

}  // namespace robogene::dev
