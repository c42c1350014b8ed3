// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// interface_of(): a device whose interfaces are not its C++ base classes (as a device written in
// Python is, through the binding) is viewed, served and encoded through find_interface.
#include <gtest/gtest.h>

#include <memory>
#include <string>
#include <vector>

#include "robogene/dev/generated/controlboard_server.hpp"
#include "robogene/dev/generated/interfaces.hpp"
#include "robogene/dev/joint_data.hpp"
#include "robogene/dev/nws/network_devices.hpp"
#include "robogene/dev/poly_driver.hpp"

using namespace robogene::dev;

namespace {

class Encoders final : public IEncoders {
 public:
  bool getAxes(std::int32_t& n) override { return n = 2, true; }
  bool getEncoder(int j, double& v) override { return j >= 0 && j < 2 && (v = 10.0 * (j + 1), true); }
  bool getEncoders(std::vector<double>& vs) override { return vs = {10.0, 20.0}, true; }
  bool getEncoderSpeed(int, double& v) override { return v = 0.0, true; }
  bool getEncoderSpeeds(std::vector<double>& vs) override { return vs = {0.0, 0.0}, true; }
  bool getEncoderAcceleration(int, double& v) override { return v = 0.0, true; }
  bool getEncoderAccelerations(std::vector<double>& vs) override { return vs = {0.0, 0.0}, true; }
  bool resetEncoder(int) override { return false; }
  bool resetEncoders() override { return false; }
  bool setEncoder(int, double) override { return false; }
  bool setEncoders(const std::vector<double>&) override { return false; }
};

// A device that derives from no interface and hands out a separate IEncoders by name.
class CompositeDevice final : public DeviceDriver {
 public:
  bool open(const Searchable&) override { return true; }
  bool close() override { return true; }
  void* find_interface(std::string_view name) override {
    return name == IEncoders::kInterfaceName ? static_cast<IEncoders*>(&encoders_) : nullptr;
  }

 private:
  Encoders encoders_;
};

void add_composite_device() {
  auto& factory = DriverFactory::instance();
  if (!factory.has("composite_test_device")) {
    factory.add("composite_test_device", "interfaces by find_interface",
                [] { return std::unique_ptr<DeviceDriver>(std::make_unique<CompositeDevice>()); });
  }
}

}  // namespace

TEST(InterfaceOf, PolyDriverViewsWhatFindInterfaceAnswers) {
  add_composite_device();
  PolyDriver device;
  ASSERT_TRUE(device.open("composite_test_device")) << device.last_error();
  IEncoders* enc = nullptr;
  ASSERT_TRUE(device.view(enc));
  double v = 0;
  EXPECT_TRUE(enc->getEncoder(1, v));
  EXPECT_EQ(v, 20.0);
  IPositionControl* pos = nullptr;
  EXPECT_FALSE(device.view(pos));  // not answered: absent, as a failed dynamic_cast is
  INetworkWrapper* wrapper = nullptr;
  EXPECT_FALSE(device.view(wrapper));  // no kInterfaceName: dynamic_cast only
}

TEST(InterfaceOf, TheServerTheWrapperChoiceAndJointDataSeeTheAnsweredInterface) {
  CompositeDevice device;
  EXPECT_EQ(wrapper_for(device), "controlBoard_nws_yarp");
  ControlboardServer server(device);
  ASSERT_EQ(server.interfaces().size(), 1u);
  EXPECT_EQ(server.interfaces()[0].first, "IEncoders");
  const std::string reply = server.respond(robogene::Bottle::from_text("[get] [enc] 0")).to_text();
  EXPECT_EQ(reply.rfind("[is] [enc] 10.0 [tsta] ", 0), 0u) << reply;
  robogene::Bottle data;
  ASSERT_TRUE(encode_joint_data(device, data));
  EXPECT_EQ(data.get(0).as_list().to_text(), "10.0 20.0");
}
