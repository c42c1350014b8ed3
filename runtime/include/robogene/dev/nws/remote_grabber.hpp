// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// remote_grabber: a camera on the network. Controls and size go by RPC through the generated
// GrabberClient; getImage() returns the next frame of the server's image stream (waiting up
// to `timeout` seconds, default 1). Configuration: remote (the server's prefix), local (this
// client's prefix), carrier (of the image stream, default tcp), timeout, server.
// Ports: <local>/rpc:o -> <remote>/rpc:i, <remote>/image:o -> <local>/image:i.
#pragma once

#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <mutex>
#include <optional>
#include <string>

#include "robogene/dev/device_driver.hpp"
#include "robogene/dev/generated/grabber_client.hpp"
#include "robogene/name_client.hpp"
#include "robogene/port.hpp"

namespace robogene::dev {

class RemoteGrabber final : public DeviceDriver, public GrabberClient {
 public:
  RemoteGrabber();
  ~RemoteGrabber() override { close(); }

  bool open(const Searchable& config) override;
  bool close() override;

  // The next frame received after the call (false after `timeout` without one, or when the
  // frame cannot be decoded).
  bool getImage(ImageRgb& image) override;
  // Frames received so far (tests measure the rate with it).
  std::uint64_t frames_received();

 private:
  bool call(const Bottle& request, Bottle& reply);

  std::string remote_, local_;
  std::optional<NameClient> names_;
  Port rpc_;
  Port images_;
  bool image_connected_ = false;
  std::chrono::milliseconds timeout_{1000};

  std::mutex mutex_;
  std::condition_variable arrived_;
  Bottle latest_;
  std::uint64_t frames_ = 0;
  bool closing_ = false;
};

}  // namespace robogene::dev
