// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// The shared state behind a Port: its listener, one thread per input connection, the outputs,
// and the hand-off between input threads and Port::read (private to src/port).
#pragma once

#include <atomic>
#include <condition_variable>
#include <list>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "robogene/carrier/connection.hpp"
#include "robogene/limits.hpp"
#include "robogene/net/tcp_listener.hpp"
#include "robogene/port.hpp"

namespace robogene {

struct OutputUnit {
  std::string target;   // the reader's port name
  std::string carrier;
  std::unique_ptr<carrier::OutboundConnection> conn;
  std::mutex mutex;     // one message at a time on a connection
};

struct InputUnit {
  std::string from;
  std::string carrier;
  std::string peer_host;  // the address the connection came from, for the access policy
  carrier::InboundConnection* conn = nullptr;  // valid while the thread owns it (under Core::mutex)
  std::thread thread;
  std::atomic<int> tid{-1};  // the thread's kernel id, for [prop] [get] / [set] (sched ...)
  bool done = false;
  bool connectionless = false;  // udp / mcast: counted against max_datagram_inputs
  bool evicted = false;         // told to leave to make room (its thread is winding down)
  // When the connection last delivered a message (steady clock), to evict the longest-silent
  // datagram input first.
  std::atomic<std::int64_t> last_heard{0};
  // After 'r': the output this connection became, watched until its reader hangs up.
  std::shared_ptr<OutputUnit> reversed;
  ConnectionSlot slot;  // this connection's share of ResourceLimits::max_connections
};

struct Port::Core : std::enable_shared_from_this<Port::Core> {
  explicit Core(PortOptions o) : options(o) {}

  PortOptions options;
  AccessPolicy access;  // options.access or the environment's, fixed when the port opens
  std::string name;
  Contact address;
  std::optional<NameClient> names;
  bool registered = false;
  Resolver resolver;

  net::TcpListener listener;
  std::thread acceptor;
  std::atomic<int> acceptor_tid{-1};
  std::atomic<bool> open{false};
  std::atomic<bool> closing{false};
  // How the owner has used the port so far, for [prop] [get] /thisport (YARP's port flags).
  std::atomic<bool> used_for_input{false}, used_for_output{false}, used_for_rpc{false};

  mutable std::mutex mutex;  // outputs, inputs, resolver, properties
  std::vector<std::shared_ptr<OutputUnit>> outputs;
  std::list<std::shared_ptr<InputUnit>> inputs;
  Bottle properties;  // user-defined, as (key value) lists: [prop] [set] key value

  std::mutex write_mutex;  // one write at a time; guards envelope
  std::string envelope;

  std::mutex reader_mutex;
  Reader reader;

  // Hand-off to Port::read when no reader is installed.
  struct Pending {
    const Bottle* data = nullptr;
    MessageInfo info;
    Bottle* reply = nullptr;
    bool taken = false;
    bool done = false;
  };
  std::mutex hand_mutex;
  std::condition_variable hand_cv;
  Pending* pending = nullptr;
  Pending* replying = nullptr;

  void start_listening(const net::Endpoint& at);
  void accept_loop();
  void serve(std::shared_ptr<InputUnit> unit, net::TcpStream stream);
  // Handles one message; false ends the connection's thread.
  bool handle(InputUnit& unit, std::unique_ptr<carrier::InboundConnection>& conn,
              carrier::InboundMessage& msg);
  void deliver(const Bottle& data, const MessageInfo& info, Bottle* reply);
  void reap_finished_inputs();
  // Makes room for a new udp / mcast input `unit` (under mutex): interrupts the input silent
  // longest when the port already holds max_datagram_inputs of them.
  void evict_silent_datagram_input(const InputUnit& unit);
  // Until the reversed output's reader hangs up (or the output is dropped, or the port closes).
  void watch_reversed(const std::shared_ptr<OutputUnit>& out);
  void shutdown();

  // Registration keeping: a port whose name the server lost (unregistered while the port was
  // too busy to answer a liveness probe, or a server restarted without its database)
  // registers again at the same address. The process's one RegistrationKeeper thread runs
  // check_registration every options.registration_check.
  bool kept = false;
  bool warned_taken = false;
  void start_keeper();
  void check_registration();
  void stop_keeper();

  // Operations shared by the API, admin messages and text commands; each returns YARP's
  // one-line report ("Added connection from /w to tcp://r\r\n") and whether it worked.
  bool add_output_report(const std::string& target_text, std::string& report);
  void connect_output(const Contact& to, const std::string& carrier);
  bool remove_output_report(const std::string& target, std::string& report);
  bool remove_input_report(const std::string& from, std::string& report);
  std::string describe() const;
  // `peer_host` is where the request came from: control commands are checked against `access`.
  Bottle admin(const Bottle& cmd, const std::string& peer_host);
  // Whether `peer_host` is the other end of a connection to/from the port `target`.
  bool is_end_of(const std::string& target, const std::string& peer_host) const;
  Bottle admin_prop(const Bottle& cmd);  // [prop] [get] / [prop] [set] (port_properties.cpp)
  void put_property(const std::string& key, const Value& value);  // with mutex held
  void add_unit(std::shared_ptr<OutputUnit> unit);
  void drop_output(const std::shared_ptr<OutputUnit>& unit, const std::string& why);
  std::optional<Contact> resolve(const std::string& port_name);
};

}  // namespace robogene
