// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// A port (paper section 4.1): a named endpoint with any number of inputs and outputs over any
// registered carrier. It listens on tcp, registers with the name server, answers YARP's admin
// messages ([add] [del] [list] [ver] [help], binary 'a' or text) and text-mode commands, so
// `yarp connect`, `yarp read/write` and telnet users can drive it. One thread per connection.
#pragma once

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "robogene/access_policy.hpp"
#include "robogene/bottle.hpp"
#include "robogene/carrier/message.hpp"
#include "robogene/contact.hpp"
#include "robogene/limits.hpp"
#include "robogene/name_client.hpp"
#include "robogene/net/endpoint.hpp"
#include "robogene/net/tcp_stream.hpp"

namespace robogene {

// Defaults come from resource_limits() (robogene/limits.hpp: environment variables), so a
// deployment changes them without a rebuild; docs/security.md lists them.
struct PortOptions {
  std::size_t max_message_size = resource_limits().max_message_size;  // larger ones are refused
  // Values one incoming message may decode to (a 1-byte int becomes a 16-byte Value).
  std::size_t max_decoded_values = resource_limits().max_decoded_values;
  // An output whose reader does not take a message (and its ack) within this time is dropped,
  // so one stalled reader cannot hold the writer or the other outputs for longer.
  net::Millis send_timeout{2000};
  net::Millis connect_timeout{5000};
  net::Millis handshake_timeout{10000};
  // Connections beyond this many open inputs are closed at once (one thread each); the
  // process as a whole holds at most ResourceLimits::max_connections.
  std::size_t max_inputs = 512;
  // Who may connect, disconnect and configure this port or write to it over HTTP
  // (docs/security.md); unset = AccessPolicy::from_environment() when the port opens.
  std::optional<AccessPolicy> access;
  // udp / mcast inputs kept (their writers never say when they leave): one more evicts the
  // input that has been silent longest.
  std::size_t max_datagram_inputs = resource_limits().max_datagram_inputs;
  // How often a registered port checks that the name server still knows it, and registers
  // again when it does not (0 = never).
  net::Millis registration_check = resource_limits().registration_check;
};

// What a reader learns about one incoming message besides its content.
struct MessageInfo {
  std::string from;        // sender port name
  std::string carrier;     // "tcp", "text", ...
  std::string envelope;    // "" when none
  bool reply_expected = false;
};

class Port {
 public:
  // Called on the connection's own thread for each data message. `reply` is non-null when the
  // sender waits for an answer: fill it (left empty, an empty Bottle is sent).
  using Reader = std::function<void(const Bottle& data, const MessageInfo& info, Bottle* reply)>;
  using Resolver = std::function<std::optional<Contact>(const std::string& name)>;

  Port();
  explicit Port(PortOptions options);
  ~Port();
  Port(const Port&) = delete;
  Port& operator=(const Port&) = delete;

  // Opens `name` and registers it with `names` (the server picks the number; the port then
  // listens on the registered host and number). Throws robogene::Error on failure.
  void open(const std::string& name, NameClient names);
  // As above with the name server from the YARP configuration.
  void open(const std::string& name);
  // Opens at an explicit address without any name server (port 0 = ephemeral).
  void open_at(const std::string& name, const net::Endpoint& at);
  // Sends "q" on outputs, unregisters, stops and joins every thread. Idempotent.
  void close();
  bool is_open() const;

  const std::string& name() const;
  Contact contact() const;  // where this port listens

  // Names of other ports are found with the name client given to open(); tests and tools
  // without a name server can supply their own lookup.
  void set_resolver(Resolver r);
  // A port need not be opened to write: an unopened port connects its outputs as the anonymous
  // sender "anon_rpc" (like `yarp rpc`) and listens nowhere.

  // Connects this port's output to `target` ("/r" or "tcp://r"); `carrier` overrides. Replaces
  // an existing connection to the same port. Throws robogene::Error naming the target.
  void add_output(const std::string& target, const std::string& carrier = "");
  void add_output(const Contact& to);
  bool remove_output(const std::string& name);
  bool remove_input(const std::string& name);
  std::vector<std::string> output_names() const;
  std::vector<std::string> input_names() const;

  // Sends to every output without waiting for replies ('D'); false when there is no output.
  bool write(const Bottle& b);
  // Sends to the first output and waits for its reply ('d'); false when there is no output or
  // the connection failed (then it is dropped).
  bool write(const Bottle& b, Bottle& reply);
  // Attached to every later write as "D <envelope>" (empty = none).
  void set_envelope(std::string envelope);
  // A user-defined property of the port, as admin [prop] [set] key value sets it: any peer may
  // read it with [prop] [get] key, answered by the port itself (YARP 3 ports do the same).
  void set_property(const std::string& key, const Value& value);

  // Installs a reader; without one, messages wait for read().
  void set_reader(Reader r);
  // Blocks until a message arrives (or timeout / close: false). With will_reply, the sender
  // (if it waits) gets the Bottle given to reply().
  bool read(Bottle& b, bool will_reply = false, net::Millis timeout = net::kNoTimeout,
            MessageInfo* info = nullptr);
  void reply(const Bottle& b);

 private:
  struct Core;
  std::shared_ptr<Core> core_;
};

}  // namespace robogene
