// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// `robogene can-sim`: the head's CAN boards simulated on a bus (drivers/can), so the head can be
// driven with no hardware: `robogene dev --device robogene_can --from head.ini --bus virtual:head`
// in another terminal talks to it as to the real boards.
#include <signal.h>

#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <memory>

#include "commands.hpp"
#include "robogene/can/logging_bus.hpp"
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

}  // namespace

int cmd_can_sim(Args& args) {
  const auto bus_spec = args.option("--bus");
  const auto from = args.option("--from");
  const auto log_path = args.option("--log");
  const auto duration = args.option("--duration");
  const auto flash_dir = args.option("--flash-dir");
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
  can::sim::SimulatedHead sim(head, std::move(bus), {}, flash_dir.value_or(""));
  std::string boards;
  for (const auto& b : head.boards) {
    boards += (boards.empty() ? "" : ", ") + b.name + " at " + std::to_string(b.address) +
              (sim.in_bootloader(b.address) ? " (in its bootloader)" : "");
  }
  std::string brakes;
  for (const auto& j : head.joints) {
    if (j.has_brake) brakes += (brakes.empty() ? "" : ", ") + j.name;
  }
  std::printf("can-sim: %zu boards (%s) on %s; holding brakes: %s (each change logged at ROBOGENE_LOG=info)%s\n",
              head.boards.size(), boards.c_str(), bus_spec->c_str(), brakes.empty() ? "none" : brakes.c_str(),
              seconds < 0 ? "; Ctrl-C stops" : "");
  std::fflush(stdout);
  wait_for_signal_or(seconds);
  sim.stop();
  std::printf("can-sim: stopped after %llu control periods\n", static_cast<unsigned long long>(sim.ticks()));
  return 0;
}

}  // namespace robogene::cli
