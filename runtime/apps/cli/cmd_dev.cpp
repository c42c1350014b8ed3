// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// `robogene dev` (the paper's yarpdev): builds a device configuration from --from FILE.ini and
// the command line (`--key value`, later wins), opens the device and serves it on the network
// until SIGINT / SIGTERM, then closes it, unregistering its ports.
//   --device test_motor --name /motors            test_motor wrapped by controlBoard_nws_yarp
//   --device controlBoard_nws_yarp --subdevice test_motor --name /motors    the same, explicitly
#include <cstdio>
#include <memory>
#include <optional>
#include <string>

#include "commands.hpp"
#include "robogene/dev/nws/controlboard_nws.hpp"
#include "robogene/dev/nws/grabber_nws.hpp"
#include "robogene/dev/nws/network_devices.hpp"
#include "robogene/dev/poly_driver.hpp"
#include "robogene/error.hpp"

namespace robogene::cli {
namespace {

dev::Property device_config(Args& args, const net::Endpoint& server) {
  dev::Property given = dev::Property::from_command_line(args.rest());
  dev::Property config("robogene dev configuration");
  if (given.check("from")) {
    const std::string file = given.get_string("from", "");
    if (file.empty()) throw UsageError("--from needs the name of an .ini file");
    config = dev::Property::from_ini_file(file);
  }
  config.merge(given);
  config.put("server", Value::string(server.host + ":" + std::to_string(server.port)),
             "robogene dev --server");
  if (config.get_string("device", "").empty()) {
    throw UsageError("no device given: use --device NAME (or a `device` line in the --from file)");
  }
  return config;
}

std::string joined(const std::vector<std::string>& names) {
  std::string out;
  for (const auto& n : names) out += (out.empty() ? "" : " ") + n;
  return out;
}

}  // namespace

int cmd_dev(Args& args) {
  const net::Endpoint server = name_server_address(args);
  const dev::Property config = device_config(args, server);
  const std::string device_name = config.get_string("device", "");

  dev::PolyDriver device;
  if (!device.open(config)) throw Error(device.last_error());

  // A device that is not itself a server is wrapped by the one that fits it, as yarpdev does.
  std::unique_ptr<dev::ControlboardNws> board;
  std::unique_ptr<dev::GrabberNws> camera;
  std::vector<std::string> ports;
  dev::INetworkWrapper* wrapper = nullptr;
  if (device.view(wrapper)) {
    ports = wrapper->port_names();
  } else {
    const std::string kind = dev::wrapper_for(*device.device());
    try {
      if (kind == "controlBoard_nws_yarp") {
        board = std::make_unique<dev::ControlboardNws>();
        board->open(*device.device(), config);
        ports = board->port_names();
      } else if (kind == "frameGrabber_nws_yarp") {
        camera = std::make_unique<dev::GrabberNws>();
        camera->open(*device.device(), config);
        ports = camera->port_names();
      } else {
        throw Error("device '" + device_name +
                    "' cannot be served: it is neither a control board nor a camera, and not a wrapper");
      }
    } catch (...) {
      device.close();
      throw;
    }
  }
  std::fprintf(stderr, "robogene dev: %s serving on %s\n", device_name.c_str(), joined(ports).c_str());
  std::fflush(stderr);

  wait_for_shutdown_signal();
  if (board) board->close();
  if (camera) camera->close();
  device.close();
  std::fprintf(stderr, "robogene dev: %s closed\n", device_name.c_str());
  return 0;
}

}  // namespace robogene::cli
