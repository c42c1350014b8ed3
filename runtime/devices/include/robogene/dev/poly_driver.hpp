// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// PolyDriver: owns one device created by the factory and hands out its interfaces (paper
// section 3.2). view() is interface_of() the requested interface (a dynamic_cast, or what a
// device written in Python answers), so it yields nullptr when the device does not implement it.
//
//   PolyDriver device;
//   device.open("test_motor");
//   IPositionControl* ipos = nullptr;
//   device.view(ipos);
#pragma once

#include <memory>
#include <string>

#include "robogene/dev/device_driver.hpp"
#include "robogene/dev/driver_factory.hpp"

namespace robogene::dev {

class PolyDriver {
 public:
  PolyDriver() = default;
  explicit PolyDriver(const Searchable& config) { open(config); }
  ~PolyDriver() { close(); }
  PolyDriver(const PolyDriver&) = delete;
  PolyDriver& operator=(const PolyDriver&) = delete;

  // Opens the driver named `device` with default parameters.
  bool open(const std::string& device);
  // Opens the driver named by the `device` key, passing it the whole configuration.
  bool open(const Searchable& config);
  // Opens the driver named `device`, passing it `config` (a wrapper opens its subdevice so).
  bool open(const std::string& device, const Searchable& config) { return open_with(device, config); }
  // Closes the device (if open) and forgets it; views obtained earlier become dangling.
  bool close();
  // Forgets the open device without closing it and hands it over (nullptr when none): for a
  // caller that must keep the device's memory alive past close(), as the Python binding does
  // while views of it are still referenced.
  std::unique_ptr<DeviceDriver> release() { return std::move(device_); }
  bool is_valid() const { return device_ != nullptr; }
  // The open device (nullptr when none), for code that serves it whole (network wrappers).
  DeviceDriver* device() const { return device_.get(); }
  // Why the last open() failed ("" after a success).
  const std::string& last_error() const { return error_; }

  template <class Interface>
  bool view(Interface*& out) const {
    out = device_ ? interface_of<Interface>(*device_) : nullptr;
    return out != nullptr;
  }

 private:
  bool open_with(const std::string& name, const Searchable& config);

  std::unique_ptr<DeviceDriver> device_;
  std::string error_;
};

}  // namespace robogene::dev
