// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "robogene/can/sim/board_sim.hpp"

#include <cmath>
#include <cstring>
#include <string>

#include "core_params.hpp"
#include "rg_board.h"
#include "robogene/error.hpp"

namespace robogene::can::sim {

// The core and the hardware it runs on: two motors, their encoders, current sense, the supply,
// the bridges' fault line and the CAN transmit queue.
struct BoardSim::Model {
  rg_board_t core{};
  rg_hal_t hal{};
  std::array<DcMotor, 2> motors;
  std::array<double, 2> motor_counts_per_degree{{1.0, 1.0}};
  std::array<double, 2> duty{{0.0, 0.0}};
  rg_board_params_t params{};  // kept for a simulated power-up
  double pwm_full_scale = 1.0;
  double supply_volts = 12.0;
  bool bridge_fault = false;
  std::vector<rg_can_frame_t> sent;
};

namespace {

using Model = BoardSim::Model;

Model& model_of(void* ctx) { return *static_cast<Model*>(ctx); }

std::uint16_t encoder_raw(void* ctx, unsigned m) {
  const Model& s = model_of(ctx);
  const double counts = std::round(s.motors[m].joint_degrees() * s.motor_counts_per_degree[m]);
  // The timer's 16-bit counter: the core extends it, as on the board.
  return static_cast<std::uint16_t>(static_cast<std::int64_t>(counts) & 0xFFFF);
}

std::int32_t current_ma(void* ctx, unsigned m) {
  return static_cast<std::int32_t>(std::lround(model_of(ctx).motors[m].current_amps() * 1000.0));
}

std::uint32_t supply_mv(void* ctx) {
  return static_cast<std::uint32_t>(std::lround(std::max(0.0, model_of(ctx).supply_volts) * 1000.0));
}

bool bridge_fault(void* ctx) { return model_of(ctx).bridge_fault; }

void set_pwm(void* ctx, unsigned m, std::int32_t duty, bool enabled) {
  Model& s = model_of(ctx);
  s.duty[m] = enabled ? duty / s.pwm_full_scale : 0.0;
}

bool can_send(void* ctx, const rg_can_frame_t* f) {
  model_of(ctx).sent.push_back(*f);
  return true;
}

rg_can_frame_t to_core(const Frame& f) {
  rg_can_frame_t c{};
  c.id = static_cast<std::uint16_t>(f.id);
  c.len = f.len;
  std::memcpy(c.data, f.data.data(), f.len);
  return c;
}

Frame from_core(const rg_can_frame_t& c) {
  Frame f;
  f.id = c.id;
  f.len = c.len;
  std::memcpy(f.data.data(), c.data, c.len);
  return f;
}

// The hard stop a homing joint runs into, on its homing side, as the motor model's limit; the
// eye board's version homes both eyes: left = version + vergence / 2, right = version - vergence / 2.
void place_stop(MotorParameters& mp, int direction, double motor_stop_degrees) {
  if (direction == 0) return;
  mp.hard_stops = true;
  mp.stop_min = direction > 0 ? -1e9 : motor_stop_degrees;
  mp.stop_max = direction > 0 ? motor_stop_degrees : 1e9;
}

}  // namespace

BoardSim::BoardSim(const HeadConfig& head, const BoardConfig& board, const MotorParameters& motor)
    : model_(std::make_unique<Model>()) {
  Model& s = *model_;
  const rg_board_params_t p = core_params(head, board);
  for (std::size_t i = 0; i < 2; ++i) {
    MotorParameters mp = motor;
    const int j = board.joints[i];
    if (j >= 0) {
      const JointConfig& jc = head.joints[static_cast<std::size_t>(j)];
      mp.gear_ratio = jc.gear_ratio;
      s.motor_counts_per_degree[i] = motor_counts_per_degree(head, board, i);
      if (board.coupling) {
        const HomingConfig& version = head.joints[static_cast<std::size_t>(board.joints[0])].homing;
        const double vergence_stop = board.joints[1] >= 0 ? head.joints[static_cast<std::size_t>(board.joints[1])].homing.stop : 0.0;
        place_stop(mp, version.direction, version.stop + (i == 0 ? 0.5 : -0.5) * vergence_stop);
      } else {
        place_stop(mp, jc.homing.direction, jc.homing.stop);
      }
    }
    s.motors[i] = DcMotor(mp);
  }
  s.pwm_full_scale = head.pwm_full_scale;
  s.hal = rg_hal_t{&s, encoder_raw, current_ma, supply_mv, bridge_fault, set_pwm, can_send, nullptr, nullptr};
  s.params = p;
  rg_board_init(&s.core, &s.params, &s.hal);
}

void BoardSim::power_up_at(double motor0_degrees, double motor1_degrees) {
  Model& s = *model_;
  s.motors[0].set_joint_degrees(motor0_degrees);
  s.motors[1].set_joint_degrees(motor1_degrees);
  s.duty = {0.0, 0.0};
  rg_board_init(&s.core, &s.params, &s.hal);
}

BoardSim::~BoardSim() = default;
BoardSim::BoardSim(BoardSim&&) noexcept = default;
BoardSim& BoardSim::operator=(BoardSim&&) noexcept = default;

int BoardSim::address() const { return model_->core.address; }

std::optional<Envelope> BoardSim::handle(const Envelope& command) {
  Model& s = *model_;
  s.sent.clear();
  const rg_can_frame_t in = to_core(encode(command));
  rg_board_receive(&s.core, &in);
  if (s.sent.empty()) return std::nullopt;
  return decode(from_core(s.sent.front()));  // a command has at most one reply
}

void BoardSim::step(double /*now*/, double dt, std::vector<Envelope>& out) {
  Model& s = *model_;
  s.sent.clear();
  rg_board_tick(&s.core);
  for (std::size_t m = 0; m < 2; ++m) s.motors[m].step(s.duty[m], dt);
  for (const auto& f : s.sent) out.push_back(decode(from_core(f)));
}

double BoardSim::motor_degrees(int m) const { return model_->motors[static_cast<std::size_t>(m)].joint_degrees(); }
std::int32_t BoardSim::measured_counts(int axis) const { return model_->core.axes[axis & 1].measured; }
ControlMode BoardSim::mode(int axis) const { return static_cast<ControlMode>(model_->core.axes[axis & 1].mode); }
void BoardSim::set_supply_voltage(double volts) { model_->supply_volts = volts; }
void BoardSim::set_bridge_fault(bool asserted) { model_->bridge_fault = asserted; }

}  // namespace robogene::can::sim
