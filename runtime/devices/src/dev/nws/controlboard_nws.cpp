// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "robogene/dev/nws/controlboard_nws.hpp"

#include "robogene/dev/joint_data.hpp"
#include "robogene/dev/nws/group_requests.hpp"
#include "robogene/dev/nws/server_identity.hpp"
#include "robogene/dev/nws/device_port.hpp"
#include "robogene/envelope.hpp"

namespace robogene::dev {
namespace {

bool all_ok(ControlboardServer& server, const std::vector<Bottle>& requests) {
  bool ok = !requests.empty();
  for (const Bottle& r : requests) {
    const Bottle reply = server.respond(r);
    ok = reply.size() == 1 && reply[0].to_text() == "[ok]" && ok;
  }
  return ok;
}

// An RPC request, group forms included.
Bottle answer(ControlboardServer& server, const Bottle& request) {
  if (auto group = expand_group_request(request)) {
    return Bottle{Value::vocab(all_ok(server, *group) ? "ok" : "fail")};
  }
  if (auto singles = expand_group_query(request)) {
    std::vector<Bottle> replies;
    for (const Bottle& single : *singles) replies.push_back(server.respond(single));
    return combine_group_replies(request, replies);
  }
  return server.respond(request);
}

// A command-port message, group forms included.
bool carry_out(ControlboardServer& server, const Bottle& message) {
  if (auto group = expand_group_command(message)) return all_ok(server, *group);
  return server.command(message);
}

}  // namespace

void ControlboardNws::open(DeviceDriver& device, const Searchable& config) {
  close();
  const std::string name = port_name_option(config, "name");
  const double period = config.get_float("period", 0.02, 0.001, 10.0);
  single_port_ = config.get_bool("single_port", false);
  NameClient names = device_name_client(config);
  auto server_of_device = std::make_unique<ControlboardServer>(device);
  if (server_of_device->interfaces().empty()) {
    throw ConfigError(name + ": the device to serve implements none of the interfaces of the " +
                      ControlboardServer::kServiceName + " service");
  }
  device_ = &device;
  server_ = std::move(server_of_device);

  auto* server = server_.get();
  const bool single = single_port_;
  rpc_.set_reader([server, single](const Bottle& data, const MessageInfo&, Bottle* reply) {
    if (reply) {
      *reply = answer(*server, data);
    } else if (single && !carry_out(*server, data)) {
      answer(*server, data);  // a request sent without waiting for the answer still acts
    }
  });
  command_.set_reader([server](const Bottle& data, const MessageInfo&, Bottle* reply) {
    const bool done = carry_out(*server, data);
    if (reply) *reply = Bottle{Value::vocab(done ? "ok" : "fail")};
  });
  announce_service(rpc_, ControlboardServer::kServiceName);  // so our clients may ask [get] [rgif]
  try {
    if (single_port_) {
      rpc_.open(name, names);
    } else {
      rpc_.open(name + "/rpc:i", names);
      command_.open(name + "/command:i", names);
      state_.open(name + "/state:o", names);
      state_ext_.open(name + "/stateExt:o", names);
    }
  } catch (...) {
    close();
    throw;
  }
  sequence_ = 0;
  publisher_.start(period, [this] { publish(); });
}

void ControlboardNws::publish() {
  Stamp stamp{sequence_++, wall_time_now()};
  const std::string envelope = stamp.to_text();
  Bottle state;
  if (server_->publish_state(state)) {
    Port& out = single_port_ ? rpc_ : state_;
    out.set_envelope(envelope);
    out.write(state);
  }
  if (single_port_) return;
  Bottle joints;
  if (encode_joint_data(*device_, joints)) {
    state_ext_.set_envelope(envelope);
    state_ext_.write(joints);
  }
}

void ControlboardNws::close() {
  publisher_.stop();
  state_ext_.close();
  state_.close();
  command_.close();
  rpc_.close();
  server_.reset();
  device_ = nullptr;
}

std::vector<std::string> ControlboardNws::port_names() const {
  std::vector<std::string> out;
  for (const Port* p : {&rpc_, &command_, &state_, &state_ext_}) {
    if (p->is_open()) out.push_back(p->name());
  }
  return out;
}

}  // namespace robogene::dev
