// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// DeviceDriver: what every device implements (paper section 3.1). open() reads the parameters
// the device needs from the configuration; close() releases what open() took. The device's other
// abilities are the interfaces it also inherits (IPositionControl, IFrameGrabberImage...), found
// by PolyDriver::view().
#pragma once

#include "robogene/dev/property.hpp"

namespace robogene::dev {

class DeviceDriver {
 public:
  virtual ~DeviceDriver() = default;
  // Returns false (or throws ConfigError naming the bad key) when the device cannot start.
  virtual bool open(const Searchable& config) = 0;
  virtual bool close() = 0;
};

}  // namespace robogene::dev
