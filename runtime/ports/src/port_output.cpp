// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// Port outputs: resolving names, connecting, removing, and writing to every output.
#include <algorithm>

#include "port_core.hpp"
#include "robogene/carrier/registry.hpp"
#include "robogene/error.hpp"
#include "robogene/log.hpp"
#include "robogene/name_server_mcast_groups.hpp"

namespace robogene {

std::optional<Contact> Port::Core::resolve(const std::string& port_name) {
  Resolver r;
  {
    std::lock_guard<std::mutex> lock(mutex);
    r = resolver;
  }
  if (r) return r(port_name);
  if (names) return names->query(port_name);
  return std::nullopt;
}

void Port::Core::add_unit(std::shared_ptr<OutputUnit> unit) {
  std::lock_guard<std::mutex> lock(mutex);
  outputs.push_back(std::move(unit));
}

void Port::Core::connect_output(const Contact& to, const std::string& carrier_name) {
  std::string dummy;
  remove_output_report(to.name, dummy);  // a new connection replaces an old one
  carrier::ConnectContext ctx;
  // A port that was never opened writes anonymously, as `yarp rpc` does.
  ctx.sender_name = name.empty() ? "anon_rpc" : name;
  ctx.target_name = to.name;
  ctx.timeout = options.connect_timeout;
  ctx.max_message_size = options.max_message_size;
  ctx.mcast_groups = name_server_mcast_groups(names ? std::optional<net::Endpoint>(names->server()) : std::nullopt);
  auto unit = std::make_shared<OutputUnit>();
  unit->target = to.name;
  unit->carrier = carrier_name.empty() ? (to.carrier.empty() ? "tcp" : to.carrier) : carrier_name;
  unit->conn = carrier::open_connection(to.endpoint(), unit->carrier, ctx);
  unit->conn->set_timeout(options.send_timeout);
  log::info(name, "Sending output from " + name + " to " + to.name + " using " + unit->carrier);
  add_unit(std::move(unit));
}

bool Port::Core::add_output_report(const std::string& target_text, std::string& report) {
  Target t;
  try {
    t = parse_target(target_text);
  } catch (const Error&) {
    report = "Do not know how to connect to " + target_text + "\r\n";
    return false;
  }
  std::optional<Contact> c;
  try {
    c = resolve(t.name);
  } catch (const std::exception& e) {
    log::warn(name, "looking up " + t.name + ": " + e.what());
  }
  if (!c) {
    report = "Do not know how to connect to " + target_text + "\r\n";
    return false;
  }
  c->name = t.name;
  try {
    connect_output(*c, t.carrier);
  } catch (const std::exception& e) {
    log::warn(name, "cannot connect to " + target_text + ": " + e.what());
    report = "Cannot connect to " + target_text + "\r\n";
    return false;
  }
  report = "Added connection from " + name + " to " + target_text + "\r\n";
  return true;
}

bool Port::Core::remove_output_report(const std::string& target, std::string& report) {
  std::vector<std::shared_ptr<OutputUnit>> gone;
  {
    std::lock_guard<std::mutex> lock(mutex);
    for (auto it = outputs.begin(); it != outputs.end();) {
      if ((*it)->target == target) {
        gone.push_back(*it);
        it = outputs.erase(it);
      } else {
        ++it;
      }
    }
  }
  for (auto& o : gone) {
    std::lock_guard<std::mutex> lock(o->mutex);
    o->conn->close();
    log::info(name, "Removing output from " + name + " to " + target);
  }
  report = gone.empty() ? "Could not find an outgoing connection to " + target + "\r\n"
                        : "Removed connection from " + name + " to " + target + "\r\n";
  return !gone.empty();
}

bool Port::Core::remove_input_report(const std::string& from, std::string& report) {
  bool found = false;
  {
    std::lock_guard<std::mutex> lock(mutex);
    for (auto& in : inputs) {
      if (!in->done && in->from == from && in->conn) {
        in->conn->interrupt();
        found = true;
      }
    }
  }
  report = found ? "Removing connection from " + from + " to " + name + "\r\n"
                 : "Could not find an incoming connection from " + from + "\r\n";
  return found;
}

void Port::Core::drop_output(const std::shared_ptr<OutputUnit>& unit, const std::string& why) {
  {
    std::lock_guard<std::mutex> lock(mutex);
    outputs.erase(std::remove(outputs.begin(), outputs.end(), unit), outputs.end());
  }
  log::warn(name, "dropping output to " + unit->target + " (" + unit->conn->peer_text() + "): " + why);
  unit->conn->interrupt();
}

void Port::add_output(const std::string& target, const std::string& carrier) {
  core_->used_for_output = true;
  Target t = parse_target(target);
  auto c = core_->resolve(t.name);
  if (!c) throw Error("cannot connect " + core_->name + " to " + target + ": no such port is registered");
  c->name = t.name;
  core_->connect_output(*c, carrier.empty() ? t.carrier : carrier);
}

void Port::add_output(const Contact& to) {
  core_->used_for_output = true;
  core_->connect_output(to, to.carrier);
}

bool Port::remove_output(const std::string& name) {
  std::string report;
  return core_->remove_output_report(name, report);
}

bool Port::remove_input(const std::string& name) {
  std::string report;
  return core_->remove_input_report(name, report);
}

std::vector<std::string> Port::output_names() const {
  std::lock_guard<std::mutex> lock(core_->mutex);
  std::vector<std::string> out;
  for (auto& o : core_->outputs) out.push_back(o->target);
  return out;
}

std::vector<std::string> Port::input_names() const {
  std::lock_guard<std::mutex> lock(core_->mutex);
  std::vector<std::string> out;
  for (auto& in : core_->inputs) {
    if (!in->done && in->conn) out.push_back(in->from);
  }
  return out;
}

void Port::set_envelope(std::string envelope) {
  std::lock_guard<std::mutex> lock(core_->write_mutex);
  core_->envelope = std::move(envelope);
}

bool Port::write(const Bottle& b) {
  core_->used_for_output = true;
  std::lock_guard<std::mutex> wlock(core_->write_mutex);
  std::vector<std::shared_ptr<OutputUnit>> outs;
  {
    std::lock_guard<std::mutex> lock(core_->mutex);
    outs = core_->outputs;
  }
  if (outs.empty()) return false;
  carrier::OutboundMessage m;
  m.key = 'D';
  m.envelope = core_->envelope;
  m.bottle = &b;
  // Put the message on every connection first, then collect the acks: readers work in
  // parallel and the last one does not wait for the others' round trips.
  std::vector<std::unique_lock<std::mutex>> locks;
  std::vector<bool> sent(outs.size(), false);
  locks.reserve(outs.size());
  for (std::size_t i = 0; i < outs.size(); ++i) {
    locks.emplace_back(outs[i]->mutex);
    try {
      outs[i]->conn->write_message(m);
      sent[i] = true;
    } catch (const std::exception& e) {
      core_->drop_output(outs[i], e.what());
    }
  }
  bool any = false;
  for (std::size_t i = 0; i < outs.size(); ++i) {
    if (!sent[i]) continue;
    try {
      outs[i]->conn->await_completion(nullptr);
      any = true;
    } catch (const std::exception& e) {
      core_->drop_output(outs[i], e.what());
    }
  }
  return any;
}

bool Port::write(const Bottle& b, Bottle& reply) {
  core_->used_for_output = true;
  core_->used_for_rpc = true;
  std::lock_guard<std::mutex> wlock(core_->write_mutex);
  std::shared_ptr<OutputUnit> o;
  {
    std::lock_guard<std::mutex> lock(core_->mutex);
    if (core_->outputs.empty()) return false;
    o = core_->outputs.front();
  }
  carrier::OutboundMessage m;
  m.key = 'd';
  m.envelope = core_->envelope;
  m.bottle = &b;
  std::lock_guard<std::mutex> lock(o->mutex);
  try {
    o->conn->send(m, &reply);
    return true;
  } catch (const std::exception& e) {
    core_->drop_output(o, e.what());
    return false;
  }
}

}  // namespace robogene
