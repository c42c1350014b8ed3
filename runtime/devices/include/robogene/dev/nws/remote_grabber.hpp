// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// remote_grabber: a camera on the network, with the ports of YARP 3.5's frameGrabber_nwc_yarp.
// Controls go by RPC through the generated GrabberClient; getImage() returns the next frame of
// the server's image stream (waiting up to `timeout` seconds, default 1); width() and height()
// are those of the frames arriving (as YARP's clients give them; YARP's grabberDual does not
// answer the size requests), asked by RPC only before the first frame. Configuration: remote
// (the server's name), local (this client's name), stream (carrier of the images, default tcp;
// `carrier` is accepted too), timeout, server.
// Ports: <local>/rpc_client -> <remote>/rpc, <remote> -> <local>.
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
  bool width(std::int32_t& cols) override;
  bool height(std::int32_t& rows) override;
  // Frames received so far (tests measure the rate with it).
  std::uint64_t frames_received();

 private:
  bool call(const Bottle& request, Bottle& reply);
  // The size of the latest frame (waiting up to `timeout` for one when none has come).
  bool frame_size(std::int32_t& cols, std::int32_t& rows);

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
