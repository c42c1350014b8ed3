// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// DriverFactory: the list of devices by symbolic name and how to create each (paper section 3.2).
// The drivers in drivers/ add themselves to instance() as the program starts
// (ROBOGENE_REGISTER_DRIVER, robogene/dev/driver_registrar.hpp); programs may add more.
#pragma once

#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "robogene/dev/device_driver.hpp"

namespace robogene::dev {

class DriverFactory {
 public:
  using Creator = std::function<std::unique_ptr<DeviceDriver>()>;

  struct Entry {
    std::string name;
    std::string description;
    Creator create;
  };

  static DriverFactory& instance();

  // Throws robogene::Error when `name` is taken or empty.
  void add(std::string name, std::string description, Creator create);
  bool has(const std::string& name) const;
  // Throws robogene::Error naming the unknown driver and listing the known ones.
  std::unique_ptr<DeviceDriver> create(const std::string& name) const;
  std::vector<Entry> entries() const;  // sorted by name

 private:
  mutable std::mutex mutex_;
  std::map<std::string, Entry> drivers_;
};

}  // namespace robogene::dev
