// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// The control board's network server (YARP 3's controlBoard_nws_yarp / controlboardwrapper2,
// reference section 5): puts a device on the network under a prefix `name`:
//   <name>/rpc:i       answers the RPC vocabs through the generated ControlboardServer
//   <name>/command:i   streamed commands (([vmo] j) (v) ...), no reply
//   <name>/state:o     the encoder vector every `period`, with a Stamp envelope
//   <name>/stateExt:o  jointData every `period`, with the same envelope (remote_controlboard
//                      reads its encoders there)
// With `single_port`, one port named `name` does all of it: it answers RPC, takes commands
// sent without waiting for a reply, and streams the encoder vector to every output, including
// readers that connected and reversed the connection with `r` (paper section 4.4).
#pragma once

#include <atomic>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "robogene/dev/device_driver.hpp"
#include "robogene/dev/generated/controlboard_server.hpp"
#include "robogene/dev/nws/periodic_thread.hpp"
#include "robogene/port.hpp"

namespace robogene::dev {

class ControlboardNws {
 public:
  ControlboardNws() = default;
  ~ControlboardNws() { close(); }
  ControlboardNws(const ControlboardNws&) = delete;
  ControlboardNws& operator=(const ControlboardNws&) = delete;

  // Serves `device` (which must outlive this) as `config` says: name (required), period
  // (seconds, default 0.02), single_port, server. Throws ConfigError for a bad key or a device
  // with none of the service's interfaces, and robogene::Error when a port cannot be opened.
  void open(DeviceDriver& device, const Searchable& config);
  // Stops streaming and closes (unregisters) every port. Idempotent.
  void close();
  // The ports this server opened, in the order above.
  std::vector<std::string> port_names() const;

 private:
  void publish();

  DeviceDriver* device_ = nullptr;
  std::unique_ptr<ControlboardServer> server_;
  bool single_port_ = false;
  Port rpc_;        // <name>/rpc:i, or the single port
  Port command_;    // <name>/command:i
  Port state_;      // <name>/state:o
  Port state_ext_;  // <name>/stateExt:o
  PeriodicThread publisher_;
  std::int32_t sequence_ = 0;
};

}  // namespace robogene::dev
