// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "robogene/dev/poly_driver.hpp"

#include <exception>

namespace robogene::dev {

bool PolyDriver::open(const std::string& device) {
  Property config("device '" + device + "' defaults");
  config.put("device", Value::string(device), "PolyDriver::open argument");
  return open_with(device, config);
}

bool PolyDriver::open(const Searchable& config) {
  try {
    return open_with(config.get_string("device", ""), config);
  } catch (const Error& e) {
    error_ = e.what();
    return false;
  }
}

bool PolyDriver::open_with(const std::string& name, const Searchable& config) {
  close();
  error_.clear();
  if (name.empty()) {
    error_ = config.source() + ": no 'device' key naming the driver to open";
    return false;
  }
  try {
    auto device = DriverFactory::instance().create(name);
    if (!device->open(config)) {
      error_ = "device '" + name + "' failed to open";
      return false;
    }
    device_ = std::move(device);
    return true;
  } catch (const Error& e) {
    error_ = "device '" + name + "': " + e.what();
    return false;
  } catch (const std::exception& e) {  // a driver's own failure, reported rather than thrown on
    error_ = "device '" + name + "' failed while opening: " + e.what();
    return false;
  }
}

bool PolyDriver::close() {
  if (!device_) return true;
  const bool ok = device_->close();
  device_.reset();
  return ok;
}

}  // namespace robogene::dev
