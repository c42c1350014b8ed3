// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <thread>

#include "robogene/dev/generated/interfaces.hpp"
#include "robogene/dev/poly_driver.hpp"
#include "robogene/dev/simulation_clock.hpp"

using namespace robogene::dev;

namespace {

// Position reached t seconds after a rest-to-rest move over `distance` starts, with speed v and
// acceleration a: a trapezoid, or a triangle when the move is too short to reach v.
double profile(double t, double v, double a, double distance) {
  const double peak = std::min(v, std::sqrt(a * distance));
  const double ramp = peak / a;
  const double total = distance / peak + ramp;
  if (t <= 0) return 0;
  if (t < ramp) return 0.5 * a * t * t;
  if (t < total - ramp) return 0.5 * a * ramp * ramp + peak * (t - ramp);
  if (t < total) return distance - 0.5 * a * (total - t) * (total - t);
  return distance;
}

// Integration uses 1 ms steps; positions agree with the analytic profile to this much.
constexpr double kTol = 0.01;

struct ManualMotor {
  PolyDriver device;
  IPositionControl* ipos = nullptr;
  IVelocityControl* ivel = nullptr;
  IEncoders* ienc = nullptr;
  IControlMode* imode = nullptr;
  ISimulationClock* clock = nullptr;
  explicit ManualMotor(int axes = 4) {
    Property p;
    p.put("device", robogene::Value::string("test_motor"));
    p.put("axes", axes);
    p.put("clock", robogene::Value::string("manual"));
    EXPECT_TRUE(device.open(p)) << device.last_error();
    EXPECT_TRUE(device.view(ipos) && device.view(ivel) && device.view(ienc) &&
                device.view(imode) && device.view(clock));
  }
  double enc(int j) {
    double v = NAN;
    EXPECT_TRUE(ienc->getEncoder(j, v));
    return v;
  }
};

}  // namespace

// Paper section 3.3, as written, on the wall clock: the encoders follow the commanded motion.
TEST(TestMotor, PaperSection33AsWritten) {
  PolyDriver device;
  device.open("test_motor");

  IPositionControl* ipos = 0;
  device.view(ipos);

  IVelocityControl* ivel = 0;
  device.view(ivel);

  ASSERT_NE(ipos, nullptr);
  ASSERT_NE(ivel, nullptr);

  const auto start = std::chrono::steady_clock::now();
  ipos->setRefAcceleration(0, 100);
  ipos->setRefSpeed(0, 5);
  ipos->positionMove(0, 40);

  ivel->setRefAcceleration(1, 100);
  ivel->velocityMove(1, 5);

  std::this_thread::sleep_for(std::chrono::milliseconds(300));
  IEncoders* ienc = nullptr;
  ASSERT_TRUE(device.view(ienc));
  std::vector<double> encs;
  ASSERT_TRUE(ienc->getEncoders(encs));
  const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  ASSERT_EQ(encs.size(), 4u);
  // Between 0.3 s and `elapsed` of motion has been simulated, whatever the machine's load.
  EXPECT_GE(encs[0], profile(0.3, 5, 100, 40) - kTol);
  EXPECT_LE(encs[0], profile(elapsed, 5, 100, 40) + kTol);
  EXPECT_GE(encs[1], profile(0.3, 5, 100, 1e9) - kTol);
  EXPECT_LE(encs[1], profile(elapsed, 5, 100, 1e9) + kTol);
  EXPECT_EQ(encs[2], 0.0);
  EXPECT_EQ(encs[3], 0.0);
  bool done = true;
  ASSERT_TRUE(ipos->checkMotionDone(0, done));
  EXPECT_FALSE(done);  // 40 deg at 5 deg/s takes 8 s
}

TEST(TestMotor, PositionMoveFollowsRefSpeedAndAccelerationInSimulatedTime) {
  ManualMotor m;
  ASSERT_TRUE(m.ipos->setRefAcceleration(0, 100));
  ASSERT_TRUE(m.ipos->setRefSpeed(0, 5));
  ASSERT_TRUE(m.ipos->positionMove(0, 40));
  double peak_speed = 0, peak_acc = 0;
  for (int step = 1; step <= 900; ++step) {  // 9 s in 10 ms steps
    ASSERT_TRUE(m.clock->advance(0.01));
    const double t = step * 0.01;
    EXPECT_NEAR(m.enc(0), profile(t, 5, 100, 40), kTol) << "at t=" << t;
    double sp = 0, acc = 0;
    ASSERT_TRUE(m.ienc->getEncoderSpeed(0, sp));
    ASSERT_TRUE(m.ienc->getEncoderAcceleration(0, acc));
    peak_speed = std::max(peak_speed, std::fabs(sp));
    peak_acc = std::max(peak_acc, std::fabs(acc));
  }
  EXPECT_EQ(m.enc(0), 40.0);  // arrives exactly, then rests
  EXPECT_LE(peak_speed, 5.0 + 1e-9);
  EXPECT_LE(peak_acc, 100.0 + 1e-6);
  EXPECT_NEAR(peak_speed, 5.0, 1e-9);
  bool done = false;
  ASSERT_TRUE(m.ipos->checkMotionDone(0, done));
  EXPECT_TRUE(done);
  double target = 0;
  ASSERT_TRUE(m.ipos->getTargetPosition(0, target));
  EXPECT_EQ(target, 40.0);
  EXPECT_EQ(m.enc(1), 0.0);
}

TEST(TestMotor, ShortMoveIsATriangleAndBackwardsMovesWork) {
  ManualMotor m;
  ASSERT_TRUE(m.ipos->setRefAcceleration(2, 10));
  ASSERT_TRUE(m.ipos->setRefSpeed(2, 100));  // never reached: 1 deg at 10 deg/s^2
  ASSERT_TRUE(m.ipos->positionMove(2, -1));
  ASSERT_TRUE(m.clock->advance(std::sqrt(0.1)));  // halfway in time: accelerated over 0.5 deg
  EXPECT_NEAR(m.enc(2), -0.5, kTol);
  ASSERT_TRUE(m.clock->advance(std::sqrt(0.1) + 0.05));
  EXPECT_EQ(m.enc(2), -1.0);
}

TEST(TestMotor, VelocityMoveRampsAtRefAccelerationAndStopBrakes) {
  ManualMotor m;
  ASSERT_TRUE(m.ivel->setRefAcceleration(1, 100));
  ASSERT_TRUE(m.ivel->velocityMove(1, 5));
  ASSERT_TRUE(m.clock->advance(10.0));
  EXPECT_NEAR(m.enc(1), 5.0 * 10.0 - 5.0 * 5.0 / (2 * 100), kTol);
  double ref = 0;
  ASSERT_TRUE(m.ivel->getRefVelocity(1, ref));
  EXPECT_EQ(ref, 5.0);
  ControlMode mode{};
  ASSERT_TRUE(m.imode->getControlMode(1, mode));
  EXPECT_EQ(mode, ControlMode::velocity);
  const double before = m.enc(1);
  ASSERT_TRUE(m.ivel->stop(1));
  ASSERT_TRUE(m.clock->advance(1.0));
  EXPECT_NEAR(m.enc(1), before + 5.0 * 5.0 / (2 * 100), kTol);  // braked over v^2/2a
  double sp = 1;
  ASSERT_TRUE(m.ienc->getEncoderSpeed(1, sp));
  EXPECT_EQ(sp, 0.0);
}

TEST(TestMotor, StopDuringAPositionMoveBrakesShortOfTheTarget) {
  ManualMotor m;
  ASSERT_TRUE(m.ipos->setRefSpeed(0, 10));
  ASSERT_TRUE(m.ipos->setRefAcceleration(0, 20));
  ASSERT_TRUE(m.ipos->positionMove(0, 100));
  ASSERT_TRUE(m.clock->advance(2.0));
  const double at_stop = m.enc(0);
  ASSERT_TRUE(m.ipos->stop(0));
  double target = 0;
  ASSERT_TRUE(m.ipos->getTargetPosition(0, target));
  EXPECT_NEAR(target, at_stop + 10.0 * 10.0 / (2 * 20), 1e-9);
  ASSERT_TRUE(m.clock->advance(2.0));
  EXPECT_NEAR(m.enc(0), target, kTol);
  bool done = false;
  ASSERT_TRUE(m.ipos->checkMotionDone(0, done));
  EXPECT_TRUE(done);
}

TEST(TestMotor, AllAxesFormsAndRelativeMoves) {
  ManualMotor m(3);
  ASSERT_TRUE(m.ipos->setRefSpeeds({10, 20, 30}));
  ASSERT_TRUE(m.ipos->setRefAccelerations({1000, 1000, 1000}));
  ASSERT_TRUE(m.ipos->positionMove(std::vector<double>{1, -2, 3}));
  ASSERT_TRUE(m.ipos->relativeMove(std::vector<double>{1, 1, 1}));  // relative to the targets
  ASSERT_TRUE(m.clock->advance(5));
  std::vector<double> encs;
  ASSERT_TRUE(m.ienc->getEncoders(encs));
  EXPECT_EQ(encs, (std::vector<double>{2, -1, 4}));
  bool done = false;
  ASSERT_TRUE(m.ipos->checkMotionDone(done));
  EXPECT_TRUE(done);
  std::vector<double> speeds;
  ASSERT_TRUE(m.ipos->getRefSpeeds(speeds));
  EXPECT_EQ(speeds, (std::vector<double>{10, 20, 30}));
}

TEST(TestMotor, BadRequestsAreRefusedAndChangeNothing) {
  ManualMotor m(2);
  double v = 0;
  EXPECT_FALSE(m.ipos->positionMove(2, 1.0));
  EXPECT_FALSE(m.ipos->positionMove(-1, 1.0));
  EXPECT_FALSE(m.ienc->getEncoder(5, v));
  EXPECT_FALSE(m.ipos->positionMove(0, NAN));
  EXPECT_FALSE(m.ipos->setRefSpeed(0, 0.0));
  EXPECT_FALSE(m.ipos->setRefSpeed(0, -3.0));
  EXPECT_FALSE(m.ipos->setRefAcceleration(0, INFINITY));
  EXPECT_FALSE(m.ipos->positionMove(std::vector<double>{1, 2, 3}));  // 3 values for 2 axes
  EXPECT_FALSE(m.ipos->setRefSpeeds({5, -1}));  // second is bad: the first must not apply
  ASSERT_TRUE(m.ipos->getRefSpeed(0, v));
  EXPECT_EQ(v, 10.0);  // the configured default
  EXPECT_FALSE(m.imode->setControlMode(0, ControlMode::current));  // not simulated
  EXPECT_FALSE(m.clock->advance(-1));
  ASSERT_TRUE(m.clock->advance(1));
  EXPECT_EQ(m.enc(0), 0.0);
  EXPECT_EQ(m.enc(1), 0.0);
}

TEST(TestMotor, ControlModesIdleAndEncoderResets) {
  ManualMotor m(2);
  std::vector<ControlMode> modes;
  ASSERT_TRUE(m.imode->getControlModes(modes));
  EXPECT_EQ(modes, (std::vector<ControlMode>{ControlMode::position, ControlMode::position}));
  ASSERT_TRUE(m.ivel->velocityMove(0, 3));
  ASSERT_TRUE(m.clock->advance(1));
  ASSERT_TRUE(m.imode->setControlMode(0, ControlMode::idle));
  const double frozen = m.enc(0);
  ASSERT_TRUE(m.clock->advance(1));
  EXPECT_EQ(m.enc(0), frozen);
  ASSERT_TRUE(m.imode->setControlModes({ControlMode::position, ControlMode::velocity}));
  ASSERT_TRUE(m.imode->getControlModes(modes));
  EXPECT_EQ(modes, (std::vector<ControlMode>{ControlMode::position, ControlMode::velocity}));
  ASSERT_TRUE(m.ienc->setEncoder(0, 10.0));
  EXPECT_EQ(m.enc(0), 10.0);
  ASSERT_TRUE(m.ienc->resetEncoders());
  EXPECT_EQ(m.enc(0), 0.0);
  ASSERT_TRUE(m.clock->advance(1));
  EXPECT_EQ(m.enc(0), 0.0);  // holding: the reset moved the target along
}

// Torque control: the axis is a damped rigid body, J dw/dt = t - b w (positions in degrees).
TEST(TestMotor, TorqueModeIsADampedBodyAndModesHandOver) {
  PolyDriver device(Property::from_command_line({"--device", "test_motor", "--axes", "2", "--clock", "manual",
                                                 "--inertia", "0.02", "--damping", "0.1", "--max_torque", "2"}));
  ITorqueControl* itrq = nullptr;
  IControlMode* imode = nullptr;
  IEncoders* ienc = nullptr;
  ISimulationClock* clock = nullptr;
  ASSERT_TRUE(device.view(itrq) && device.view(imode) && device.view(ienc) && device.view(clock));
  const double deg = 180.0 / M_PI;
  const double tau = 0.02 / 0.1;  // J / b, seconds

  ASSERT_TRUE(imode->setControlMode(0, ControlMode::torque));
  double ref = 1;
  ASSERT_TRUE(itrq->getRefTorque(0, ref));
  EXPECT_EQ(ref, 0.0);  // entering torque mode exerts nothing until asked
  ASSERT_TRUE(itrq->setRefTorque(0, 1.0));
  ASSERT_TRUE(clock->advance(0.3));
  double w = 0, x = 0, acc = 0;
  ASSERT_TRUE(ienc->getEncoderSpeed(0, w) && ienc->getEncoder(0, x) && ienc->getEncoderAcceleration(0, acc));
  const double w_end = 1.0 / 0.1 * deg;
  EXPECT_NEAR(w, w_end * (1 - std::exp(-0.3 / tau)), 1e-9);
  EXPECT_NEAR(x, w_end * (0.3 - tau * (1 - std::exp(-0.3 / tau))), 1e-9);
  EXPECT_NEAR(acc, (1.0 - 0.1 * w / deg) / 0.02 * deg, 1e-9);  // (t - b w) / J

  // stop() takes the torque away: damping brings the axis to rest.
  IPositionControl* ipos = nullptr;
  ASSERT_TRUE(device.view(ipos));
  ASSERT_TRUE(ipos->stop(0));
  ASSERT_TRUE(clock->advance(20 * tau));
  ASSERT_TRUE(ienc->getEncoderSpeed(0, w));
  EXPECT_LT(std::fabs(w), 1e-6);

  // Back to position mode: the axis holds where it is.
  ASSERT_TRUE(itrq->setRefTorque(0, -2.0));
  ASSERT_TRUE(clock->advance(0.5));
  ASSERT_TRUE(imode->setControlMode(0, ControlMode::position));
  ASSERT_TRUE(clock->advance(60.0));
  double target = 0;
  ASSERT_TRUE(ipos->getTargetPosition(0, target) && ienc->getEncoder(0, x));
  EXPECT_EQ(x, target);
  double t = 1;
  ASSERT_TRUE(itrq->getTorque(0, t));
  EXPECT_EQ(t, 0.0);  // at rest, position control needs no torque
  EXPECT_FALSE(itrq->setRefTorque(1, 2.5));  // beyond max_torque

  PolyDriver bad;
  EXPECT_FALSE(bad.open(Property::from_command_line({"--device", "test_motor", "--damping", "0"})));
  EXPECT_NE(bad.last_error().find("damping"), std::string::npos) << bad.last_error();
}
