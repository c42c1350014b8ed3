// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// remote_controlboard: a device that is a control board on the network (paper section 3.4),
// YARP 3's client of the same name. It implements every control-board interface through the
// generated ControlboardClient over RPC, and like YARP's it
//   * reads the encoders (positions, speeds, accelerations) from the server's stateExt:o stream
//     (jointData), falling back to RPC when the last message is older than 0.5 s or the server
//     flagged that field [fail], and
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
#include "robogene/dev/joint_data.hpp"
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
  bool getEncoderSpeed(int j, double& sp) override;
  bool getEncoderSpeeds(std::vector<double>& sps) override;
  bool getEncoderAcceleration(int j, double& acc) override;
  bool getEncoderAccelerations(std::vector<double>& accs) override;
  bool velocityMove(int j, double sp) override;

 private:
  using Field = JointDataField<double> JointData::*;

  bool call(const Bottle& request, Bottle& reply);
  void on_state(const Bottle& joint_data);
  // One field of the latest jointData, if that message is fresh and the field valid.
  bool fresh(Field field, std::vector<double>& vs);
  // Axis j of a fresh field; nullopt (ask by RPC) when there is none. False for a bad j.
  std::optional<bool> fresh_one(Field field, int j, double& v);

  std::string remote_, local_;
  std::optional<NameClient> names_;
  Port rpc_;
  Port command_;
  Port state_;
  bool state_connected_ = false;
  std::int32_t axes_ = 0;

  std::mutex state_mutex_;
  std::optional<JointData> latest_;  // the latest well-formed jointData with one value per axis
  std::chrono::steady_clock::time_point latest_at_{};
  bool warned_malformed_ = false;
};

}  // namespace robogene::dev
