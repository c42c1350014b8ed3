// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// A Robogene server says what it is through a port property; a client reads it with an admin
// message, so that a YARP server is never sent the fingerprint request (server_identity.hpp).
#include <gtest/gtest.h>

#include "nws_test_util.hpp"
#include "robogene/dev/nws/server_identity.hpp"
#include "robogene/dev/poly_driver.hpp"
#include "robogene/network.hpp"
#include "robogene/port.hpp"

using namespace robogene;
using namespace robogene::dev;
using robogene::test::LocalNameServer;

TEST(ServerIdentity, OurServersSayWhatTheyServe) {
  LocalNameServer ns;
  PolyDriver motors;
  ASSERT_TRUE(motors.open(ns.config("(device controlBoard_nws_yarp) (subdevice test_motor) (axes 2) (name /m)")))
      << motors.last_error();
  PolyDriver camera;
  ASSERT_TRUE(camera.open(ns.config("(device frameGrabber_nws_yarp) (subdevice fake_grabber) (name /cam)")))
      << camera.last_error();
  NameClient names = ns.client();
  EXPECT_TRUE(serves_robogene(names, "/m/rpc:i", "controlboard"));
  EXPECT_FALSE(serves_robogene(names, "/m/rpc:i", "grabber"));
  EXPECT_FALSE(serves_robogene(names, "/m/state:o", "controlboard"));  // answers no request
  EXPECT_TRUE(serves_robogene(names, "/cam/rpc", "grabber"));
  EXPECT_TRUE(serves_robogene(names, "/cam", "grabber"));  // YARP 3.5's remote_grabber asks here
}

TEST(ServerIdentity, AnyOtherPortIsNotOurs) {
  LocalNameServer ns;
  Port plain;
  plain.set_reader([](const Bottle&, const MessageInfo&, Bottle* reply) {
    if (reply) *reply = Bottle::from_text("[fail]");
  });
  plain.open("/plain", ns.client());
  NameClient names = ns.client();
  EXPECT_FALSE(serves_robogene(names, "/plain", "controlboard"));
  EXPECT_FALSE(serves_robogene(names, "/nobody", "controlboard"));  // not registered
  // The property is the port's own, answered to [prop] [get] as YARP's ports answer it.
  plain.set_property(kServiceProperty, Value("controlboard"));
  EXPECT_EQ(network::admin(plain.contact(), Bottle::from_text("[prop] [get] robogene_service")).to_text(),
            "controlboard");
  EXPECT_TRUE(serves_robogene(names, "/plain", "controlboard"));
}
