// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// A control core on a fake HAL for its unit tests: two motors as first-order plants in encoder
// counts (speed follows duty, current follows duty minus back-EMF, a hard stop where asked),
// settable supply, bridge fault and forced currents, the frames each joint encoder answers (none set:
// 0x0000, a missing encoder's pulled-down line), and the frames the core sent.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstring>
#include <functional>
#include <optional>
#include <vector>

#include "rg_board.h"
#include "generated/robogene_can_motor_control.h"

namespace rg_test {

struct Plant {
  double counts = 0.0, speed = 0.0;  // counts, counts/s
  double duty = 0.0;                 // -1..1
  bool enabled = false;
  double no_load_speed = 200000.0;   // counts/s at full duty
  double stall_current_ma = 6000.0;  // at full duty, standing still
  double time_constant = 0.02;       // s
  std::optional<double> stop_low, stop_high;
  std::optional<std::int32_t> forced_current_ma;

  double current_ma() const {
    if (forced_current_ma) return *forced_current_ma;
    return stall_current_ma * (duty - speed / no_load_speed);
  }
  void step(double dt) {
    speed += (duty * no_load_speed - speed) * std::min(1.0, dt / time_constant);
    counts += speed * dt;
    if (stop_low && counts < *stop_low) counts = *stop_low, speed = 0.0;
    if (stop_high && counts > *stop_high) counts = *stop_high, speed = 0.0;
  }
};

// One call of the HAL's bridge and brake outputs, in the order the core made them.
struct OutputCall {
  enum Kind { kBridge, kBrake } kind;
  unsigned motor;
  bool on;  // bridge enabled, brake released
};

struct FakeBoard {
  rg_board_t core{};
  rg_hal_t hal{};
  rg_board_params_t params{};
  Plant plant[2];
  std::uint32_t supply = 12000;
  bool fault = false;
  std::vector<rg_can_frame_t> sent;
  std::vector<int> saved_addresses;
  int bootloader_requests = 0;
  bool brake_released[2] = {false, false};  // the brake pins' level as the core last set it (low after reset)
  int brake_writes[2] = {0, 0};
  std::vector<OutputCall> outputs;
  // What axis 0's or 1's joint encoder answers to each SPI frame; frames read, per axis.
  std::function<std::uint16_t(unsigned)> joint_frames;
  int joint_frames_read[2] = {0, 0};
  std::vector<std::pair<unsigned, std::uint16_t>> saved_zeros;

  static FakeBoard& of(void* ctx) { return *static_cast<FakeBoard*>(ctx); }

  // A board at address 1 with two identical axes, uncoupled unless told.
  explicit FakeBoard(std::uint8_t coupling = RG_COUPLING_NONE) {
    params.address = 1;
    params.coupling = coupling;
    params.counts_m2a[0][0] = params.counts_m2a[1][1] = 1;
    if (coupling == RG_COUPLING_VERSION_VERGENCE) {
      params.counts_m2a[0][1] = 1;
      params.counts_m2a[1][0] = 1;
      params.counts_m2a[1][1] = -1;
    }
    params.pwm_full_scale = 1000;
    params.control_period_us = 1000;
    params.velocity_timeout_ms = 100;
    params.protocol_major = 1;
    params.protocol_minor = 0;
    params.broadcast_policy = 0;
    for (auto& a : params.axes) {
      a.present = true;
      a.min_position = -20000;
      a.max_position = 20000;
      a.max_speed = 50000;
      a.current_limit_ma = 1000;
      a.pid = rg_pid_gains_t{100, 1, 1000, 8, 0, 900, 300};
    }
    hal.ctx = this;
    hal.encoder_raw = [](void* c, unsigned m) {
      return static_cast<std::uint16_t>(static_cast<std::int64_t>(std::llround(of(c).plant[m].counts)) & 0xFFFF);
    };
    hal.current_ma = [](void* c, unsigned m) { return static_cast<std::int32_t>(std::lround(of(c).plant[m].current_ma())); };
    hal.supply_mv = [](void* c) { return of(c).supply; };
    hal.bridge_fault = [](void* c) { return of(c).fault; };
    hal.set_pwm = [](void* c, unsigned m, std::int32_t duty, bool enabled) {
      of(c).plant[m].duty = enabled ? duty / 1000.0 : 0.0;
      of(c).plant[m].enabled = enabled;
      of(c).outputs.push_back({OutputCall::kBridge, m, enabled});
    };
    hal.set_brake = [](void* c, unsigned m, bool released) {
      of(c).brake_released[m] = released;
      ++of(c).brake_writes[m];
      of(c).outputs.push_back({OutputCall::kBrake, m, released});
    };
    hal.can_send = [](void* c, const rg_can_frame_t* f) {
      of(c).sent.push_back(*f);
      return true;
    };
    hal.save_address = [](void* c, std::uint8_t a) { of(c).saved_addresses.push_back(a); };
    hal.enter_bootloader = [](void* c) { ++of(c).bootloader_requests; };
    hal.joint_encoder_frame = [](void* c, unsigned axis) -> std::uint16_t {
      ++of(c).joint_frames_read[axis];
      return of(c).joint_frames ? of(c).joint_frames(axis) : 0u;
    };
    hal.save_joint_zero = [](void* c, unsigned axis, std::uint16_t zero) { of(c).saved_zeros.emplace_back(axis, zero); };
  }
  FakeBoard(const FakeBoard&) = delete;

  void start() { rg_board_init(&core, &params, &hal); }

  // Sends a host command; returns the reply, if any.
  std::optional<rg_can_frame_t> command(std::vector<std::uint8_t> bytes, unsigned axis = 0, unsigned dst = 1,
                                        unsigned message_class = ROBOGENE_CAN_CLASS_POLLING_MOTOR_CONTROL) {
    rg_can_frame_t f{};
    f.id = static_cast<std::uint16_t>(ROBOGENE_CAN_ID(message_class, 0, dst));
    f.len = static_cast<std::uint8_t>(bytes.size());
    std::memcpy(f.data, bytes.data(), bytes.size());
    if (axis) f.data[0] |= ROBOGENE_CAN_AXIS_BIT;
    sent.clear();
    rg_board_receive(&core, &f);
    if (sent.empty()) return std::nullopt;
    return sent.front();
  }
  void run(double seconds) {
    const int ticks = static_cast<int>(std::lround(seconds * 1000));
    for (int i = 0; i < ticks; ++i) {
      rg_board_tick(&core);
      for (auto& p : plant) p.step(0.001);
    }
  }
  std::uint8_t mode(unsigned axis) const { return core.axes[axis].mode; }
};

inline std::vector<std::uint8_t> le32(std::uint8_t code, std::int32_t v) {
  return {code, static_cast<std::uint8_t>(v), static_cast<std::uint8_t>(v >> 8), static_cast<std::uint8_t>(v >> 16),
          static_cast<std::uint8_t>(v >> 24)};
}
inline std::vector<std::uint8_t> position_move(std::int32_t position, std::int16_t speed_raw) {
  auto b = le32(ROBOGENE_CAN_CMD_POSITION_MOVE, position);
  b.push_back(static_cast<std::uint8_t>(speed_raw));
  b.push_back(static_cast<std::uint8_t>(speed_raw >> 8));
  return b;
}

}  // namespace rg_test
