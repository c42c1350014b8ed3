// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "robogene/can/homing.hpp"

#include <chrono>
#include <cmath>
#include <thread>

#include "board_link.hpp"
#include "robogene/error.hpp"

namespace robogene::can {
namespace {

constexpr Millis kPollInterval{50};
constexpr double kGraceSeconds = 5.0;  // beyond the joint's own timeout, for the back-off and the bus

std::vector<std::size_t> chosen_joints(const HeadConfig& head, const std::vector<std::string>& names) {
  std::vector<std::size_t> out;
  if (names.empty()) {
    for (std::size_t j = 0; j < head.joints.size(); ++j) {
      if (head.joints[j].homing.direction != 0) out.push_back(j);
    }
    if (out.empty()) throw Error(head.source + ": [HOMING] homes no joint");
    return out;
  }
  for (const auto& name : names) {
    std::string known;
    std::size_t found = head.joints.size();
    for (std::size_t j = 0; j < head.joints.size(); ++j) {
      if (head.joints[j].homing.direction != 0) known += (known.empty() ? "" : ", ") + head.joints[j].name;
      if (head.joints[j].name == name) found = j;
    }
    if (found == head.joints.size()) throw Error("no joint '" + name + "' in " + head.source);
    if (head.joints[found].homing.direction == 0) {
      throw Error("joint '" + name + "' does not home ([HOMING] direction 0); the joints that home: " +
                  (known.empty() ? "none" : known));
    }
    out.push_back(found);
  }
  return out;
}

void check_protocol(BoardLink& link, const HeadConfig& head, int board) {
  const Envelope e = link.request(board, 0, GetFirmwareVersion{static_cast<std::uint8_t>(head.protocol_major),
                                                               static_cast<std::uint8_t>(head.protocol_minor)});
  if (!std::get<GetFirmwareVersionReply>(e.message).compatible) {
    throw Error(link.bus_name() + ": board " + std::to_string(board) + " does not speak protocol " +
                std::to_string(head.protocol_major) + "." + std::to_string(head.protocol_minor));
  }
}

HomingResult home_one(BoardLink& link, const JointConfig& jc) {
  HomingResult r;
  r.joint = jc.name;
  link.send(jc.board, jc.axis, CalibrateEncoder{CalibrationType::hard_stop, 0, 0});
  const auto deadline = BoardLink::Clock::now() + std::chrono::duration_cast<BoardLink::Clock::duration>(
                                                      std::chrono::duration<double>(jc.homing.timeout + kGraceSeconds));
  bool started = false;
  while (BoardLink::Clock::now() < deadline) {
    const auto mode = std::get<GetControlModeReply>(link.request(jc.board, jc.axis, GetControlMode{}).message).mode;
    if (mode == ControlMode::calibration) {
      started = true;
    } else if (mode == ControlMode::position && started) {
      const auto p = std::get<GetEncoderPositionReply>(link.request(jc.board, jc.axis, GetEncoderPosition{}).message);
      r.homed = true;
      r.degrees = p.position / jc.counts_per_degree;
      r.detail = "homed";
      return r;
    } else if (mode == ControlMode::not_configured) {
      r.detail = "found no stop within " + std::to_string(jc.homing.timeout) + " s (the board left the joint unpowered)";
      return r;
    } else if (mode == ControlMode::hardware_fault) {
      r.detail = "the board stopped the joint with a fault";
      return r;
    } else if (!started) {
      r.detail = "the board did not start homing (mode " + std::string(to_string(mode)) +
                 "): its firmware has no homing for this axis, or it is in a fault";
      return r;
    }
    std::this_thread::sleep_for(kPollInterval);
  }
  r.detail = "still homing after " + std::to_string(jc.homing.timeout + kGraceSeconds) + " s";
  return r;
}

}  // namespace

std::vector<HomingResult> home_joints(std::unique_ptr<Bus> bus, const HeadConfig& head, const std::vector<std::string>& joints,
                                      const std::function<void(const std::string&)>& progress) {
  const auto chosen = chosen_joints(head, joints);
  BoardLink link(std::move(bus), Millis(head.reply_timeout_ms));
  std::vector<HomingResult> results;
  for (std::size_t j : chosen) {
    const JointConfig& jc = head.joints[j];
    check_protocol(link, head, jc.board);
    if (progress) progress(jc.name + ": homing on board " + std::to_string(jc.board) + " axis " + std::to_string(jc.axis));
    results.push_back(home_one(link, jc));
  }
  return results;
}

}  // namespace robogene::can
