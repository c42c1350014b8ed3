// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// Input side of a Port: accepting connections, one thread per connection, the message loop
// with data, admin, reverse, quit and the text-mode commands of reference section 3.5.
#include <poll.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <string>
#include <system_error>

#include "port_core.hpp"
#include "robogene/carrier/registry.hpp"
#include "robogene/error.hpp"
#include "robogene/log.hpp"

namespace robogene {

namespace {

const char kHelp[] =
    "This is a YARP-compatible port. Commands, one per line:\r\n"
    "*       describe this port and its connections\r\n"
    "d       the next line is data for the port's owner (a reply may follow)\r\n"
    "do      the same as \"d\" without a reply (\"data only\")\r\n"
    "q       disconnect\r\n"
    "r       reverse this connection: receive what the port writes\r\n"
    "/port   send this port's output to /port as well\r\n"
    "!/port  stop sending output to /port\r\n"
    "~/port  stop receiving input from /port\r\n"
    "a       the next line is an administrative message ([help] lists them)\r\n"
    "?       this help\r\n";

const char kNotUnderstood[] =
    "Port command not understood.\r\n"
    "Type d to send data to the port's owner.\r\n"
    "Type ? for help.\r\n";

bool rooted(const std::string& name) { return !name.empty() && name[0] == '/'; }

}  // namespace

void Port::Core::accept_loop() {
  acceptor_tid = static_cast<int>(gettid());
  while (!closing) {
    auto s = listener.accept();
    if (!s) {
      if (closing) break;
      continue;
    }
    reap_finished_inputs();
    auto unit = std::make_shared<InputUnit>();
    std::lock_guard<std::mutex> lock(mutex);
    if (closing) break;
    if (inputs.size() >= options.max_inputs) {
      log::warn(name, "refused a connection from " + s->peer_text() + ": already " +
                          std::to_string(inputs.size()) + " inputs (the limit)");
      continue;  // the stream closes as it goes out of scope
    }
    std::string refused_because;
    unit->slot = ConnectionSlot::try_take(s->peer().host, &refused_because);
    if (!unit->slot.held()) {
      log::warn(name, "refused a connection from " + s->peer_text() + ": " + refused_because);
      continue;
    }
    try {
      unit->thread = std::thread(
          [self = shared_from_this(), unit, stream = std::move(*s)]() mutable {
            self->serve(unit, std::move(stream));
          });
    } catch (const std::system_error& e) {
      log::warn(name, std::string("cannot start a thread for a new connection: ") + e.what());
      continue;
    }
    inputs.push_back(unit);
  }
}

void Port::Core::reap_finished_inputs() {
  std::list<std::shared_ptr<InputUnit>> finished;
  {
    std::lock_guard<std::mutex> lock(mutex);
    for (auto it = inputs.begin(); it != inputs.end();) {
      if ((*it)->done) {
        finished.push_back(*it);
        it = inputs.erase(it);
      } else {
        ++it;
      }
    }
  }
  for (auto& f : finished) {
    if (f->thread.joinable()) f->thread.join();
  }
}

void Port::Core::serve(std::shared_ptr<InputUnit> unit, net::TcpStream stream) {
  unit->tid = static_cast<int>(gettid());
  carrier::AcceptContext ctx;
  ctx.local_name = name;
  ctx.max_message_size = options.max_message_size;
  ctx.handshake_timeout = options.handshake_timeout;
  ctx.access = access;
  const std::string peer_host = stream.peer().host;
  std::string peer = stream.peer_text();
  std::unique_ptr<carrier::InboundConnection> conn;
  auto finished = [&] {
    std::lock_guard<std::mutex> lock(mutex);
    unit->conn = nullptr;
    unit->done = true;
    unit->slot = ConnectionSlot{};
  };
  try {
    conn = carrier::accept_connection(std::move(stream), ctx);
  } catch (const std::exception& e) {
    log::warn(name, std::string("rejected a connection: ") + e.what());
    finished();
    return;
  }
  unit->slot.end_handshake();
  unit->last_heard = std::chrono::steady_clock::now().time_since_epoch().count();
  {
    std::lock_guard<std::mutex> lock(mutex);
    unit->from = conn->remote_name();
    unit->carrier = conn->carrier_name();
    unit->peer_host = peer_host;
    if (closing) {
      unit->done = true;
      unit->slot = ConnectionSlot{};
      return;
    }
    // Datagram writers never say when they leave (YARP's neither): their inputs are bounded
    // by count, and the one silent longest makes room for a new one.
    unit->connectionless = conn->carrier_name() == "udp" || conn->carrier_name() == "mcast";
    if (unit->connectionless) evict_silent_datagram_input(*unit);
    // A new rooted connection from the same source replaces older ones (YARP does the same).
    if (rooted(unit->from)) {
      for (auto& other : inputs) {
        if (other != unit && !other->done && other->from == unit->from && other->conn) {
          other->conn->interrupt();
        }
      }
    }
    unit->conn = conn.get();
  }
  const bool noticed = rooted(unit->from);
  if (noticed) {
    log::info(name, "Receiving input from " + unit->from + " to " + name + " using " + unit->carrier);
  }
  carrier::InboundMessage msg;
  try {
    while (!closing && conn && conn->read(msg)) {
      unit->last_heard = std::chrono::steady_clock::now().time_since_epoch().count();
      if (!handle(*unit, conn, msg)) break;
    }
  } catch (const std::exception& e) {
    if (!closing) {
      log::warn(name, "input from " + unit->from + " (" + peer + ") closed: " + e.what());
    }
  }
  {
    std::lock_guard<std::mutex> lock(mutex);
    unit->conn = nullptr;  // before the connection goes: others look at it under the mutex
  }
  conn.reset();
  if (unit->reversed) {
    watch_reversed(unit->reversed);
    unit->reversed.reset();
  }
  finished();
  if (noticed) log::info(name, "Removing input from " + unit->from + " to " + name);
}

void Port::Core::evict_silent_datagram_input(const InputUnit& unit) {
  std::size_t held = 0;
  InputUnit* silent = nullptr;
  for (auto& other : inputs) {
    if (other.get() == &unit || other->done || other->evicted || !other->conn || !other->connectionless) continue;
    ++held;
    if (!silent || other->last_heard < silent->last_heard) silent = other.get();
  }
  if (held < options.max_datagram_inputs || !silent) return;
  log::warn(name, "dropping the " + silent->carrier + " input from " + silent->from +
                      " (silent longest) to make room: already " + std::to_string(held) +
                      " datagram inputs (ROBOGENE_MAX_DATAGRAM_INPUTS)");
  silent->evicted = true;
  silent->conn->interrupt();
}

void Port::Core::watch_reversed(const std::shared_ptr<OutputUnit>& out) {
  const int fd = out->conn->socket_fd();
  if (fd < 0) return;  // shmem: its own peer check drops it on the next write
  for (;;) {
    {
      std::lock_guard<std::mutex> lock(mutex);
      if (closing || std::find(outputs.begin(), outputs.end(), out) == outputs.end()) return;
    }
    // Only a hang-up matters: the reader's acks (POLLIN) are for the writer to read.
    pollfd p{fd, POLLRDHUP, 0};
    int n = ::poll(&p, 1, 200);
    if (n > 0 && (p.revents & (POLLRDHUP | POLLHUP | POLLERR | POLLNVAL))) break;
  }
  std::lock_guard<std::mutex> lock(out->mutex);  // not in the middle of a write
  {
    std::lock_guard<std::mutex> lock2(mutex);
    auto it = std::find(outputs.begin(), outputs.end(), out);
    if (it == outputs.end()) return;
    outputs.erase(it);
  }
  log::info(name, "Removing output from " + name + " to " + out->target + " (the reader hung up)");
  out->conn->close();
}

bool Port::Core::handle(InputUnit& unit, std::unique_ptr<carrier::InboundConnection>& conn,
                        carrier::InboundMessage& msg) {
  auto& c = *conn;
  switch (msg.key) {
    case 'd':
    case 'D': {
      Bottle data;
      try {
        DecodeLimits limits;
        limits.max_bytes = options.max_message_size;
        limits.max_values = options.max_decoded_values;
        data = msg.take_bottle(limits);
      } catch (const ParseError& e) {
        log::warn(name, "dropped a message from " + unit.from + " (" + c.peer_text() +
                            "): " + e.what() + " (position " + std::to_string(e.position()) + ")");
        c.finish();
        return true;
      }
      MessageInfo info{unit.from, unit.carrier, msg.envelope, msg.reply_expected};
      Bottle reply;
      deliver(data, info, msg.reply_expected ? &reply : nullptr);
      if (msg.reply_expected && (!reply.empty() || !c.is_text())) c.reply(reply);
      c.finish();
      msg.recycle(data);  // the reader is done with it: keep its image buffers for the next one
      return true;
    }
    case 'a': {
      Bottle cmd;
      try {
        cmd = msg.bottle();
      } catch (const ParseError& e) {
        c.reply(Bottle{Value::vocab("fail"), Value(std::string("cannot parse admin message: ") + e.what())});
        c.finish();
        return true;
      }
      c.reply(admin(cmd, unit.peer_host));
      c.finish();
      return true;
    }
    case 'r': {
      c.finish();
      auto out = std::make_shared<OutputUnit>();
      out->target = unit.from;
      out->carrier = unit.carrier;
      out->conn = c.reverse();
      out->conn->set_timeout(options.send_timeout);
      {
        std::lock_guard<std::mutex> lock(mutex);
        unit.conn = nullptr;
      }
      log::info(name, "Sending output from " + name + " to " + unit.from + " using " +
                          unit.carrier + " (reversed)");
      unit.reversed = out;
      add_unit(std::move(out));
      return false;
    }
    case 'q':
      c.finish();
      return false;
    case '/':
    case '!':
    case '~': {
      std::string report;
      if (!access.allows(unit.peer_host)) {
        report = refusal_text("\"" + msg.command + "\"", unit.peer_host) + "\r\n";
        log::warn(name, report.substr(0, report.size() - 2));
      } else if (msg.key == '/') {
        add_output_report(msg.command, report);
      } else if (msg.key == '!') {
        remove_output_report(msg.command.substr(1), report);
      } else {
        remove_input_report(msg.command.substr(1), report);
      }
      c.reply_raw(report.data(), report.size());
      break;
    }
    case '*': {
      std::string text = describe();
      c.reply_raw(text.data(), text.size());
      break;
    }
    case '?':
    case 'h':
      c.reply_raw(kHelp, sizeof kHelp - 1);
      break;
    default:
      c.reply_raw(kNotUnderstood, sizeof kNotUnderstood - 1);
      break;
  }
  c.finish();
  return true;
}

void Port::Core::deliver(const Bottle& data, const MessageInfo& info, Bottle* reply) {
  Reader r;
  {
    std::lock_guard<std::mutex> lock(reader_mutex);
    r = reader;
  }
  if (r) {
    try {
      r(data, info, reply);
    } catch (const std::exception& e) {
      log::warn(name, "reader failed on a message from " + info.from + ": " + e.what());
    }
    return;
  }
  // No reader installed: wait for Port::read, one message at a time.
  std::unique_lock<std::mutex> lk(hand_mutex);
  hand_cv.wait(lk, [&] { return closing || pending == nullptr; });
  if (closing) return;
  Pending p;
  p.data = &data;
  p.info = info;
  p.reply = reply;
  pending = &p;
  hand_cv.notify_all();
  hand_cv.wait(lk, [&] { return closing || p.done; });
  if (pending == &p) pending = nullptr;
  if (replying == &p) replying = nullptr;
  hand_cv.notify_all();
}

std::string Port::Core::describe() const {
  std::string out = "This is " + name + " at " + address.uri() + "\r\n";
  std::lock_guard<std::mutex> lock(mutex);
  int n = 0;
  for (auto& o : outputs) {
    out += "There is an output connection from " + name + " to " + o->target + " using " + o->carrier + "\r\n";
    ++n;
  }
  if (!n) out += "There are no outgoing connections\r\n";
  n = 0;
  for (auto& in : inputs) {
    if (in->done || !in->conn) continue;
    out += "There is an input connection from " + in->from + " to " + name + " using " + in->carrier + "\r\n";
    ++n;
  }
  if (!n) out += "There are no incoming connections\r\n";
  return out;
}

}  // namespace robogene
