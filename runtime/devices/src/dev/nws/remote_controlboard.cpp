// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "robogene/dev/nws/remote_controlboard.hpp"

#include <cmath>
#include <exception>

#include "robogene/dev/nws/device_port.hpp"
#include "robogene/dev/nws/server_identity.hpp"
#include "robogene/error.hpp"
#include "robogene/log.hpp"
#include "robogene/network.hpp"

namespace robogene::dev {
namespace {

// YARP's remote_controlboard treats stateExt data older than this as stale.
constexpr std::chrono::milliseconds kStateTimeout{500};

}  // namespace

RemoteControlboard::RemoteControlboard()
    : ControlboardClient([this](const Bottle& request, Bottle& reply) { return call(request, reply); }) {}

bool RemoteControlboard::call(const Bottle& request, Bottle& reply) {
  try {
    return rpc_.write(request, reply);
  } catch (const std::exception& e) {
    log::warn(local_ + "/rpc:o", std::string("request to ") + remote_ + "/rpc:i failed: " + e.what());
    return false;
  }
}

bool RemoteControlboard::open(const Searchable& config) {
  close();
  remote_ = port_name_option(config, "remote");
  local_ = port_name_option(config, "local");
  const std::string carrier = config.get_string("carrier", "udp");
  names_ = device_name_client(config);
  state_.set_reader([this](const Bottle& data, const MessageInfo&, Bottle*) { on_state(data); });
  try {
    rpc_.open(local_ + "/rpc:o", *names_);
    rpc_.add_output(remote_ + "/rpc:i", "tcp");
    // Throws naming an interface built from different IDL, or a wrong protocol. Only a server
    // that says it is Robogene's is asked for its fingerprints (server_identity.hpp).
    check_server(serves_robogene(*names_, remote_ + "/rpc:i", kServiceName));
    if (!getAxes(axes_)) throw Error(remote_ + "/rpc:i does not answer [get] [axes]");
    command_.open(local_ + "/command:o", *names_);
    command_.add_output(remote_ + "/command:i", carrier);
    state_.open(local_ + "/stateExt:i", *names_);
    auto r = network::connect(*names_, remote_ + "/stateExt:o", local_ + "/stateExt:i", carrier);
    if (!r.ok) throw Error("connecting " + remote_ + "/stateExt:o to " + local_ + "/stateExt:i: " + r.message);
    state_connected_ = true;
  } catch (const ConfigError&) {
    close();
    throw;
  } catch (const std::exception& e) {
    close();
    throw Error("remote_controlboard " + local_ + " -> " + remote_ + ": " + e.what());
  }
  return true;
}

bool RemoteControlboard::close() {
  if (state_connected_ && names_) {
    // YARP does the same: the server would otherwise keep sending (udp never notices).
    try {
      network::disconnect(*names_, remote_ + "/stateExt:o", local_ + "/stateExt:i");
    } catch (const std::exception& e) {
      log::warn(local_ + "/stateExt:i", std::string("could not disconnect: ") + e.what());
    }
    state_connected_ = false;
  }
  state_.close();
  command_.close();
  rpc_.close();
  std::lock_guard<std::mutex> lock(state_mutex_);
  latest_.reset();
  warned_malformed_ = false;
  return true;
}

void RemoteControlboard::on_state(const Bottle& joint_data) {
  JointData d;
  try {
    d = decode_joint_data(joint_data);
  } catch (const Error& e) {
    std::lock_guard<std::mutex> lock(state_mutex_);
    if (!warned_malformed_) log::warn(local_ + "/stateExt:i", std::string("ignoring jointData: ") + e.what());
    warned_malformed_ = true;
    return;
  }
  if (d.position.values.size() != static_cast<std::size_t>(axes_)) return;  // another board's
  std::lock_guard<std::mutex> lock(state_mutex_);
  latest_ = std::move(d);
  latest_at_ = std::chrono::steady_clock::now();
}

bool RemoteControlboard::fresh(Field field, std::vector<double>& vs) {
  std::lock_guard<std::mutex> lock(state_mutex_);
  if (!latest_ || std::chrono::steady_clock::now() - latest_at_ > kStateTimeout || !((*latest_).*field).valid) {
    return false;
  }
  vs = ((*latest_).*field).values;
  return true;
}

std::optional<bool> RemoteControlboard::fresh_one(Field field, int j, double& v) {
  std::vector<double> vs;
  if (!fresh(field, vs)) return std::nullopt;
  if (j < 0 || static_cast<std::size_t>(j) >= vs.size()) return false;
  v = vs[static_cast<std::size_t>(j)];
  return true;
}

bool RemoteControlboard::getEncoders(std::vector<double>& vs) {
  return fresh(&JointData::position, vs) || ControlboardClient::getEncoders(vs);
}

bool RemoteControlboard::getEncoder(int j, double& v) {
  if (auto got = fresh_one(&JointData::position, j, v)) return *got;
  return ControlboardClient::getEncoder(j, v);
}

bool RemoteControlboard::getEncoderSpeeds(std::vector<double>& sps) {
  return fresh(&JointData::velocity, sps) || ControlboardClient::getEncoderSpeeds(sps);
}

bool RemoteControlboard::getEncoderSpeed(int j, double& sp) {
  if (auto got = fresh_one(&JointData::velocity, j, sp)) return *got;
  return ControlboardClient::getEncoderSpeed(j, sp);
}

bool RemoteControlboard::getEncoderAccelerations(std::vector<double>& accs) {
  return fresh(&JointData::acceleration, accs) || ControlboardClient::getEncoderAccelerations(accs);
}

bool RemoteControlboard::getEncoderAcceleration(int j, double& acc) {
  if (auto got = fresh_one(&JointData::acceleration, j, acc)) return *got;
  return ControlboardClient::getEncoderAcceleration(j, acc);
}

bool RemoteControlboard::velocityMove(int j, double sp) {
  if (!std::isfinite(sp) || j < 0 || j >= axes_) return false;
  // CommandMessage: a (head) bottle and a (values) vector, sent without waiting (reference 5.5).
  Bottle head{Value::vocab("vmo"), Value(static_cast<std::int32_t>(j))};
  Bottle values{Value(sp)};
  Bottle message{Value::list(std::move(head)), Value::list(std::move(values))};
  if (command_.write(message)) return true;
  return ControlboardClient::velocityMove(j, sp);  // no command connection: ask by RPC
}

}  // namespace robogene::dev
