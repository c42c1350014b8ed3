// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// DeviceDriver: what every device implements (paper section 3.1). open() reads the parameters
// the device needs from the configuration; close() releases what open() took. The device's other
// abilities are the interfaces it also inherits (IPositionControl, IFrameGrabberImage...), found
// by PolyDriver::view() through interface_of().
#pragma once

#include <string_view>
#include <type_traits>

#include "robogene/dev/property.hpp"

namespace robogene::dev {

class DeviceDriver {
 public:
  virtual ~DeviceDriver() = default;
  // Returns false (or throws ConfigError naming the bad key) when the device cannot start.
  virtual bool open(const Searchable& config) = 0;
  virtual bool close() = 0;

  // The interface named `name` (an I*::kInterfaceName) when this device provides it other than
  // as a C++ base class, else nullptr. A device written in Python answers here: its interfaces
  // are separate C++ objects of the binding, which no dynamic_cast of this one can reach.
  virtual void* find_interface(std::string_view name) { return (void)name, nullptr; }
};

template <class T, class = void>
struct has_interface_name : std::false_type {};
template <class T>
struct has_interface_name<T, std::void_t<decltype(T::kInterfaceName)>> : std::true_type {};

// The device's `Interface`, or nullptr: a C++ base class of the device, or, for a generated
// interface (one with a kInterfaceName), what the device's find_interface answers.
template <class Interface>
Interface* interface_of(DeviceDriver& device) {
  if (auto* direct = dynamic_cast<Interface*>(&device)) return direct;
  if constexpr (has_interface_name<Interface>::value) {
    return static_cast<Interface*>(device.find_interface(Interface::kInterfaceName));
  } else {
    return nullptr;
  }
}

}  // namespace robogene::dev
