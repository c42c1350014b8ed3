// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// The head's simulated boards stepped by hand (no bus, no wall clock), commanded through the codec
// both ways as on the bus: deterministic, for the simulator's tests.
#pragma once

#include <cmath>
#include <optional>
#include <utility>
#include <vector>

#include "head_config_fixture.hpp"
#include "robogene/can/sim/board_sim.hpp"
#include "robogene/error.hpp"

namespace robogene::can::testing {

// Every board of the generated head.ini, at power-up, with the head's broadcast policy set.
struct Rig {
  HeadConfig head;
  std::vector<sim::BoardSim> boards;
  double t = 0.0;
  std::vector<Envelope> broadcasts;

  // `config`: the head to simulate, by default the generated head.ini's (an edited copy for a variant).
  explicit Rig(HeadConfig config = head_config()) : head(std::move(config)) {
    for (const auto& b : head.boards) boards.emplace_back(head, b, sim::MotorParameters{});
    for (const auto& b : head.boards) {
      for (int axis = 0; axis < 2; ++axis) {
        send(b.address, axis, SetBroadcastPolicy{head.broadcast_policy});
      }
    }
  }
  sim::BoardSim& board_of(int joint) {
    const int address = head.joints[static_cast<std::size_t>(joint)].board;
    for (auto& b : boards) {
      if (b.address() == address) return b;
    }
    throw Error("no board");
  }
  std::optional<Envelope> send(int address, int axis, Message m) {
    // Through the codec both ways, as on the bus.
    const Envelope e = decode(encode(Envelope{kHostAddress, static_cast<std::uint8_t>(address), static_cast<std::uint8_t>(axis), m}));
    for (auto& b : boards) {
      if (b.address() == address) {
        auto r = b.handle(e);
        if (r) return decode(encode(*r));
      }
    }
    return std::nullopt;
  }
  std::optional<Envelope> to_joint(int joint, Message m) {
    const JointConfig& j = head.joints[static_cast<std::size_t>(joint)];
    return send(j.board, j.axis, std::move(m));
  }
  void run(double seconds) {
    const int ticks = static_cast<int>(std::lround(seconds * 1000));
    for (int i = 0; i < ticks; ++i) {
      t += 0.001;
      for (auto& b : boards) b.step(t, 0.001, broadcasts);
    }
  }
  // The joint's true angle (beyond any backlash), from the simulated hardware.
  double true_degrees(int joint) {
    const JointConfig& j = head.joints[static_cast<std::size_t>(joint)];
    return board_of(joint).joint_degrees(j.axis);
  }
  double degrees(int joint) {
    const JointConfig& j = head.joints[static_cast<std::size_t>(joint)];
    return board_of(joint).measured_counts(j.axis) / j.counts_per_degree;
  }
};

}  // namespace robogene::can::testing
