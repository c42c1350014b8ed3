// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// The generated client against the generated server, through the binary wire form: every
// request and reply is encoded to bytes and decoded again, as a port would carry them.
#include <gtest/gtest.h>

#include "in_process_board.hpp"

#include <cmath>
#include <string>
#include <utility>

#include "robogene/dev/generated/controlboard_client.hpp"
#include "robogene/dev/generated/controlboard_server.hpp"
#include "robogene/dev/poly_driver.hpp"
#include "robogene/dev/simulation_clock.hpp"

using namespace robogene;
using namespace robogene::dev;

using Remote = robogene::test::InProcessBoard;

// Paper section 3.3 again, with the device on the far side of the RPC protocol (section 3.4).
TEST(ControlboardClient, PaperSection33ThroughTheNetworkWrappers) {
  Remote remote;
  const auto listed = remote.client->check_server(true);
  ASSERT_EQ(listed.size(), 6u);  // test_motor: encoders, position, velocity, torque, PID, control mode
  EXPECT_EQ(listed[1].first, "IPositionControl");

  IPositionControl* ipos = remote.client.get();
  IVelocityControl* ivel = remote.client.get();
  EXPECT_TRUE(ipos->setRefAcceleration(0, 100));
  EXPECT_TRUE(ipos->setRefSpeed(0, 5));
  EXPECT_TRUE(ipos->positionMove(0, 40));
  EXPECT_TRUE(ivel->setRefAcceleration(1, 100));
  EXPECT_TRUE(ivel->velocityMove(1, 5));
  ASSERT_TRUE(remote.clock->advance(4.0));

  IEncoders* ienc = remote.client.get();
  std::vector<double> encs;
  ASSERT_TRUE(ienc->getEncoders(encs));
  ASSERT_EQ(encs.size(), 3u);
  EXPECT_NEAR(encs[0], 0.125 + 5 * (4.0 - 0.05), 0.01);
  EXPECT_NEAR(encs[1], 0.125 + 5 * (4.0 - 0.05), 0.01);
  EXPECT_EQ(encs[2], 0.0);
  bool done = true;
  ASSERT_TRUE(ipos->checkMotionDone(0, done));
  EXPECT_FALSE(done);
  bool all_done = true;  // [get] [dons]: one value, as YARP answers; axes 0 and 1 still move
  ASSERT_TRUE(ipos->checkMotionDone(all_done));
  EXPECT_FALSE(all_done);
  std::int32_t axes = 0;
  ASSERT_TRUE(ienc->getAxes(axes));
  EXPECT_EQ(axes, 3);
}

TEST(ControlboardClient, EnumsVectorsAndRefusals) {
  Remote remote;
  IControlMode* imode = remote.client.get();
  ASSERT_TRUE(imode->setControlModes({ControlMode::idle, ControlMode::velocity, ControlMode::position}));
  std::vector<ControlMode> modes;
  ASSERT_TRUE(imode->getControlModes(modes));
  EXPECT_EQ(modes, (std::vector<ControlMode>{ControlMode::idle, ControlMode::velocity, ControlMode::position}));
  ControlMode one{};
  ASSERT_TRUE(imode->getControlMode(1, one));
  EXPECT_EQ(one, ControlMode::velocity);
  EXPECT_FALSE(imode->setControlMode(0, ControlMode::pwm));    // the device refuses
  IPositionControl* ipos = remote.client.get();
  EXPECT_FALSE(ipos->positionMove(7, 1.0));                    // no such axis
  EXPECT_FALSE(ipos->setRefSpeeds({1.0, 2.0}));                 // 2 values for 3 axes
  ITorqueControl* itrq = remote.client.get();
  double t = 0;
  EXPECT_FALSE(itrq->getTorque(7, t));                          // no such axis
}

// Torque control and the PID store through client, bytes and server to test_motor (3 axes,
// inertia 0.01 kg m^2, damping 0.5 N m s/rad, torques within +-5 N m).
TEST(ControlboardClient, TorqueControlAndPidsSucceedThroughTheWire) {
  Remote remote;
  ITorqueControl* itrq = remote.client.get();
  IPidControl* ipid = remote.client.get();
  IControlMode* imode = remote.client.get();
  IEncoders* ienc = remote.client.get();
  IVelocityControl* ivel = remote.client.get();

  ASSERT_TRUE(itrq->setRefTorque(0, 0.5));
  ControlMode mode{};
  ASSERT_TRUE(imode->getControlMode(0, mode));
  EXPECT_EQ(mode, ControlMode::torque);
  ASSERT_TRUE(remote.clock->advance(1.0));  // 50 time constants of J/b = 0.02 s
  double t = 0, ref = 0, speed = 0, pos = 0;
  ASSERT_TRUE(itrq->getTorque(0, t) && itrq->getRefTorque(0, ref));
  EXPECT_EQ(t, 0.5);
  EXPECT_EQ(ref, 0.5);
  const double terminal = 0.5 / 0.5 * 180.0 / M_PI;  // t / b, in deg/s
  ASSERT_TRUE(ienc->getEncoderSpeed(0, speed) && ienc->getEncoder(0, pos));
  EXPECT_NEAR(speed, terminal, 1e-9);
  EXPECT_NEAR(pos, terminal * (1.0 - 0.02), 1e-9);  // w_end (t - J/b) once the lag has decayed
  double lo = 0, hi = 0;
  ASSERT_TRUE(itrq->getTorqueRange(2, lo, hi));
  EXPECT_EQ(std::make_pair(lo, hi), std::make_pair(-5.0, 5.0));
  EXPECT_FALSE(itrq->setRefTorque(1, 5.5));  // beyond the range
  EXPECT_FALSE(itrq->setRefTorques({1.0, 2.0, -6.0}));  // one bad entry: nothing changes
  std::vector<double> refs;
  ASSERT_TRUE(itrq->getRefTorques(refs));
  EXPECT_EQ(refs, (std::vector<double>{0.5, 0.0, 0.0}));

  // An axis moving at a constant velocity needs b w to overcome the damping.
  ASSERT_TRUE(ivel->setRefAcceleration(1, 100.0));
  ASSERT_TRUE(ivel->velocityMove(1, 10.0));
  ASSERT_TRUE(remote.clock->advance(1.0));
  ASSERT_TRUE(itrq->getTorque(1, t));
  EXPECT_NEAR(t, 0.5 * 10.0 * M_PI / 180.0, 1e-12);
  double out = 0;
  ASSERT_TRUE(ipid->getPidOutput(PidType::velocity, 1, out));
  EXPECT_EQ(out, t);
  double err = 1;
  ASSERT_TRUE(ipid->getPidReference(PidType::velocity, 1, ref) && ipid->getPidError(PidType::velocity, 1, err));
  EXPECT_EQ(ref, 10.0);
  EXPECT_EQ(err, 0.0);
  EXPECT_FALSE(ipid->getPidReference(PidType::torque, 1, ref));  // axis 1 runs its velocity loop
  std::vector<double> errs;
  EXPECT_FALSE(ipid->getPidErrors(PidType::position, errs));  // not every axis runs it

  // Gains: one Pid per axis and type, kept as given; a non-finite field is refused.
  const Pid gains{6000, 500, 5, 1333, 1333, 0, 8, 0.5, -0.5, 1};
  ASSERT_TRUE(ipid->setPid(PidType::position, 2, gains));
  Pid back;
  ASSERT_TRUE(ipid->getPid(PidType::position, 2, back));
  EXPECT_EQ(back, gains);
  std::vector<Pid> all;
  ASSERT_TRUE(ipid->getPids(PidType::position, all));
  EXPECT_EQ(all, (std::vector<Pid>{Pid{}, Pid{}, gains}));
  ASSERT_TRUE(ipid->getPids(PidType::torque, all));
  EXPECT_EQ(all, (std::vector<Pid>(3, Pid{})));
  Pid bad = gains;
  bad.ki = NAN;
  EXPECT_FALSE(ipid->setPid(PidType::velocity, 0, bad));
  EXPECT_FALSE(ipid->setPids(PidType::velocity, {gains, gains}));  // 2 for 3 axes
  ASSERT_TRUE(ipid->setPids(PidType::current, {gains, Pid{}, gains}));
  ASSERT_TRUE(ipid->getPids(PidType::current, all));
  EXPECT_EQ(all, (std::vector<Pid>{gains, Pid{}, gains}));
  ASSERT_TRUE(ipid->setPidErrorLimits(PidType::position, {1.0, 2.0, 3.0}));
  EXPECT_FALSE(ipid->setPidErrorLimit(PidType::position, 0, -1.0));
  std::vector<double> limits;
  ASSERT_TRUE(ipid->getPidErrorLimits(PidType::position, limits));
  EXPECT_EQ(limits, (std::vector<double>{1.0, 2.0, 3.0}));

  // The position loop of axis 2 follows its target; its error is the distance left.
  IPositionControl* ipos = remote.client.get();
  ASSERT_TRUE(ipos->positionMove(2, 20.0));
  ASSERT_TRUE(ipid->getPidError(PidType::position, 2, err));
  EXPECT_EQ(err, 20.0);
  ASSERT_TRUE(remote.clock->advance(10.0));
  ASSERT_TRUE(ipid->getPidReference(PidType::position, 2, ref) && ipid->getPidError(PidType::position, 2, err));
  EXPECT_EQ(ref, 20.0);
  EXPECT_EQ(err, 0.0);
  EXPECT_FALSE(ipid->setPidReference(PidType::position, 2, 5.0));  // not simulated
}

TEST(ControlboardClient, FingerprintMismatchIsRefusedWithAClearError) {
  Remote remote([](const Bottle& req, Bottle reply) {
    if (req.size() == 2 && req[1].is_vocab() && req[1].as_vocab() == vocab("rgif")) {
      Bottle& list = reply[2].as_list();
      list[1].as_list()[1] = Value::string("0123456789abcdef");  // IPositionControl changed
    }
    return reply;
  });
  try {
    remote.client->check_server(true);
    FAIL() << "accepted a server built from another IDL";
  } catch (const robogene::Error& e) {
    EXPECT_EQ(std::string(e.what()),
              std::string("controlboard server: interface IPositionControl has fingerprint "
                          "0123456789abcdef, this client was generated for ") +
                  IPositionControl::kFingerprint + " (the two sides were built from different IDL)");
  }
}

TEST(ControlboardClient, AYarpServerIsCheckedByItsProtocolVersionAndNeverAskedForFingerprints) {
  // A YARP 3 controlBoard_nws_yarp logs "unknown request after a VOCAB_GET: rgif" as an error:
  // a server not known to be Robogene's must never see that request.
  int asked_rgif = 0;
  auto yarp_like = [&asked_rgif](const char* minor) {
    return [minor, &asked_rgif](const Bottle& req, Bottle reply) {
      if (req.size() == 2 && req[1].as_vocab() == vocab("rgif")) {
        ++asked_rgif;
        return Bottle::from_text("[fail]");
      }
      if (req.size() == 2 && req[1].as_vocab() == vocab("prot")) {
        return Bottle::from_text(std::string("[prot] 1 ") + minor + " 0 [ok]");
      }
      return reply;
    };
  };
  Remote same(yarp_like("9"));
  EXPECT_TRUE(same.client->check_server(false).empty());
  Remote older(yarp_like("8"));
  try {
    older.client->check_server(false);
    FAIL() << "accepted protocol 1.8";
  } catch (const robogene::Error& e) {
    EXPECT_EQ(std::string(e.what()), "controlboard server speaks protocol 1.8, this client speaks 1.9");
  }
  EXPECT_EQ(asked_rgif, 0);
}

TEST(ControlboardClient, AServerThatSaysItIsRobogenesMustListItsInterfaces) {
  Remote remote([](const Bottle& req, Bottle reply) {
    if (req.size() == 2 && req[1].as_vocab() == vocab("rgif")) return Bottle::from_text("[fail]");
    return reply;
  });
  try {
    remote.client->check_server(true);
    FAIL() << "accepted a server that does not list its interfaces";
  } catch (const robogene::Error& e) {
    EXPECT_EQ(std::string(e.what()),
              "controlboard server says it is Robogene's but does not list its interfaces: [fail]");
  }
}

TEST(ControlboardClient, MalformedRepliesMakeMethodsFail) {
  Remote remote([](const Bottle& req, Bottle reply) {
    if (req.size() >= 2 && req[1].as_vocab() == vocab("enc")) return Bottle::from_text("[is] [enc]");
    if (req.size() >= 2 && req[1].as_vocab() == vocab("encs")) return Bottle::from_text("[is] [encs] 3.0");
    if (req.size() >= 2 && req[1].as_vocab() == vocab("pos")) return Bottle::from_text("[nak]");
    return reply;
  });
  IEncoders* ienc = remote.client.get();
  double v = 0;
  EXPECT_FALSE(ienc->getEncoder(0, v));   // no value
  std::vector<double> vs;
  EXPECT_FALSE(ienc->getEncoders(vs));    // not a list
  IPositionControl* ipos = remote.client.get();
  EXPECT_FALSE(ipos->positionMove(0, 1.0));
}
