// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
#include <gtest/gtest.h>

#include "robogene/dev/generated/interfaces.hpp"
#include "robogene/dev/poly_driver.hpp"
#include "robogene/dev/simulation_clock.hpp"

using namespace robogene::dev;

namespace {

class CountingDevice : public DeviceDriver {
 public:
  static int opened, closed;
  bool open(const Searchable& config) override {
    if (config.get_bool("refuse", false)) return false;
    ++opened;
    return true;
  }
  bool close() override {
    ++closed;
    return true;
  }
};
int CountingDevice::opened = 0;
int CountingDevice::closed = 0;

}  // namespace

TEST(DriverFactory, KnowsTheBuiltInDriversByName) {
  auto& factory = DriverFactory::instance();
  EXPECT_TRUE(factory.has("test_motor"));
  EXPECT_TRUE(factory.has("fake_grabber"));
  EXPECT_FALSE(factory.has("dragonfly"));
  try {
    factory.create("dragonfly");
    FAIL() << "created an unknown device";
  } catch (const robogene::Error& e) {
    EXPECT_NE(std::string(e.what()).find("unknown device 'dragonfly' (known devices: "),
              std::string::npos);
    EXPECT_NE(std::string(e.what()).find("test_motor"), std::string::npos);
  }
  EXPECT_THROW(factory.add("test_motor", "again", [] { return nullptr; }), robogene::Error);
}

TEST(PolyDriver, ViewIsADynamicCastToWhatTheDeviceImplements) {
  PolyDriver device;
  ASSERT_TRUE(device.open("test_motor")) << device.last_error();
  IPositionControl* ipos = nullptr;
  IVelocityControl* ivel = nullptr;
  IEncoders* ienc = nullptr;
  IFrameGrabberImage* igrab = nullptr;
  EXPECT_TRUE(device.view(ipos));
  EXPECT_TRUE(device.view(ivel));
  EXPECT_TRUE(device.view(ienc));
  EXPECT_FALSE(device.view(igrab));
  EXPECT_EQ(igrab, nullptr);
  std::int32_t axes = 0;
  ASSERT_TRUE(ienc->getAxes(axes));
  EXPECT_EQ(axes, 4);  // the paper's test_motor has four axes by default
  EXPECT_TRUE(device.close());
  EXPECT_FALSE(device.is_valid());
  EXPECT_FALSE(device.view(ipos));
}

TEST(PolyDriver, OpensFromAConfigurationAndPassesItToTheDevice) {
  const Property config = Property::from_command_line({"--device", "test_motor", "--axes", "2"});
  PolyDriver device(config);
  ASSERT_TRUE(device.is_valid()) << device.last_error();
  IEncoders* enc = nullptr;
  ASSERT_TRUE(device.view(enc));
  std::int32_t axes = 0;
  ASSERT_TRUE(enc->getAxes(axes));
  EXPECT_EQ(axes, 2);
}

TEST(PolyDriver, FailuresSayWhatAndWhere) {
  PolyDriver device;
  EXPECT_FALSE(device.open("dragonfly"));
  EXPECT_NE(device.last_error().find("unknown device 'dragonfly'"), std::string::npos);

  EXPECT_FALSE(device.open(Property::from_ini("axes 2\n", "motor.ini")));
  EXPECT_EQ(device.last_error(), "motor.ini: no 'device' key naming the driver to open");

  EXPECT_FALSE(device.open(Property::from_ini("device test_motor\naxes 100\n", "motor.ini")));
  EXPECT_EQ(device.last_error(), "device 'test_motor': motor.ini:2: key 'axes': 100 is outside [1, 64]");
  EXPECT_FALSE(device.is_valid());
}

TEST(PolyDriver, OwnsTheDeviceLifecycle) {
  DriverFactory::instance().add("counting_device", "test", [] { return std::make_unique<CountingDevice>(); });
  {
    PolyDriver device;
    ASSERT_TRUE(device.open("counting_device"));
    EXPECT_EQ(CountingDevice::opened, 1);
    ASSERT_TRUE(device.open("counting_device"));  // reopening closes the first one
    EXPECT_EQ(CountingDevice::closed, 1);
  }
  EXPECT_EQ(CountingDevice::closed, 2);  // the destructor closes
  PolyDriver refused;
  EXPECT_FALSE(refused.open(Property::from_command_line({"--device", "counting_device", "--refuse"})));
  EXPECT_EQ(refused.last_error(), "device 'counting_device' failed to open");
}

TEST(PolyDriver, ADriverThatThrowsIsReportedNotPropagated) {
  struct Throwing : DeviceDriver {
    bool open(const Searchable&) override { throw std::runtime_error("serial port /dev/ttyX busy"); }
    bool close() override { return true; }
  };
  DriverFactory::instance().add("throwing_device", "test", [] { return std::make_unique<Throwing>(); });
  PolyDriver device;
  EXPECT_FALSE(device.open("throwing_device"));
  EXPECT_EQ(device.last_error(), "device 'throwing_device' failed while opening: serial port /dev/ttyX busy");
}
