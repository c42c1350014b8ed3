// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "fake_grabber.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <thread>

#include "robogene/dev/driver_registrar.hpp"

namespace robogene::dev {
namespace {

int slot(CameraFeature f) {
  switch (f) {
    case CameraFeature::brightness: return 0;
    case CameraFeature::exposure: return 1;
    case CameraFeature::shutter: return 2;
    case CameraFeature::gain: return 3;
    default: return -1;
  }
}

std::uint8_t wrap(std::int64_t v) { return static_cast<std::uint8_t>(((v % 256) + 256) % 256); }

}  // namespace

void FakeGrabber::draw(ImageRgb& image, int width, int height, std::int64_t n) {
  image.resize(width, height);
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      std::uint8_t* p = image.at(x, y);
      p[0] = wrap(x + 2 * n);
      p[1] = wrap(y + n);
      p[2] = ((x / 16 + y / 16 + n / 8) % 2) ? 200 : 40;
    }
  }
}

bool FakeGrabber::open(const Searchable& config) {
  std::lock_guard<std::mutex> lock(mutex_);
  width_ = config.get_int("width", 320, 1, 4096);
  height_ = config.get_int("height", 240, 1, 4096);
  rate_ = config.get_float("framerate", 30.0, 0.1, 1000.0);
  clock_.configure(config);
  features_ = {};
  last_frame_ = -1;
  open_ = true;
  return true;
}

bool FakeGrabber::close() {
  std::lock_guard<std::mutex> lock(mutex_);
  open_ = false;
  return true;
}

double FakeGrabber::now() {
  std::lock_guard<std::mutex> lock(mutex_);
  return clock_.now();
}

bool FakeGrabber::advance(double seconds) {
  std::lock_guard<std::mutex> lock(mutex_);
  return open_ && clock_.advance(seconds);
}

std::int64_t FakeGrabber::last_frame() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return last_frame_;
}

bool FakeGrabber::getImage(ImageRgb& image) {
  std::unique_lock<std::mutex> lock(mutex_);
  if (!open_) return false;
  std::int64_t n = static_cast<std::int64_t>(std::floor(clock_.now() * rate_));
  if (!clock_.manual() && n <= last_frame_) {
    // Wait (without the lock, so controls stay usable) for the next frame to be "exposed".
    const double due = static_cast<double>(last_frame_ + 1) / rate_;
    const double wait = due - clock_.now();
    lock.unlock();
    if (wait > 0) std::this_thread::sleep_for(std::chrono::duration<double>(wait));
    lock.lock();
    if (!open_) return false;
    n = std::max(last_frame_ + 1, static_cast<std::int64_t>(std::floor(clock_.now() * rate_)));
  }
  last_frame_ = n;
  draw(image, width_, height_, n);
  const double gain = 2.0 * effective(CameraFeature::gain);
  const double offset = (effective(CameraFeature::brightness) - 0.5) * 255.0;
  if (gain != 1.0 || offset != 0.0) {
    for (auto& byte : image.pixels) {
      byte = static_cast<std::uint8_t>(std::clamp(std::lround(byte * gain + offset), 0L, 255L));
    }
  }
  return true;
}

bool FakeGrabber::height(std::int32_t& rows) {
  std::lock_guard<std::mutex> lock(mutex_);
  rows = height_;
  return open_;
}

bool FakeGrabber::width(std::int32_t& cols) {
  std::lock_guard<std::mutex> lock(mutex_);
  cols = width_;
  return open_;
}

FakeGrabber::Feature* FakeGrabber::feature(CameraFeature f) {
  const int i = slot(f);
  return (open_ && i >= 0) ? &features_[static_cast<std::size_t>(i)] : nullptr;
}

double FakeGrabber::effective(CameraFeature f) {
  const Feature* feat = feature(f);
  if (!feat || !feat->active || feat->mode == FeatureMode::automatic) return 0.5;
  return feat->value;
}

bool FakeGrabber::hasFeature(CameraFeature f, bool& has) {
  std::lock_guard<std::mutex> lock(mutex_);
  has = slot(f) >= 0;
  return open_;
}

bool FakeGrabber::setFeature(CameraFeature f, double value) {
  std::lock_guard<std::mutex> lock(mutex_);
  Feature* feat = feature(f);
  if (!feat || !std::isfinite(value) || value < 0.0 || value > 1.0) return false;
  feat->value = value;
  return true;
}

bool FakeGrabber::getFeature(CameraFeature f, double& value) {
  std::lock_guard<std::mutex> lock(mutex_);
  const Feature* feat = feature(f);
  if (!feat) return false;
  value = feat->value;
  return true;
}

bool FakeGrabber::setActive(CameraFeature f, bool onoff) {
  std::lock_guard<std::mutex> lock(mutex_);
  Feature* feat = feature(f);
  if (!feat) return false;
  feat->active = onoff;
  return true;
}

bool FakeGrabber::getActive(CameraFeature f, bool& active) {
  std::lock_guard<std::mutex> lock(mutex_);
  const Feature* feat = feature(f);
  if (!feat) return false;
  active = feat->active;
  return true;
}

bool FakeGrabber::setMode(CameraFeature f, FeatureMode mode) {
  std::lock_guard<std::mutex> lock(mutex_);
  Feature* feat = feature(f);
  if (!feat || mode == FeatureMode::unknown) return false;
  feat->mode = mode;
  return true;
}

bool FakeGrabber::getMode(CameraFeature f, FeatureMode& mode) {
  std::lock_guard<std::mutex> lock(mutex_);
  const Feature* feat = feature(f);
  if (!feat) return false;
  mode = feat->mode;
  return true;
}

ROBOGENE_REGISTER_DRIVER(fake_grabber, "simulated camera: a moving RGB test pattern", FakeGrabber);

}  // namespace robogene::dev
