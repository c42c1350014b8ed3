// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// ISimulationClock: the time a simulated device (test_motor, fake_grabber) lives in. Opened with
// `clock manual`, the device's time only moves when advance() is called, so tests replay motion
// exactly; with `clock wall` (the default) it follows a monotonic wall clock.
#pragma once

namespace robogene::dev {

class ISimulationClock {
 public:
  virtual ~ISimulationClock() = default;
  virtual double now() = 0;                   // seconds since the device opened
  virtual bool advance(double seconds) = 0;   // false with a wall clock or a negative step
};

}  // namespace robogene::dev
