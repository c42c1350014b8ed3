// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// Gives each test its own virtual-bus directory, so concurrent test runs never share a bus.
#pragma once

#include <stdlib.h>
#include <unistd.h>

#include <cstdlib>
#include <stdexcept>
#include <string>

namespace robogene::can::testing {

class TempBusDir {
 public:
  TempBusDir() {
    const char* tmp = std::getenv("TMPDIR");
    std::string tmpl = std::string(tmp && *tmp ? tmp : "/tmp") + "/rgcan-XXXXXX";
    const char* made = ::mkdtemp(tmpl.data());
    if (!made) throw std::runtime_error("mkdtemp " + tmpl + " failed");
    path_ = made;
    ::setenv("ROBOGENE_CAN_DIR", path_.c_str(), 1);
  }
  ~TempBusDir() {
    const std::string cmd = "rm -rf '" + path_ + "'";
    (void)!::system(cmd.c_str());
  }
  const std::string& path() const { return path_; }

 private:
  std::string path_;
};

}  // namespace robogene::can::testing
