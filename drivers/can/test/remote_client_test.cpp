// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// The acceptance: a simulated head on the virtual bus, the robogene_can driver served by
// controlBoard_nws_yarp (what `robogene dev --device robogene_can --from head.ini` does), and a
// remote_controlboard client that moves every joint through position and velocity commands with
// its encoders tracking, as it would drive test_motor.
#include <cmath>
#include <thread>

#include <gtest/gtest.h>

#include "head_rig.hpp"
#include "robogene/can/sim/simulated_head.hpp"
#include "robogene/can/virtual_bus.hpp"
#include "robogene/dev/generated/icontrolmode.hpp"
#include "robogene/dev/generated/iencoders.hpp"
#include "robogene/dev/generated/ipositioncontrol.hpp"
#include "robogene/dev/generated/ivelocitycontrol.hpp"
#include "robogene/dev/poly_driver.hpp"
#include "robogene/name/local_name_server.hpp"
#include "test_bus_dir.hpp"

namespace robogene::can {
namespace {

TEST(CanHeadRemoteClient, MovesEveryJointThroughTheNetworkWithEncodersTracking) {
  testing::TempBusDir dir;
  name::LocalNameServer ns;
  const HeadConfig head = testing::head_config();
  sim::SimulatedHead sim(head, std::make_unique<VirtualBus>("remote"));

  dev::Property served = testing::driver_config("virtual:remote");
  served.put("device", Value::string("controlBoard_nws_yarp"));
  served.put("subdevice", Value::string("robogene_can"));
  served.put("name", Value::string("/head"));
  served.put("server", Value::string(ns.address()));
  dev::PolyDriver server;
  ASSERT_TRUE(server.open(served)) << server.last_error();

  dev::Property client_config = dev::Property::from_bottle(
      Bottle::from_text("(device remote_controlboard) (remote /head) (local /client)"), "client");
  client_config.put("server", Value::string(ns.address()));
  dev::PolyDriver client;
  ASSERT_TRUE(client.open(client_config)) << client.last_error();
  dev::IEncoders* enc = nullptr;
  dev::IPositionControl* pos = nullptr;
  dev::IVelocityControl* vel = nullptr;
  dev::IControlMode* mode = nullptr;
  ASSERT_TRUE(client.view(enc) && client.view(pos) && client.view(vel) && client.view(mode));

  std::int32_t axes = 0;
  ASSERT_TRUE(pos->getAxes(axes));
  ASSERT_EQ(axes, static_cast<std::int32_t>(head.joints.size()));
  for (std::size_t j = 0; j < head.joints.size(); ++j) {
    const JointConfig& jc = head.joints[j];
    const int i = static_cast<int>(j);
    const double target = jc.min + 0.3 * (jc.max - jc.min);
    ASSERT_TRUE(pos->setRefSpeed(i, 50.0));
    ASSERT_TRUE(pos->positionMove(i, target));
    ASSERT_TRUE(testing::eventually(5.0, [&] {
      double v = 0;
      return enc->getEncoder(i, v) && std::fabs(v - target) < 0.2;
    })) << jc.name << " did not reach " << target;

    ASSERT_TRUE(vel->velocityMove(i, 10.0));
    double start = 0, now = 0;
    ASSERT_TRUE(enc->getEncoder(i, start));
    ASSERT_TRUE(testing::eventually(5.0, [&] { return enc->getEncoder(i, now) && now - start > 3.0; }))
        << jc.name << " did not follow a velocity move";
    dev::ControlMode m{};
    ASSERT_TRUE(mode->getControlMode(i, m));
    EXPECT_EQ(m, dev::ControlMode::velocity) << jc.name;
    ASSERT_TRUE(vel->velocityMove(i, 0.0));
  }
  client.close();
  server.close();
}

}  // namespace
}  // namespace robogene::can
