// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// libFuzzer target: device RPC dispatch. A bottle from the wire (binary form; the first byte
// picks the service) goes to the generated controlboard server in front of a test_motor, as
// <name>/rpc:i and <name>/command:i hand it over, or to the grabber server in front of a
// fake_grabber. Properties: respond() never throws and always answers (YARP's [ok] / [fail] /
// [is] ... / [nak] shapes, never an empty reply); the reply has a binary form that decodes.
#include <cstddef>
#include <cstdint>
#include <memory>

#include "robogene/bottle.hpp"
#include "robogene/dev/generated/controlboard_server.hpp"
#include "robogene/dev/generated/grabber_server.hpp"
#include "robogene/dev/poly_driver.hpp"
#include "robogene/dev/property.hpp"
#include "robogene/error.hpp"
#include "robogene/log.hpp"

using namespace robogene;
using namespace robogene::dev;

namespace {

struct Devices {
  PolyDriver motor, grabber;
  std::unique_ptr<ControlboardServer> controlboard;
  std::unique_ptr<GrabberServer> camera;
  Devices() {
    log::set_level(log::Level::Error);
    if (!motor.open(Property::from_command_line({"--device", "test_motor", "--axes", "4", "--clock", "manual"})) ||
        !grabber.open(Property::from_command_line({"--device", "fake_grabber", "--width", "32", "--height", "24"}))) {
      __builtin_trap();
    }
    DeviceDriver* m = nullptr;
    DeviceDriver* g = nullptr;
    if (!motor.view(m) || !grabber.view(g)) __builtin_trap();
    controlboard = std::make_unique<ControlboardServer>(*m);
    camera = std::make_unique<GrabberServer>(*g);
  }
};

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static Devices devices;
  if (size < 1) return 0;
  Bottle request;
  try {
    DecodeLimits limits;
    limits.max_bytes = 1u << 16;
    request = Bottle::from_bytes(data + 1, size - 1, limits);
  } catch (const ParseError&) {
    return 0;  // the port drops it before any device sees it
  }
  Bottle reply;
  switch (data[0] % 3) {
    case 0: reply = devices.controlboard->respond(request); break;
    case 1: (void)devices.controlboard->command(request); return 0;
    default: reply = devices.camera->respond(request); break;
  }
  if (reply.empty()) __builtin_trap();
  if (Bottle::from_bytes(reply.to_bytes()).size() != reply.size()) __builtin_trap();
  return 0;
}
