// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "robogene/can/joint_encoders.hpp"

#include <chrono>
#include <cmath>
#include <thread>

#include "board_link.hpp"
#include "robogene/error.hpp"

namespace robogene::can {
namespace {

const JointConfig& with_encoder(const HeadConfig& head, const std::string& name) {
  std::string known;
  const JointConfig* found = nullptr;
  for (const auto& jc : head.joints) {
    if (jc.joint_encoder_bits > 0) known += (known.empty() ? "" : ", ") + jc.name;
    if (jc.name == name) found = &jc;
  }
  if (!found) throw Error("no joint '" + name + "' in " + head.source);
  if (found->joint_encoder_bits == 0) {
    throw Error("joint '" + name + "' has no joint encoder ([GENERAL] joint_encoder_bits 0); the joints with one: " +
                (known.empty() ? "none" : known));
  }
  return *found;
}

void require_encoder(const JointConfig& jc) {
  if (jc.joint_encoder_bits == 0) throw Error("joint '" + jc.name + "' has no joint encoder ([GENERAL] joint_encoder_bits 0)");
}

}  // namespace

double joint_encoder_degrees(int bits, double middle, std::uint16_t raw, std::uint16_t zero) {
  const double modulus = std::ldexp(1.0, bits);
  const double steps = std::fmod(raw - static_cast<double>(zero) + modulus, modulus);
  double delta = std::fmod(steps * 360.0 / modulus - middle, 360.0);
  if (delta < -180.0) delta += 360.0;
  if (delta >= 180.0) delta -= 360.0;
  return middle + delta;
}

JointEncoderReading read_joint_encoder(BoardLink& link, const HeadConfig& head, const JointConfig& jc) {
  require_encoder(jc);
  const auto r = std::get<GetJointEncoderReply>(link.request(jc.board, jc.axis, GetJointEncoder{}).message);
  const BoardConfig* board = head.board(jc.board);
  const bool pan = board && board->coupling;
  JointEncoderReading out;
  out.joint = jc.name;
  out.measures = pan ? board->coupling->motors[static_cast<std::size_t>(jc.axis)] : jc.name;
  out.state = to_string(r.state);
  out.raw = r.raw_angle;
  out.zero = r.zero;
  out.zero_stored = r.zero_stored;
  out.homed = r.homed;
  out.raw_degrees = r.raw_angle * 360.0 / std::ldexp(1.0, jc.joint_encoder_bits);
  if (r.zero_stored) {
    out.joint_degrees = joint_encoder_degrees(jc.joint_encoder_bits, pan ? 0.0 : 0.5 * (jc.min + jc.max), r.raw_angle, r.zero);
  }
  return out;
}

JointEncoderReading store_joint_encoder_zero(BoardLink& link, const HeadConfig& head, const JointConfig& jc,
                                             std::uint16_t zero) {
  require_encoder(jc);
  const long limit = 1L << jc.joint_encoder_bits;
  if (zero >= limit) {
    throw Error("joint '" + jc.name + "': zero " + std::to_string(zero) + " is beyond its " + std::to_string(jc.joint_encoder_bits) +
                "-bit encoder (0.." + std::to_string(limit - 1) + ")");
  }
  link.send(jc.board, jc.axis, SetJointEncoderZero{zero});
  const JointEncoderReading r = read_joint_encoder(link, head, jc);
  if (!r.zero_stored || r.zero != zero) {
    throw Error("joint '" + jc.name + "': board " + std::to_string(jc.board) +
                " did not take the zero (a running joint keeps its zero: stop it, set control mode idle, and store again)");
  }
  if (!r.homed) {
    throw Error("joint '" + jc.name + "': zero " + std::to_string(zero) + " stored, but the board did not home the joint from it (encoder " +
                r.state + (r.joint_degrees ? ", the angle it gives, " + std::to_string(*r.joint_degrees) +
                                                 " deg, lies outside the joint's range" : std::string()) + ")");
  }
  return r;
}

std::vector<JointEncoderReading> read_joint_encoders(std::unique_ptr<Bus> bus, const HeadConfig& head,
                                                     const std::vector<std::string>& joints) {
  std::vector<const JointConfig*> chosen;
  if (joints.empty()) {
    for (const auto& jc : head.joints) {
      if (jc.joint_encoder_bits > 0) chosen.push_back(&jc);
    }
    if (chosen.empty()) throw Error(head.source + ": no joint has a joint encoder ([GENERAL] joint_encoder_bits)");
  } else {
    for (const auto& name : joints) chosen.push_back(&with_encoder(head, name));
  }
  BoardLink link(std::move(bus), Millis(head.reply_timeout_ms));
  std::vector<JointEncoderReading> out;
  for (const JointConfig* jc : chosen) out.push_back(read_joint_encoder(link, head, *jc));
  return out;
}

std::vector<JointEncoderReading> store_joint_encoder_zeros(
    std::unique_ptr<Bus> bus, const HeadConfig& head,
    const std::vector<std::pair<std::string, std::optional<std::uint16_t>>>& zeros) {
  std::vector<const JointConfig*> chosen;
  for (const auto& [name, zero] : zeros) chosen.push_back(&with_encoder(head, name));
  BoardLink link(std::move(bus), Millis(head.reply_timeout_ms));
  std::vector<JointEncoderReading> out;
  for (std::size_t i = 0; i < zeros.size(); ++i) {
    const JointConfig& jc = *chosen[i];
    std::uint16_t zero = 0;
    if (zeros[i].second) {
      zero = *zeros[i].second;
    } else {
      const JointEncoderReading now = read_joint_encoder(link, head, jc);
      if (now.state != "ok") {
        throw Error("joint '" + jc.name + "': its encoder is " + now.state + ", so there is no angle to take as its zero");
      }
      zero = now.raw;
    }
    out.push_back(store_joint_encoder_zero(link, head, jc, zero));
  }
  return out;
}

}  // namespace robogene::can
