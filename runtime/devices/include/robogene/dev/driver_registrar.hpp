// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// Registers a driver with DriverFactory::instance() while the program starts, so a driver in
// drivers/ needs no list to be edited elsewhere. The drivers are linked as object files (the
// robogene_drivers OBJECT library), never from a static archive, whose linker would drop a
// registrar nothing refers to.
//
//   ROBOGENE_REGISTER_DRIVER(test_motor, "simulated control board", TestMotor)
#pragma once

#include <memory>
#include <string>

#include "robogene/dev/driver_factory.hpp"

namespace robogene::dev {

struct DriverRegistrar {
  DriverRegistrar(std::string name, std::string description, DriverFactory::Creator create) {
    DriverFactory::instance().add(std::move(name), std::move(description), std::move(create));
  }
};

}  // namespace robogene::dev

#define ROBOGENE_REGISTER_DRIVER(name, description, Class)                      \
  static const ::robogene::dev::DriverRegistrar robogene_registrar_##name{     \
      #name, description,                                                       \
      []() -> std::unique_ptr<::robogene::dev::DeviceDriver> { return std::make_unique<Class>(); }}
