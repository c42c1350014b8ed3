// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// remote_controlboard: a device that is a control board on the network (paper section 3.4),
// YARP 3's client of the same name. It implements every control-board interface through the
// generated ControlboardClient over RPC, and like YARP's it
//   * reads encoders from the server's stateExt:o stream (falling back to RPC when the stream
//     is older than 0.5 s), and
//   * sends single-joint velocity moves on the streaming command port.
// Configuration: remote (the server's prefix, e.g. /motors), local (this client's prefix),
// carrier (of the two streams, default udp as YARP's), server (name server HOST:PORT).
// Ports: <local>/rpc:o -> <remote>/rpc:i (tcp), <local>/command:o -> <remote>/command:i,
// <remote>/stateExt:o -> <local>/stateExt:i.
#pragma once

#include <chrono>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "robogene/dev/device_driver.hpp"
#include "robogene/dev/generated/controlboard_client.hpp"
#include "robogene/name_client.hpp"
#include "robogene/port.hpp"

namespace robogene::dev {

class RemoteControlboard final : public DeviceDriver, public ControlboardClient {
 public:
  RemoteControlboard();
  ~RemoteControlboard() override { close(); }

  bool open(const Searchable& config) override;
  bool close() override;

  bool getEncoder(int j, double& v) override;
  bool getEncoders(std::vector<double>& vs) override;
  bool velocityMove(int j, double sp) override;

 private:
  bool call(const Bottle& request, Bottle& reply);
  void on_state(const Bottle& joint_data);
  // The joint positions of the latest jointData, if it is fresh.
  bool fresh_encoders(std::vector<double>& vs);

  std::string remote_, local_;
  std::optional<NameClient> names_;
  Port rpc_;
  Port command_;
  Port state_;
  bool state_connected_ = false;
  std::int32_t axes_ = 0;

  std::mutex state_mutex_;
  std::vector<double> positions_;
  std::chrono::steady_clock::time_point positions_at_{};
};

}  // namespace robogene::dev
