// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "fake_grabber.hpp"
#include "robogene/dev/driver_factory.hpp"
#include "test_motor.hpp"

namespace robogene::dev {

void add_builtin_drivers(DriverFactory& factory) {
  factory.add("test_motor", "simulated control board: position and velocity moves, encoders",
              &TestMotor::create);
  factory.add("fake_grabber", "simulated camera: a moving RGB test pattern", &FakeGrabber::create);
}

}  // namespace robogene::dev
