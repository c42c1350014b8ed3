// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// A firmware update across processes, as a lab would run it: `robogene can-sim --flash-dir`
// simulates the head with each board's flash in a file, `robogene can-flash` updates the eye
// board. Refused: an image for another board, a corrupted file. Interrupted: the flasher is killed
// at a third of the way, the simulated head is power-cycled, the board answers from its
// bootloader, and a second can-flash succeeds. Used on the virtual bus and on vcan0 in the VM.
#pragma once

#include <fcntl.h>
#include <signal.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "cli_head_session.hpp"
#include "flash_fixture.hpp"
#include "head_rig.hpp"
#include "robogene/can/flasher.hpp"

namespace robogene::can::testing {

struct CommandResult {
  int status = -1;
  std::string output;
};

inline CommandResult run_command(const std::string& cmd) {
  CommandResult r;
  FILE* p = ::popen((cmd + " 2>&1").c_str(), "r");
  if (!p) return r;
  char buf[512];
  while (std::fgets(buf, sizeof buf, p)) r.output += buf;
  const int status = ::pclose(p);
  r.status = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return r;
}

inline pid_t start_flash_simulator(const std::string& bus, const std::string& flash_dir, const std::string& log) {
  const std::string bin = robogene_bin(), ini = head_ini_path();
  const pid_t pid = ::fork();
  if (pid == 0) {
    const int out = ::open(log.c_str(), O_WRONLY | O_CREAT | O_APPEND, 0644);
    if (out >= 0) ::dup2(out, 1);
    ::execl(bin.c_str(), bin.c_str(), "can-sim", "--bus", bus.c_str(), "--from", ini.c_str(), "--flash-dir",
            flash_dir.c_str(), "--duration", "120", static_cast<char*>(nullptr));
    ::_exit(127);
  }
  return pid;
}

inline void stop_child(ChildGuard& child) {
  ::kill(child.pid, SIGTERM);
  ::waitpid(child.pid, nullptr, 0);
  child.pid = 0;
}

// The eye board's identity, asked on a bus opened for the question (a bus left open would queue
// everything the flasher and the boards send meanwhile).
inline std::optional<BoardIdentity> ask_eye_board(const std::string& bus_spec) {
  auto bus = open_bus(bus_spec);
  return identify_board(*bus, 3, Millis(500));
}

// Waits until the eye board answers (the simulator may still be starting); returns its identity.
inline std::optional<BoardIdentity> eye_board(const std::string& bus_spec) {
  std::optional<BoardIdentity> id;
  eventually(10.0, [&] { return (id = ask_eye_board(bus_spec)).has_value(); });
  return id;
}

inline void run_flash_session(const std::string& bus_spec, const std::string& scratch) {
  const std::string bin = robogene_bin();
  const std::string flash_dir = scratch + "/flash-files", sim_out = scratch + "/can-sim-flash.out";
  ::mkdir(flash_dir.c_str(), 0755);
  const auto good = make_stamped_image(3, static_cast<std::uint8_t>(board_revision()), 40000);
  write_file(scratch + "/eyes.bin", good);
  std::ofstream(scratch + "/eyes.hex") << to_intel_hex(good, kApplicationBase);
  write_file(scratch + "/neck.bin", make_stamped_image(1, static_cast<std::uint8_t>(board_revision()), 40000));
  auto corrupted = good;
  corrupted[20000] ^= 0x04;
  write_file(scratch + "/corrupted.bin", corrupted);
  const std::string flash = bin + " can-flash --bus " + bus_spec + " --address 3 ";

  ChildGuard sim{start_flash_simulator(bus_spec, flash_dir, sim_out)};
  ASSERT_GT(sim.pid, 0);
  auto id = eye_board(bus_spec);
  ASSERT_TRUE(id) << "the simulated eye board does not answer";
  EXPECT_FALSE(id->in_bootloader);

  const CommandResult wrong = run_command(flash + scratch + "/neck.bin");
  EXPECT_EQ(wrong.status, 1) << wrong.output;
  EXPECT_NE(wrong.output.find("robogene can-flash: check: " + scratch + "/neck.bin is built for board 1; the board at address 3 is board 3: wrong board"),
            std::string::npos) << wrong.output;
  const CommandResult bad = run_command(flash + scratch + "/corrupted.bin");
  EXPECT_EQ(bad.status, 1) << bad.output;
  EXPECT_NE(bad.output.find("corrupted.bin: CRC-32 mismatch"), std::string::npos) << bad.output;
  id = ask_eye_board(bus_spec);
  ASSERT_TRUE(id);
  EXPECT_FALSE(id->in_bootloader) << "a refused image leaves the board running";

  // The flasher killed a third of the way through.
  int pipefd[2];
  ASSERT_EQ(::pipe(pipefd), 0);
  const pid_t flasher = ::fork();
  if (flasher == 0) {
    ::dup2(pipefd[1], 1);
    ::close(pipefd[0]);
    ::execl(bin.c_str(), bin.c_str(), "can-flash", "--bus", bus_spec.c_str(), "--address", "3",
            (scratch + "/eyes.bin").c_str(), static_cast<char*>(nullptr));
    ::_exit(127);
  }
  ChildGuard flasher_guard{flasher};
  ::close(pipefd[1]);
  std::string seen, line;
  bool killed = false;
  char c;
  while (::read(pipefd[0], &c, 1) == 1) {
    if (c != '\n') {
      line += c;
      continue;
    }
    seen += line + "\n";
    if (line.find("(30 %)") != std::string::npos) {
      ::kill(flasher, SIGKILL);
      killed = true;
      break;
    }
    line.clear();
  }
  ::close(pipefd[0]);
  ::waitpid(flasher, nullptr, 0);
  flasher_guard.pid = 0;
  ASSERT_TRUE(killed) << "can-flash never reported 30 %:\n" << seen;
  id = ask_eye_board(bus_spec);
  ASSERT_TRUE(id);
  EXPECT_TRUE(id->in_bootloader);
  EXPECT_FALSE(id->image_valid);

  // Power cycle: the simulator restarts on the same flash files.
  stop_child(sim);
  sim.pid = start_flash_simulator(bus_spec, flash_dir, sim_out);
  id = eye_board(bus_spec);
  ASSERT_TRUE(id);
  EXPECT_TRUE(id->in_bootloader) << "after an interrupted update the board must boot into its bootloader";
  EXPECT_FALSE(id->image_valid);

  // A second update, from the HEX file, finding the board by the image's board id.
  const CommandResult again = run_command(bin + " can-flash --bus " + bus_spec + " " + scratch + "/eyes.hex");
  EXPECT_EQ(again.status, 0) << again.output;
  EXPECT_NE(again.output.find("can-flash: found board 3, revision"), std::string::npos) << again.output;
  EXPECT_NE(again.output.find("in its bootloader 1.0 (no valid application)"), std::string::npos) << again.output;
  EXPECT_NE(again.output.find("can-flash: done"), std::string::npos) << again.output;
  stop_child(sim);
  EXPECT_EQ(read_file(flash_dir + "/board-3-eyes-pan.flash").size(), kApplicationRegionBytes);
  const auto cells = read_file(flash_dir + "/board-3-eyes-pan.flash");
  EXPECT_TRUE(std::equal(good.begin(), good.end(), cells.begin())) << "the flash holds the image";
  sim.pid = start_flash_simulator(bus_spec, flash_dir, sim_out);
  id = eye_board(bus_spec);
  ASSERT_TRUE(id);
  EXPECT_FALSE(id->in_bootloader) << "the updated board starts its application at power-up";
  stop_child(sim);
}

}  // namespace robogene::can::testing
