// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// Port: opening and closing. Outputs and writing are in port_output.cpp, reading in
// port_read.cpp, inputs in port_input.cpp, admin messages in port_admin.cpp.
#include "robogene/port.hpp"

#include <unistd.h>

#include "port_core.hpp"
#include "registration_keeper.hpp"
#include "robogene/carrier/registry.hpp"
#include "robogene/error.hpp"
#include "robogene/log.hpp"

namespace robogene {

Port::Port() : Port(PortOptions{}) {}
Port::Port(PortOptions options) : core_(std::make_shared<Core>(options)) {}
Port::~Port() { close(); }

void Port::Core::start_listening(const net::Endpoint& at) {
  listener = net::TcpListener::listen(at);
  address.carrier = "tcp";
  address.host = listener.local().host.empty() || listener.local().host == "0.0.0.0"
                     ? "127.0.0.1"
                     : listener.local().host;
  address.port = listener.local().port;
  address.name = name;
  open = true;
  closing = false;
  acceptor = std::thread([self = shared_from_this()] { self->accept_loop(); });
}

void Port::open_at(const std::string& name, const net::Endpoint& at) {
  if (core_->open) throw Error("port " + core_->name + " is already open");
  if (name.empty() || name[0] != '/') throw Error("port name \"" + name + "\" must start with '/'");
  core_->access = core_->options.access ? *core_->options.access : AccessPolicy::from_environment();
  core_->name = name;
  core_->start_listening(at);
  log::info(name, "Port " + name + " active at " + core_->address.uri());
}

namespace {

// What YARP clients record next to a registration (reference section 4.1).
void advertise(NameClient& names, const std::string& name) {
  const std::vector<std::string> carriers = carrier::CarrierRegistry::global().names();
  names.set_property(name, "offers", carriers);
  names.set_property(name, "accepts", carriers);
  names.set_property(name, "process", {std::to_string(::getpid())});
}

}  // namespace

void Port::Core::start_keeper() {
  if (options.registration_check.count() <= 0 || !names) return;
  kept = true;
  detail::RegistrationKeeper::instance().add(this, options.registration_check,
                                             [weak = weak_from_this()] {
                                               if (auto self = weak.lock()) self->check_registration();
                                             });
}

void Port::Core::check_registration() {
  if (closing) return;
  try {
    auto known = names->query(name);
    if (!known) {
      names->register_name(name, "tcp", address.host, address.port);
      advertise(*names, name);
      log::warn(name, "the name server had lost " + name + "; registered it again at " + address.uri());
      warned_taken = false;
    } else if ((known->host != address.host || known->port != address.port) && !warned_taken) {
      log::warn(name, "the name server gives " + name + " to " + known->uri() + ", not to this port at " +
                          address.uri() + "; leaving it to that port");
      warned_taken = true;
    }
  } catch (const std::exception& e) {
    log::debug(name, std::string("could not check the registration (will try again): ") + e.what());
  }
}

void Port::Core::stop_keeper() {
  if (!kept) return;
  kept = false;
  detail::RegistrationKeeper::instance().remove(this);
}

void Port::open(const std::string& name, NameClient names) {
  if (core_->open) throw Error("port " + core_->name + " is already open");
  if (name.empty() || name[0] != '/') throw Error("port name \"" + name + "\" must start with '/'");
  core_->access = core_->options.access ? *core_->options.access : AccessPolicy::from_environment();
  Contact reg = names.register_name(name);
  core_->name = name;
  core_->names = names;
  core_->registered = true;
  try {
    core_->start_listening({reg.host, reg.port});
    advertise(names, name);
  } catch (...) {
    try {
      names.unregister(name);
    } catch (const std::exception&) {
    }
    core_->registered = false;
    core_->shutdown();
    throw;
  }
  core_->start_keeper();
  log::info(name, "Port " + name + " active at " + core_->address.uri());
}

void Port::open(const std::string& name) { open(name, NameClient::from_config()); }

void Port::close() {
  // Also for a port that was never opened: its outputs still get their "q".
  core_->open = false;
  core_->shutdown();
}

bool Port::is_open() const { return core_->open; }
const std::string& Port::name() const { return core_->name; }
Contact Port::contact() const { return core_->address; }

void Port::set_resolver(Resolver r) {
  std::lock_guard<std::mutex> lock(core_->mutex);
  core_->resolver = std::move(r);
}

void Port::Core::shutdown() {
  closing = true;
  {
    std::lock_guard<std::mutex> lock(hand_mutex);
    hand_cv.notify_all();
  }
  stop_keeper();  // before unregistering: it must not register the name again
  if (registered && names) {
    try {
      names->unregister(name);
    } catch (const std::exception& e) {
      log::warn(name, std::string("could not unregister: ") + e.what());
    }
    registered = false;
  }
  listener.interrupt();
  if (acceptor.joinable()) acceptor.join();
  listener.close();
  std::vector<std::shared_ptr<OutputUnit>> outs;
  std::list<std::shared_ptr<InputUnit>> ins;
  {
    std::lock_guard<std::mutex> lock(mutex);
    outs.swap(outputs);
    for (auto& in : inputs) {
      if (in->conn) in->conn->interrupt();
    }
    ins = inputs;
  }
  for (auto& o : outs) {
    std::lock_guard<std::mutex> lock(o->mutex);
    o->conn->close();
  }
  for (auto& in : ins) {
    if (in->thread.joinable()) in->thread.join();
  }
  std::lock_guard<std::mutex> lock(mutex);
  inputs.clear();
}

}  // namespace robogene
