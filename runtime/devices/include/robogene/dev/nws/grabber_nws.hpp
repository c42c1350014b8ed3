// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// The frame grabber's network server: puts a camera on the network under a prefix `name`, with
// the ports of YARP 3.5's grabberDual and frameGrabber_nws_yarp:
//   <name>/rpc  answers the grabber RPC vocabs (size, features) through GrabberServer
//   <name>      every frame the device gives, as a YARP 3 image with a Stamp envelope; it answers
//               the same requests (YARP's remote_grabber sends them there)
// The device sets the pace (getImage waits for its next frame); `period` (seconds, default 0)
// is a minimum time between two published frames.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "robogene/dev/device_driver.hpp"
#include "robogene/dev/generated/grabber_server.hpp"
#include "robogene/dev/nws/periodic_thread.hpp"
#include "robogene/port.hpp"

namespace robogene::dev {

class GrabberNws {
 public:
  GrabberNws() = default;
  ~GrabberNws() { close(); }
  GrabberNws(const GrabberNws&) = delete;
  GrabberNws& operator=(const GrabberNws&) = delete;

  // Serves `device` (which must outlive this): name (required), period, server. Throws
  // ConfigError for a bad key or a device with none of the grabber service's interfaces.
  void open(DeviceDriver& device, const Searchable& config);
  void close();
  std::vector<std::string> port_names() const;

 private:
  void publish();

  std::unique_ptr<GrabberServer> server_;
  Port rpc_;    // <name>/rpc
  Port image_;  // <name>
  PeriodicThread publisher_;
  std::int32_t sequence_ = 0;
};

}  // namespace robogene::dev
