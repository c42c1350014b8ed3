// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// A three-axis test_motor on a manual clock, the generated server over it, and a generated client
// whose every request and reply goes through the binary wire form, as a port would carry them.
// `tamper` may rewrite a reply on its way back; `exchanges` counts the requests.
#pragma once

#include <functional>
#include <memory>

#include <gtest/gtest.h>

#include "robogene/dev/generated/controlboard_client.hpp"
#include "robogene/dev/generated/controlboard_server.hpp"
#include "robogene/dev/poly_driver.hpp"
#include "robogene/dev/simulation_clock.hpp"

namespace robogene::test {

struct InProcessBoard {
  dev::PolyDriver device;
  std::unique_ptr<dev::ControlboardServer> server;
  std::unique_ptr<dev::ControlboardClient> client;
  dev::ISimulationClock* clock = nullptr;
  int exchanges = 0;

  explicit InProcessBoard(std::function<Bottle(const Bottle&, Bottle)> tamper = nullptr) {
    EXPECT_TRUE(device.open(dev::Property::from_command_line(
        {"--device", "test_motor", "--axes", "3", "--clock", "manual"})));
    dev::DeviceDriver* driver = nullptr;
    EXPECT_TRUE(device.view(driver) && device.view(clock));
    server = std::make_unique<dev::ControlboardServer>(*driver);
    client = std::make_unique<dev::ControlboardClient>([this, tamper](const Bottle& req, Bottle& reply) {
      ++exchanges;
      const Bottle on_server = Bottle::from_bytes(req.to_bytes());
      Bottle answer = server->respond(on_server);
      if (tamper) answer = tamper(on_server, answer);
      reply = Bottle::from_bytes(answer.to_bytes());
      return true;
    });
  }
};

}  // namespace robogene::test
