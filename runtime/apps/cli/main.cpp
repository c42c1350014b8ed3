// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// `robogene`: one executable for the name server and the everyday port tools, in the manner of
// YARP's `yarp` companion (same outputs where a user would compare them).
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "commands.hpp"
#include "robogene/error.hpp"

namespace {

using robogene::cli::Args;

struct Command {
  const char* name;
  const char* usage;
  const char* summary;
  int (*run)(Args&);
};

const Command kCommands[] = {
    {"server", "robogene server [--ip HOST] [--socket PORT] [--db FILE] [--read] [--stale-grace S] [--recheck S] [--sweep S] [--max-message BYTES] [--max-connections N] [--idle-timeout S] [--no-fallback]",
     "run the name server /root (default 127.0.0.1:10000); registrations persist in FILE", robogene::cli::cmd_server},
    {"detect", "robogene detect [--write] [--ip IFACE] [--timeout S]",
     "find the name server over multicast, without yarp.conf (as yarp detect); --write saves it",
     robogene::cli::cmd_detect},
    {"name", "robogene name query|list|register|unregister|set|get|check|route|gc ARGS... [--server HOST:PORT]",
     "ask the name server, printing its replies as `yarp name` does", robogene::cli::cmd_name},
    {"read", "robogene read /port [/source] [--envelope] [--max-message BYTES] [--server HOST:PORT]",
     "open an input port and print every bottle received, one per line (stop with Ctrl-C)",
     robogene::cli::cmd_read},
    {"write", "robogene write /port [/destination ...] [--server HOST:PORT]",
     "open an output port, connect it, and send each bottle typed on stdin (ends at EOF)",
     robogene::cli::cmd_write},
    {"rpc", "robogene rpc /port [--carrier tcp|text_ack|...] [--server HOST:PORT]",
     "send each bottle typed on stdin as a request and print `Response: <reply>`", robogene::cli::cmd_rpc},
    {"connect", "robogene connect /from /to [carrier] [--server HOST:PORT]",
     "ask port /from to add an output to /to (admin [add] over text_ack, as yarp connect)",
     robogene::cli::cmd_connect},
    {"disconnect", "robogene disconnect /from /to [--server HOST:PORT]",
     "ask port /from to drop its connection to /to (admin [del])", robogene::cli::cmd_disconnect},
    {"ping", "robogene ping /port [--server HOST:PORT]", "check that a port is there and answers, with the time taken",
     robogene::cli::cmd_ping},
    {"ls", "robogene ls [/prefix] [--server HOST:PORT]",
     "list registered ports with their connections and carriers", robogene::cli::cmd_ls},
    {"dev", "robogene dev --device NAME [--name /prefix] [--from FILE.ini] [--subdevice NAME] [--axes N] [--period S] [--single_port] [--KEY VALUE...] [--server HOST:PORT]",
     "open a device and serve it on the network until Ctrl-C (the paper's yarpdev)", robogene::cli::cmd_dev},
    {"can-sim", "robogene can-sim --bus virtual:NAME|socketcan:IFACE --from head.ini [--log FILE.log] [--duration S] [--flash-dir DIR] [--pose JOINT=DEG,...] [--backlash JOINT=DEG]... [--reverse-joint-encoder JOINT]...",
     "simulate the head's CAN boards on a bus until Ctrl-C (drive them with --device robogene_can)",
     robogene::cli::cmd_can_sim},
    {"can-home", "robogene can-home --bus virtual:NAME|socketcan:IFACE --from head.ini [JOINT...]",
     "home the joints without absolute encoders (the eyes) against their hard stops; exit 1 if one fails",
     robogene::cli::cmd_can_home},
    {"can-zero", "robogene can-zero --bus virtual:NAME|socketcan:IFACE --from head.ini [--store JOINT[=RAW]] [JOINT...]",
     "read the joints' absolute encoders, or store a joint's zero (its raw angle now, or RAW) in its board; exit 1 if one is not homed",
     robogene::cli::cmd_can_zero},
    {"can-flash", "robogene can-flash --bus virtual:NAME|socketcan:IFACE [--address N] [--timeout S] [--no-start] IMAGE.bin|IMAGE.hex",
     "update a motor board's firmware over CAN through its bootloader (checks board, revision and CRC)",
     robogene::cli::cmd_can_flash},
};

const Command* find_command(const std::string& name) {
  for (const auto& c : kCommands) {
    if (name == c.name) return &c;
  }
  return nullptr;
}

void print_help() {
  std::printf("robogene %s: ports, name server and tools speaking YARP 3's protocol\n\n", ROBOGENE_VERSION);
  std::printf("usage: robogene COMMAND [ARGS...] [--server HOST:PORT]\n\ncommands:\n");
  for (const auto& c : kCommands) std::printf("  %-11s %s\n", c.name, c.summary);
  std::printf("  %-11s %s\n", "version", "print the version");
  std::printf("  %-11s %s\n", "help", "this list; `robogene help COMMAND` for one command");
  std::printf("\nWithout --server, the name server is found through yarp.conf ($YARP_CONFIG_HOME,\n"
              "$XDG_CONFIG_HOME/yarp or ~/.config/yarp), else 127.0.0.1:10000.\n");
}

}  // namespace

int main(int argc, char** argv) {
  robogene::cli::block_shutdown_signals();
  std::vector<std::string> words(argv + 1, argv + argc);
  if (words.empty()) {
    print_help();
    return 2;
  }
  const std::string name = words[0];
  words.erase(words.begin());
  if (name == "help" || name == "--help" || name == "-h") {
    if (!words.empty()) {
      const Command* c = find_command(words[0]);
      if (!c) {
        std::fprintf(stderr, "robogene help: unknown command \"%s\"\n", words[0].c_str());
        return 2;
      }
      std::printf("usage: %s\n\n%s\n", c->usage, c->summary);
      return 0;
    }
    print_help();
    return 0;
  }
  if (name == "version" || name == "--version") {
    std::printf("robogene %s (YARP 3 wire protocol)\n", ROBOGENE_VERSION);
    return 0;
  }
  const Command* command = find_command(name);
  if (!command) {
    std::fprintf(stderr, "robogene: unknown command \"%s\"; `robogene help` lists them\n", name.c_str());
    return 2;
  }
  Args args(words);
  try {
    return command->run(args);
  } catch (const robogene::cli::UsageError& e) {
    std::fprintf(stderr, "robogene %s: %s\nusage: %s\n", name.c_str(), e.what(), command->usage);
    return 2;
  } catch (const robogene::Error& e) {
    std::fprintf(stderr, "robogene %s: %s\n", name.c_str(), e.what());
    return 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "robogene %s: unexpected failure: %s\n", name.c_str(), e.what());
    return 1;
  }
}
