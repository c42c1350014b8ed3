// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// The joints' absolute encoders (AS5048A, [GENERAL] joint_encoder_bits) seen from the host: each board
// homes such a joint itself at power-up from its encoder and the zero kept in its settings flash
// (docs/firmware.md "Joint encoders"). The zero is the raw angle the encoder reads with the joint at
// 0 deg; it is measured once on each built head (docs/fabricate.md "Homing") and stored with
// store_joint_encoder_zero. `robogene can-zero` runs both; the robogene_can driver reads the same.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "robogene/can/bus.hpp"
#include "robogene/can/head_config.hpp"

namespace robogene::can {

class BoardLink;

struct JointEncoderReading {
  std::string joint;
  // What the encoder is on: the joint itself, or on the eye board (coupled) a pan: eyes_version's axis
  // reads the left pan's (the encoder beside motor 0), eyes_vergence's the right pan's.
  std::string measures;
  std::string state;          // JointEncoderState: starting, ok, absent, failed
  std::uint16_t raw = 0;      // the last good raw angle
  std::uint16_t zero = 0;     // the stored zero (meaningful when zero_stored)
  bool zero_stored = false;
  bool homed = false;         // the board took the joint's position from it
  double raw_degrees = 0.0;   // raw x 360 / 2^bits
  // (raw - zero) in degrees, wrapped into the turn centred on the joint's range (a pan's: about 0), as
  // the board does; only with a stored zero.
  std::optional<double> joint_degrees;
};

// The joint's angle from a raw reading and a zero, as the firmware computes it.
// `middle`: the middle of the range the angle is wrapped about (a joint's; 0 for a pan).
double joint_encoder_degrees(int bits, double middle, std::uint16_t raw, std::uint16_t zero);

// Reads one joint's encoder through its board (get_joint_encoder). Throws robogene::Error for a joint
// without a joint encoder, or BusError when its board does not answer.
JointEncoderReading read_joint_encoder(BoardLink& link, const HeadConfig& head, const JointConfig& jc);
// Stores `zero` on the joint's board (set_joint_encoder_zero) and reads back: the board must report it
// stored and the joint homed. Throws robogene::Error naming the joint for a zero beyond the encoder's
// bits, a joint without an encoder, or a board that did not take it (the joint was running).
JointEncoderReading store_joint_encoder_zero(BoardLink& link, const HeadConfig& head, const JointConfig& jc,
                                             std::uint16_t zero);

// The same on a bus of its own, for `robogene can-zero`: `joints` by name (empty: every joint with a
// joint encoder). Throws robogene::Error naming an unknown joint or one without an encoder.
std::vector<JointEncoderReading> read_joint_encoders(std::unique_ptr<Bus> bus, const HeadConfig& head,
                                                     const std::vector<std::string>& joints);
// Stores each (joint, zero) given; a zero of nullopt takes the raw angle the encoder reads now (the
// joint held at its 0 deg pose). Returns the readings after storing.
std::vector<JointEncoderReading> store_joint_encoder_zeros(
    std::unique_ptr<Bus> bus, const HeadConfig& head,
    const std::vector<std::pair<std::string, std::optional<std::uint16_t>>>& zeros);

}  // namespace robogene::can
