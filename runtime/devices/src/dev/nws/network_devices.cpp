// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "robogene/dev/nws/network_devices.hpp"

#include <memory>

#include "robogene/dev/generated/interfaces.hpp"
#include "robogene/dev/nws/controlboard_nws.hpp"
#include "robogene/dev/nws/grabber_nws.hpp"
#include "robogene/dev/nws/remote_controlboard.hpp"
#include "robogene/dev/nws/remote_grabber.hpp"
#include "robogene/dev/poly_driver.hpp"

namespace robogene::dev {
namespace {

// A server device: opens the device named by `subdevice` with the same configuration and puts
// it on the network with Server (ControlboardNws or GrabberNws).
template <class Server>
class WrapperDevice final : public DeviceDriver, public INetworkWrapper {
 public:
  bool open(const Searchable& config) override {
    const std::string sub = config.get_string("subdevice", "");
    if (sub.empty()) {
      throw ConfigError(config.source() + ": no 'subdevice' key naming the device to serve");
    }
    if (!subdevice_.open(sub, config)) throw Error("subdevice: " + subdevice_.last_error());
    try {
      server_.open(*subdevice_.device(), config);
    } catch (...) {
      subdevice_.close();
      throw;
    }
    return true;
  }
  bool close() override {
    server_.close();
    return subdevice_.close();
  }
  std::vector<std::string> port_names() const override { return server_.port_names(); }

 private:
  PolyDriver subdevice_;
  Server server_;
};

template <class Device>
DriverFactory::Creator make() {
  return [] { return std::unique_ptr<DeviceDriver>(std::make_unique<Device>()); };
}

}  // namespace

void add_network_devices(DriverFactory& factory) {
  factory.add("controlBoard_nws_yarp", "serves a control board `subdevice` on <name>/rpc:i, command:i, state:o, stateExt:o",
              make<WrapperDevice<ControlboardNws>>());
  factory.add("controlboardwrapper2", "YARP 3.5's name for controlBoard_nws_yarp",
              make<WrapperDevice<ControlboardNws>>());
  factory.add("frameGrabber_nws_yarp", "serves a camera `subdevice` on <name>/rpc and <name> (the images), as YARP 3.5 does",
              make<WrapperDevice<GrabberNws>>());
  factory.add("grabberDual", "YARP 3.5's name for frameGrabber_nws_yarp", make<WrapperDevice<GrabberNws>>());
  factory.add("remote_controlboard", "a control board served elsewhere (remote, local, carrier)",
              make<RemoteControlboard>());
  factory.add("remote_grabber", "a camera served elsewhere (remote, local, stream)", make<RemoteGrabber>());
}

std::string wrapper_for(DeviceDriver& device) {
  if (interface_of<IEncoders>(device)) return "controlBoard_nws_yarp";
  if (interface_of<IFrameGrabberImage>(device)) return "frameGrabber_nws_yarp";
  return "";
}

}  // namespace robogene::dev
