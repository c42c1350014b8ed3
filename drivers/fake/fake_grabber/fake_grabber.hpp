// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// fake_grabber: a camera that films a moving RGB test pattern. Frame n shows red rising with x
// and shifting 2 px left per frame, green rising with y and shifting 1 px up per frame, and a
// blue 16 px checkerboard that flips every 8 frames. Brightness and gain change the pixels as a
// camera's would (gain 0.5 and brightness 0.5 leave them as drawn); shutter and exposure are
// kept but do not change the picture.
//
// Configuration: width (1-4096, default 320), height (1-4096, default 240), framerate (Hz,
// 0.1-1000, default 30), clock (wall or manual). With the wall clock getImage() waits for the
// next frame, so a reader gets frames at the configured rate; with the manual clock it returns
// the frame of the current simulated time at once.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <mutex>

#include "robogene/dev/device_driver.hpp"
#include "robogene/dev/generated/iframegrabbercontrols.hpp"
#include "robogene/dev/generated/iframegrabberimage.hpp"
#include "robogene/dev/simulation_clock.hpp"
#include "common/sim_clock.hpp"

namespace robogene::dev {

class FakeGrabber final : public DeviceDriver,
                          public IFrameGrabberImage,
                          public IFrameGrabberControls,
                          public ISimulationClock {
 public:
  // Draws frame `n` of the pattern, before brightness and gain; shared with the tests.
  static void draw(ImageRgb& image, int width, int height, std::int64_t n);

  bool open(const Searchable& config) override;
  bool close() override;

  double now() override;
  bool advance(double seconds) override;

  bool getImage(ImageRgb& image) override;
  bool height(std::int32_t& rows) override;
  bool width(std::int32_t& cols) override;

  bool hasFeature(CameraFeature feature, bool& has) override;
  bool setFeature(CameraFeature feature, double value) override;
  bool getFeature(CameraFeature feature, double& value) override;
  bool setActive(CameraFeature feature, bool onoff) override;
  bool getActive(CameraFeature feature, bool& active) override;
  bool setMode(CameraFeature feature, FeatureMode mode) override;
  bool getMode(CameraFeature feature, FeatureMode& mode) override;

  // Frames delivered by getImage() so far, and the number of the last one.
  std::int64_t last_frame() const;

 private:
  struct Feature {
    double value = 0.5;
    bool active = true;
    FeatureMode mode = FeatureMode::manual;
  };
  Feature* feature(CameraFeature f);
  double effective(CameraFeature f);  // what the picture uses: 0.5 when off or automatic

  mutable std::mutex mutex_;
  SimClock clock_;
  bool open_ = false;
  int width_ = 320;
  int height_ = 240;
  double rate_ = 30.0;
  std::int64_t last_frame_ = -1;
  std::array<Feature, 4> features_{};  // brightness, exposure, shutter, gain
};

}  // namespace robogene::dev
