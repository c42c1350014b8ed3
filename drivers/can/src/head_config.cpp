// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "robogene/can/head_config.hpp"

#include <cmath>
#include <set>

#include "motor_control.hpp"

namespace robogene::can {
namespace {

using dev::ConfigError;
using dev::Searchable;

// Reads from one [GROUP] of the file; every message names file:line, group and key.
class Group {
 public:
  Group(const Searchable& root, const std::string& name) : name_(name) {
    group_ = root.find_group(name);
    if (!group_) throw ConfigError(root.source() + ": missing group [" + name + "]");
  }

  [[noreturn]] void fail(const std::string& key, const std::string& what) const {
    const std::string where = group_->origin(key);
    throw ConfigError((where.empty() ? group_->source() : where) + ": [" + name_ + "] key '" + key + "': " + what);
  }

  const Value& require(const std::string& key) const {
    const Value& v = group_->find(key);
    if (v.is_null()) throw ConfigError(group_->source() + ": [" + name_ + "] missing key '" + key + "'");
    return v;
  }
  bool has(const std::string& key) const { return !group_->find(key).is_null(); }

  std::vector<const Value*> list(const std::string& key, std::size_t count) const {
    const Value& v = require(key);
    std::vector<const Value*> out;
    if (v.is_list()) {
      for (std::size_t i = 0; i < v.as_list().size(); ++i) out.push_back(&v.as_list()[i]);
    } else {
      out.push_back(&v);
    }
    if (count != 0 && out.size() != count) {
      fail(key, "expected " + std::to_string(count) + " values (one per joint), got " + std::to_string(out.size()));
    }
    return out;
  }

  std::vector<double> numbers(const std::string& key, std::size_t count, double lo, double hi) const {
    std::vector<double> out;
    std::size_t i = 0;
    for (const Value* v : list(key, count)) {
      if (!v->is_number()) fail(key, "value " + std::to_string(i + 1) + " (" + v->to_text() + ") is not a number");
      const double d = v->as_float64();
      if (!std::isfinite(d) || d < lo || d > hi) {
        fail(key, "value " + std::to_string(i + 1) + " (" + v->to_text() + ") is outside [" + text(lo) + ", " + text(hi) + "]");
      }
      out.push_back(d);
      ++i;
    }
    return out;
  }

  std::vector<int> ints(const std::string& key, std::size_t count, int lo, int hi) const {
    std::vector<int> out;
    std::size_t i = 0;
    for (double d : numbers(key, count, lo, hi)) {
      ++i;
      if (d != std::floor(d)) fail(key, "value " + std::to_string(i) + " (" + text(d) + ") is not an integer");
      out.push_back(static_cast<int>(d));
    }
    return out;
  }

  int integer(const std::string& key, int lo, int hi) const { return ints(key, 1, lo, hi)[0]; }

  std::vector<std::string> words(const std::string& key, std::size_t count) const {
    std::vector<std::string> out;
    for (const Value* v : list(key, count)) {
      if (!v->is_string()) fail(key, v->to_text() + " is not a \"string\"");
      out.push_back(v->as_string());
    }
    return out;
  }

  // A 2x2 matrix written as two (a b) rows.
  std::array<std::array<double, 2>, 2> matrix(const std::string& key) const {
    const auto rows = list(key, 2);
    std::array<std::array<double, 2>, 2> m{};
    for (int r = 0; r < 2; ++r) {
      const Value& row = *rows[static_cast<std::size_t>(r)];
      if (!row.is_list() || row.as_list().size() != 2 || !row.as_list()[0].is_number() || !row.as_list()[1].is_number()) {
        fail(key, "row " + std::to_string(r + 1) + " (" + row.to_text() + ") is not a list of two numbers");
      }
      m[static_cast<std::size_t>(r)] = {row.as_list()[0].as_float64(), row.as_list()[1].as_float64()};
    }
    return m;
  }

  static std::string text(double d) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%g", d);
    return buf;
  }

 private:
  std::string name_;
  const Searchable* group_ = nullptr;
};

void read_coupling(const Searchable& root, HeadConfig& head, BoardConfig& board) {
  const std::string name = "COUPLING_" + std::to_string(board.address);
  if (!root.find_group(name)) return;
  const Group g(root, name);
  Coupling c;
  c.type = g.words("type", 1)[0];
  if (c.type != "version_vergence") g.fail("type", "\"" + c.type + "\" is not a known coupling (version_vergence)");
  const auto joints = g.ints("joints", 2, 0, static_cast<int>(head.joints.size()) - 1);
  c.joints = {joints[0], joints[1]};
  if (c.joints[0] != board.joints[0] || c.joints[1] != board.joints[1]) {
    g.fail("joints", "joints " + std::to_string(c.joints[0]) + " " + std::to_string(c.joints[1]) +
                         " are not the ones on board " + std::to_string(board.address) + "'s axes 0 and 1");
  }
  const auto motors = g.words("motors", 2);
  c.motors = {motors[0], motors[1]};
  c.j2m = g.matrix("j2m");
  c.m2j = g.matrix("m2j");
  for (int r = 0; r < 2; ++r) {
    for (int k = 0; k < 2; ++k) {
      double p = 0;
      for (int i = 0; i < 2; ++i) p += c.m2j[static_cast<std::size_t>(r)][static_cast<std::size_t>(i)] *
                                     c.j2m[static_cast<std::size_t>(i)][static_cast<std::size_t>(k)];
      if (std::fabs(p - (r == k ? 1.0 : 0.0)) > 1e-9) g.fail("m2j", "is not the inverse of j2m (m2j * j2m is not the identity)");
    }
  }
  board.coupling = c;
}

}  // namespace

const BoardConfig* HeadConfig::board(int address) const {
  for (const auto& b : boards) {
    if (b.address == address) return &b;
  }
  return nullptr;
}

HeadConfig read_head_config(const Searchable& config) {
  HeadConfig head;
  head.source = config.source();
  const Group can(config, "CAN");
  head.device = can.words("device", 1)[0];
  head.host_address = can.integer("host_address", 0, 15);
  if (head.host_address != kHostAddress) {
    can.fail("host_address", std::to_string(head.host_address) + " is not the protocol's host address " + std::to_string(kHostAddress));
  }
  const std::string fingerprint = can.words("protocol_fingerprint", 1)[0];
  if (fingerprint != kProtocolFingerprint) {
    can.fail("protocol_fingerprint", "\"" + fingerprint + "\" is not this driver's protocol (" + kProtocolFingerprint +
                                         "): regenerate the config or rebuild the driver");
  }
  const auto version = can.ints("protocol_version", 2, 0, 255);
  head.protocol_major = version[0];
  head.protocol_minor = version[1];
  head.broadcast_policy = static_cast<std::uint32_t>(can.numbers("broadcast_policy", 1, 0, 4294967295.0)[0]);
  if (!(head.broadcast_policy & broadcast_mask::position)) {
    can.fail("broadcast_policy", "must enable the position broadcast (bit 0): the driver reads encoders from it");
  }
  head.polling_interval_ms = can.integer("polling_interval_ms", 1, 1000);
  head.reply_timeout_ms = can.integer("reply_timeout_ms", 1, 60000);
  const auto names = can.words("board_names", 0);
  const auto addresses = can.ints("board_addresses", names.size(), 1, 14);

  const Group general(config, "GENERAL");
  const int n = general.integer("joints", 1, 64);
  const auto count = static_cast<std::size_t>(n);
  const auto axis_names = general.words("axis_names", count);
  const auto boards = general.ints("board", count, 1, 14);
  const auto axes = general.ints("axis", count, 0, 1);
  const auto encoder = general.numbers("encoder", count, 1e-6, 1e9);
  const auto gear = general.numbers("gear_ratio", count, 1e-6, 1e6);
  const auto lines = general.ints("motor_encoder_lines", count, 1, 1 << 20);
  // brake is optional: a configuration without it has no holding brakes.
  const auto brake = general.has("brake") ? general.ints("brake", count, 0, 1) : std::vector<int>(count, 0);
  // joint_encoder_bits is optional: a configuration without it has no joint encoders. The boards read
  // AS5048As (14 bits); 0 is none.
  const auto joint_encoder_bits =
      general.has("joint_encoder_bits") ? general.ints("joint_encoder_bits", count, 0, 14) : std::vector<int>(count, 0);
  // joint_correction_limit is optional: without it every joint's position is its motor encoder's.
  const auto joint_correction =
      general.has("joint_correction_limit") ? general.numbers("joint_correction_limit", count, 0, 360)
                                             : std::vector<double>(count, 0.0);
  head.pwm_full_scale = general.integer("pwm_full_scale", 1, 32767);
  head.control_period_us = general.integer("control_period_us", 100, 100000);

  const Group limits(config, "LIMITS");
  const auto min = limits.numbers("min", count, -360, 360);
  const auto max = limits.numbers("max", count, -360, 360);
  const auto max_velocity = limits.numbers("max_velocity", count, 1e-6, 1e5);
  const auto current = limits.numbers("current", count, 0, 1e6);
  const Group velocity(config, "VELOCITY");
  head.velocity_timeout_ms = velocity.integer("timeout_ms", 1, 32767);

  const Group pids(config, "PIDS");
  const auto kp = pids.ints("kp", count, -32768, 32767);
  const auto ki = pids.ints("ki", count, -32768, 32767);
  const auto kd = pids.ints("kd", count, -32768, 32767);
  const auto shift = pids.ints("shift", count, 0, 15);
  const auto offset = pids.ints("offset", count, -32768, 32767);
  const auto output_limit = pids.ints("output_limit", count, 0, 32767);
  const auto integral_limit = pids.ints("integral_limit", count, 0, 32767);

  // [HOMING] is optional: a configuration without it homes no joint.
  std::vector<HomingConfig> homing(count);
  if (config.find_group("HOMING")) {
    const Group h(config, "HOMING");
    const auto direction = h.ints("direction", count, -1, 1);
    const auto stop = h.numbers("stop", count, -360, 360);
    const auto speed = h.numbers("speed", count, 0, 1e5);
    const auto pwm = h.ints("pwm", count, 0, 32767);
    const auto backoff = h.numbers("backoff", count, 0, 720);
    const auto timeout = h.numbers("timeout", count, 0, 3600);
    const auto homing_current = h.ints("current", count, 0, 100000);
    for (std::size_t j = 0; j < count; ++j) {
      homing[j] = HomingConfig{direction[j], stop[j], speed[j], pwm[j], backoff[j], timeout[j], homing_current[j]};
      if (direction[j] != 0 && (speed[j] <= 0 || pwm[j] <= 0 || timeout[j] <= 0)) {
        h.fail("speed", "joint " + axis_names[j] + " homes (direction " + std::to_string(direction[j]) +
                            ") but its speed, pwm or timeout is 0");
      }
      if (direction[j] != 0 && (homing_current[j] <= 0 || homing_current[j] > current[j])) {
        h.fail("current", "joint " + axis_names[j] + " homes with " + std::to_string(homing_current[j]) +
                              " mA, outside 1..its current limit (" + Group::text(current[j]) + " mA, [LIMITS] current)");
      }
    }
  }

  std::set<int> seen_addresses;
  for (std::size_t b = 0; b < names.size(); ++b) {
    if (!seen_addresses.insert(addresses[b]).second) {
      can.fail("board_addresses", "address " + std::to_string(addresses[b]) + " is used by two boards");
    }
    head.boards.push_back(BoardConfig{names[b], addresses[b], {{-1, -1}}, std::nullopt});
  }
  for (std::size_t j = 0; j < count; ++j) {
    JointConfig jc;
    jc.name = axis_names[j];
    jc.board = boards[j];
    jc.axis = axes[j];
    jc.counts_per_degree = encoder[j];
    jc.gear_ratio = gear[j];
    jc.motor_encoder_lines = lines[j];
    jc.has_brake = brake[j] != 0;
    jc.joint_encoder_bits = joint_encoder_bits[j];
    if (jc.joint_encoder_bits != 0 && jc.joint_encoder_bits != 14) {
      general.fail("joint_encoder_bits", "joint " + jc.name + ": " + std::to_string(jc.joint_encoder_bits) +
                                             " bits; the boards read AS5048A joint encoders (14 bits) or none (0)");
    }
    jc.joint_correction_limit = joint_correction[j];
    if (jc.joint_correction_limit > 0 && jc.joint_encoder_bits == 0) {
      general.fail("joint_correction_limit", "joint " + jc.name + ": " + Group::text(jc.joint_correction_limit) +
                                                 " deg, but it has no joint encoder to close its position on");
    }
    jc.min = min[j];
    jc.max = max[j];
    if (jc.min >= jc.max) limits.fail("max", "joint " + jc.name + ": max " + Group::text(jc.max) + " is not above min " + Group::text(jc.min));
    jc.max_velocity = max_velocity[j];
    jc.current_limit = current[j];
    jc.pid = PidGains{kp[j], ki[j], kd[j], shift[j], offset[j], output_limit[j], integral_limit[j]};
    jc.homing = homing[j];
    BoardConfig* board = nullptr;
    for (auto& b : head.boards) {
      if (b.address == jc.board) board = &b;
    }
    if (!board) general.fail("board", "joint " + jc.name + " is on board " + std::to_string(jc.board) + ", which [CAN] board_addresses does not list");
    int& slot = board->joints[static_cast<std::size_t>(jc.axis)];
    if (slot >= 0) {
      general.fail("axis", "joints " + head.joints[static_cast<std::size_t>(slot)].name + " and " + jc.name + " are both on board " +
                               std::to_string(jc.board) + " axis " + std::to_string(jc.axis));
    }
    slot = static_cast<int>(j);
    head.joints.push_back(jc);
  }
  for (auto& b : head.boards) read_coupling(config, head, b);
  for (const auto& b : head.boards) {
    // A coupled board derives both joints from both motors' encoders: both have them, or neither.
    if (b.coupling && b.joints[0] >= 0 && b.joints[1] >= 0) {
      const JointConfig& j0 = head.joints[static_cast<std::size_t>(b.joints[0])];
      const JointConfig& j1 = head.joints[static_cast<std::size_t>(b.joints[1])];
      if (j0.joint_encoder_bits != j1.joint_encoder_bits) {
        general.fail("joint_encoder_bits", "joints " + j0.name + " and " + j1.name + " on coupled board " + std::to_string(b.address) +
                                               " differ: its firmware derives both from both pans' encoders");
      }
    }
    for (int j : b.joints) {
      // A board's brake output follows one motor; on a coupled board each motor serves both axes.
      if (j >= 0 && b.coupling && head.joints[static_cast<std::size_t>(j)].has_brake) {
        general.fail("brake", "joint " + head.joints[static_cast<std::size_t>(j)].name + " has a brake, but board " +
                                  std::to_string(b.address) + " couples its motors: a board drives brakes only on uncoupled axes");
      }
    }
  }
  return head;
}

}  // namespace robogene::can
