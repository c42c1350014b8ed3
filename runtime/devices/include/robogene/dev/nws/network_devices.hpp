// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// The framework's own devices, known to DriverFactory::instance() from the start:
//   controlBoard_nws_yarp, controlboardwrapper2   serve a `subdevice` (ControlboardNws)
//   frameGrabber_nws_yarp, grabberDual            serve a camera `subdevice` (GrabberNws)
//   remote_controlboard, remote_grabber           use a served device through the network
#pragma once

#include <string>
#include <vector>

#include "robogene/dev/device_driver.hpp"
#include "robogene/dev/driver_factory.hpp"

namespace robogene::dev {

// Implemented by wrapper devices: the ports they opened, for tools to report.
class INetworkWrapper {
 public:
  virtual ~INetworkWrapper() = default;
  virtual std::vector<std::string> port_names() const = 0;
};

void add_network_devices(DriverFactory& factory);

// The wrapper that serves a device of this kind, as yarpdev picks one for a device given
// without a wrapper: "controlBoard_nws_yarp" for a control board (it has IEncoders),
// "frameGrabber_nws_yarp" for a camera (IFrameGrabberImage), "" for anything else.
std::string wrapper_for(DeviceDriver& device);

}  // namespace robogene::dev
