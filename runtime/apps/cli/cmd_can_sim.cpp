// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// `robogene can-sim`: the head's CAN boards simulated on a bus (drivers/can), so the head can be
// driven with no hardware: `robogene dev --device robogene_can --from head.ini --bus virtual:head`
// in another terminal talks to it as to the real boards.
#include <signal.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "commands.hpp"
#include "robogene/can/logging_bus.hpp"
#include "robogene/can/sim/motor_place.hpp"
#include "robogene/can/sim/simulated_head.hpp"
#include "robogene/can/virtual_bus.hpp"
#include "robogene/dev/property.hpp"

namespace robogene::cli {
namespace {

// Waits for SIGINT/SIGTERM (blocked by main, so taken here) or until `seconds` pass (< 0: forever).
void wait_for_signal_or(double seconds) {
  if (seconds < 0) {
    wait_for_shutdown_signal();
    return;
  }
  sigset_t set;
  sigemptyset(&set);
  sigaddset(&set, SIGINT);
  sigaddset(&set, SIGTERM);
  timespec ts{static_cast<time_t>(seconds), static_cast<long>((seconds - static_cast<double>(static_cast<time_t>(seconds))) * 1e9)};
  sigtimedwait(&set, nullptr, &ts);
}

// --pose JOINT=DEG[,JOINT=DEG...]: the joints' angles when the boards power up (the rest at 0), as
// motor angles per board; on the eye board version and vergence become the pans' (left = version +
// vergence / 2, right = version - vergence / 2).
std::map<int, std::array<double, 2>> parse_pose(const std::string& text, const can::HeadConfig& head) {
  std::map<std::string, double> joints;
  std::size_t at = 0;
  while (at <= text.size()) {
    const std::size_t end = std::min(text.find(',', at), text.size());
    const std::string item = text.substr(at, end - at);
    const auto eq = item.find('=');
    const std::string name = item.substr(0, eq);
    bool known = false;
    for (const auto& j : head.joints) known = known || j.name == name;
    if (eq == std::string::npos || !known) {
      throw UsageError("--pose " + text + ": '" + item + "' is not JOINT=DEG with a joint of " + head.source);
    }
    char* stop = nullptr;
    const std::string value = item.substr(eq + 1);
    const double deg = std::strtod(value.c_str(), &stop);
    if (value.empty() || *stop != '\0' || !std::isfinite(deg)) {
      throw UsageError("--pose " + text + ": '" + value + "' (" + name + ") is not an angle in degrees");
    }
    joints[name] = deg;
    at = end + 1;
  }
  std::map<int, std::array<double, 2>> boards;
  for (const auto& b : head.boards) {
    std::array<double, 2> axis{{0.0, 0.0}};
    bool posed = false;
    for (int i = 0; i < 2; ++i) {
      const int j = b.joints[static_cast<std::size_t>(i)];
      if (j < 0) continue;
      const auto it = joints.find(head.joints[static_cast<std::size_t>(j)].name);
      if (it == joints.end()) continue;
      axis[static_cast<std::size_t>(i)] = it->second;
      posed = true;
    }
    if (!posed) continue;
    if (b.coupling) {
      const auto& m = b.coupling->j2m;  // motors = j2m * joints
      boards[b.address] = {m[0][0] * axis[0] + m[0][1] * axis[1], m[1][0] * axis[0] + m[1][1] * axis[1]};
    } else {
      boards[b.address] = axis;
    }
  }
  return boards;
}

// --backlash MOTOR=DEG: the dead band (deg at the joint) between that motor's gear output and its joint.
std::pair<can::sim::MotorPlace, double> parse_backlash(const std::string& text, const can::HeadConfig& head) {
  const auto eq = text.find('=');
  if (eq == std::string::npos) throw UsageError("--backlash " + text + ": expected JOINT=DEG");
  can::sim::MotorPlace place;
  try {
    place = can::sim::motor_place(head, text.substr(0, eq));
  } catch (const Error& e) {
    throw UsageError("--backlash " + text + ": " + e.what());
  }
  const std::string value = text.substr(eq + 1);
  char* stop = nullptr;
  const double deg = std::strtod(value.c_str(), &stop);
  if (value.empty() || *stop != '\0' || !std::isfinite(deg) || deg < 0.0) {
    throw UsageError("--backlash " + text + ": '" + value + "' is not a width in degrees >= 0");
  }
  return {place, deg};
}

can::sim::MotorPlace parse_reversed(const std::string& text, const can::HeadConfig& head) {
  try {
    return can::sim::motor_place(head, text);
  } catch (const Error& e) {
    throw UsageError("--reverse-joint-encoder " + text + ": " + e.what());
  }
}

}  // namespace

int cmd_can_sim(Args& args) {
  const auto bus_spec = args.option("--bus");
  const auto from = args.option("--from");
  const auto log_path = args.option("--log");
  const auto duration = args.option("--duration");
  const auto flash_dir = args.option("--flash-dir");
  const auto pose = args.option("--pose");
  std::vector<std::string> backlash_texts, reversed_texts;
  while (auto v = args.option("--backlash")) backlash_texts.push_back(*v);
  while (auto v = args.option("--reverse-joint-encoder")) reversed_texts.push_back(*v);
  if (!args.positional().empty()) throw UsageError("unexpected argument " + args.positional()[0]);
  if (!bus_spec) throw UsageError("--bus is required (virtual:NAME or socketcan:IFACE)");
  if (!from) throw UsageError("--from is required (the head's board config, e.g. drivers/can/generated/head.ini)");
  const double seconds = duration ? parse_seconds(*duration, "--duration") : -1.0;

  if (flash_dir && bus_spec->rfind("virtual:", 0) == 0) {
    // The virtual bus takes every file in its directory for a node's socket and removes it.
    char* bus_dir = ::realpath(can::VirtualBus::directory_for(bus_spec->substr(8)).c_str(), nullptr);
    char* flash = ::realpath(flash_dir->c_str(), nullptr);
    const bool same = bus_dir && flash && std::string(bus_dir) == flash;
    std::free(bus_dir);
    std::free(flash);
    if (same) throw UsageError("--flash-dir " + *flash_dir + " is the virtual bus's own directory; give another");
  }
  const can::HeadConfig head = can::read_head_config(dev::Property::from_ini_file(*from));
  std::unique_ptr<can::Bus> bus = can::open_bus(*bus_spec);
  if (log_path) bus = std::make_unique<can::LoggingBus>(std::move(bus), std::make_shared<can::CandumpWriter>(*log_path));
  const auto posed = pose ? parse_pose(*pose, head) : std::map<int, std::array<double, 2>>{};
  std::vector<std::pair<can::sim::MotorPlace, double>> backlash;
  for (const auto& t : backlash_texts) backlash.push_back(parse_backlash(t, head));
  std::vector<can::sim::MotorPlace> reversed;
  for (const auto& t : reversed_texts) reversed.push_back(parse_reversed(t, head));
  can::sim::SimulatedHead sim(head, std::move(bus), {}, flash_dir.value_or(""));
  for (const auto& [address, motors] : posed) sim.power_up_at(address, motors[0], motors[1]);
  for (const auto& [place, deg] : backlash) sim.set_backlash(place.board, place.motor, deg);
  for (const auto& place : reversed) sim.set_joint_encoder_reversed(place.board, place.motor, true);
  std::string boards;
  for (const auto& b : head.boards) {
    boards += (boards.empty() ? "" : ", ") + b.name + " at " + std::to_string(b.address) +
              (sim.in_bootloader(b.address) ? " (in its bootloader)" : "");
  }
  std::string brakes;
  for (const auto& j : head.joints) {
    if (j.has_brake) brakes += (brakes.empty() ? "" : ", ") + j.name;
  }
  std::string extras;
  for (std::size_t i = 0; i < backlash.size(); ++i) extras += "; backlash " + backlash_texts[i] + " deg";
  for (const auto& t : reversed_texts) extras += "; " + t + "'s joint encoder reversed";
  std::printf("can-sim: %zu boards (%s) on %s; holding brakes: %s (each change logged at ROBOGENE_LOG=info)%s%s\n",
              head.boards.size(), boards.c_str(), bus_spec->c_str(), brakes.empty() ? "none" : brakes.c_str(),
              extras.c_str(), seconds < 0 ? "; Ctrl-C stops" : "");
  std::fflush(stdout);
  wait_for_signal_or(seconds);
  sim.stop();
  std::printf("can-sim: stopped after %llu control periods\n", static_cast<unsigned long long>(sim.ticks()));
  return 0;
}

}  // namespace robogene::cli
