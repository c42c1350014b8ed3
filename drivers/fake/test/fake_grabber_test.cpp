// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>

#include "robogene/dev/generated/interfaces.hpp"
#include "robogene/dev/poly_driver.hpp"
#include "robogene/dev/simulation_clock.hpp"

using namespace robogene::dev;

namespace {

Property grabber_config(const char* extra) {
  return Property::from_ini(std::string("device fake_grabber\nwidth 64\nheight 48\nframerate 25\n") +
                                extra,
                            "grabber.ini");
}

}  // namespace

TEST(FakeGrabber, SizeComesFromTheConfiguration) {
  PolyDriver device(grabber_config("clock manual\n"));
  ASSERT_TRUE(device.is_valid()) << device.last_error();
  IFrameGrabberImage* img = nullptr;
  ASSERT_TRUE(device.view(img));
  std::int32_t w = 0, h = 0;
  ASSERT_TRUE(img->width(w));
  ASSERT_TRUE(img->height(h));
  EXPECT_EQ(w, 64);
  EXPECT_EQ(h, 48);
  ImageRgb frame;
  ASSERT_TRUE(img->getImage(frame));
  EXPECT_EQ(frame.width, 64);
  EXPECT_EQ(frame.height, 48);
  EXPECT_EQ(frame.pixels.size(), 64u * 48u * 3u);
  IPositionControl* ipos = nullptr;
  EXPECT_FALSE(device.view(ipos));
}

TEST(FakeGrabber, ThePatternMovesFromFrameToFrame) {
  PolyDriver device(grabber_config("clock manual\n"));
  IFrameGrabberImage* img = nullptr;
  ISimulationClock* clock = nullptr;
  ASSERT_TRUE(device.view(img) && device.view(clock));
  ImageRgb a, b;
  ASSERT_TRUE(img->getImage(a));
  ASSERT_TRUE(clock->advance(1.0 / 25));  // one frame later
  ASSERT_TRUE(img->getImage(b));
  EXPECT_NE(a.pixels, b.pixels);
  for (int y = 0; y + 1 < 48; ++y) {
    for (int x = 0; x + 2 < 64; ++x) {
      ASSERT_EQ(b.at(x, y)[0], a.at(x + 2, y)[0]) << x << "," << y;  // red: 2 px left
      ASSERT_EQ(b.at(x, y)[1], a.at(x, y + 1)[1]) << x << "," << y;  // green: 1 px up
    }
  }
  // Frame 0 is the pattern as documented: red = x, green = y, blue a 16 px checkerboard.
  for (int y = 0; y < 48; ++y) {
    for (int x = 0; x < 64; ++x) {
      ASSERT_EQ(a.at(x, y)[0], x);
      ASSERT_EQ(a.at(x, y)[1], y);
      ASSERT_EQ(a.at(x, y)[2], ((x / 16 + y / 16) % 2) ? 200 : 40);
    }
  }
}

TEST(FakeGrabber, BrightnessAndGainChangeThePixels) {
  PolyDriver device(grabber_config("clock manual\n"));
  IFrameGrabberImage* img = nullptr;
  IFrameGrabberControls* ctl = nullptr;
  ASSERT_TRUE(device.view(img) && device.view(ctl));
  ImageRgb plain, bright, dark;
  ASSERT_TRUE(img->getImage(plain));
  ASSERT_TRUE(ctl->setFeature(CameraFeature::brightness, 0.75));
  ASSERT_TRUE(img->getImage(bright));
  ASSERT_TRUE(ctl->setFeature(CameraFeature::brightness, 0.5));
  ASSERT_TRUE(ctl->setFeature(CameraFeature::gain, 0.25));  // halves every byte
  ASSERT_TRUE(img->getImage(dark));
  for (std::size_t i = 0; i < plain.pixels.size(); ++i) {
    const int p = plain.pixels[i];
    ASSERT_EQ(bright.pixels[i], std::min(255, p + 64)) << i;  // +63.75, rounded
    ASSERT_EQ(dark.pixels[i], std::lround(p * 0.5)) << i;
  }
  ASSERT_TRUE(ctl->setActive(CameraFeature::gain, false));  // off: neutral again
  ImageRgb again;
  ASSERT_TRUE(img->getImage(again));
  EXPECT_EQ(again.pixels, plain.pixels);
  double v = 0;
  ASSERT_TRUE(ctl->getFeature(CameraFeature::gain, v));
  EXPECT_EQ(v, 0.25);
}

TEST(FakeGrabber, ControlsRefuseWhatTheCameraCannotDo) {
  PolyDriver device(grabber_config("clock manual\n"));
  IFrameGrabberControls* ctl = nullptr;
  ASSERT_TRUE(device.view(ctl));
  bool has = true;
  ASSERT_TRUE(ctl->hasFeature(CameraFeature::focus, has));
  EXPECT_FALSE(has);
  ASSERT_TRUE(ctl->hasFeature(CameraFeature::shutter, has));
  EXPECT_TRUE(has);
  EXPECT_FALSE(ctl->setFeature(CameraFeature::focus, 0.5));
  EXPECT_FALSE(ctl->setFeature(CameraFeature::shutter, 1.5));
  EXPECT_FALSE(ctl->setFeature(CameraFeature::shutter, NAN));
  EXPECT_TRUE(ctl->setFeature(CameraFeature::shutter, 0.75));
  EXPECT_TRUE(ctl->setMode(CameraFeature::shutter));  // default argument: manual
  FeatureMode mode{};
  ASSERT_TRUE(ctl->getMode(CameraFeature::shutter, mode));
  EXPECT_EQ(mode, FeatureMode::manual);
  EXPECT_FALSE(ctl->setMode(CameraFeature::shutter, FeatureMode::unknown));
}

TEST(FakeGrabber, WallClockDeliversFramesAtTheConfiguredRate) {
  PolyDriver device(Property::from_ini("device fake_grabber\nwidth 8\nheight 8\nframerate 50\n", "g.ini"));
  IFrameGrabberImage* img = nullptr;
  ASSERT_TRUE(device.view(img));
  ImageRgb frame;
  ASSERT_TRUE(img->getImage(frame));
  const auto start = std::chrono::steady_clock::now();
  for (int i = 0; i < 5; ++i) ASSERT_TRUE(img->getImage(frame));
  const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_GE(elapsed, 4.0 / 50);  // five new frames need at least four frame periods
}

TEST(FakeGrabber, BadConfigurationIsReportedWithItsPlace) {
  PolyDriver device;
  EXPECT_FALSE(device.open(Property::from_ini("device fake_grabber\nwidth 0\n", "g.ini")));
  EXPECT_EQ(device.last_error(), "device 'fake_grabber': g.ini:2: key 'width': 0 is outside [1, 4096]");
  EXPECT_FALSE(device.open(Property::from_ini("device fake_grabber\nclock sundial\n", "g.ini")));
  EXPECT_EQ(device.last_error(), "device 'fake_grabber': g.ini:2: key 'clock': expected wall or manual, got 'sundial'");
}
