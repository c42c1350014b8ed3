// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// The two ends of a connection after the handshake. An inbound (acceptor) connection yields
// messages and lets its owner answer each with a Bottle or raw bytes, then the carrier's ack; an
// outbound (initiator) connection sends messages and collects replies. A server is written as:
//   auto in = carrier::accept_connection(std::move(stream), ctx);
//   while (in->read(msg)) { ...; in->reply_raw(text); in->finish(); }
#pragma once

#include <cstddef>
#include <memory>
#include <string>

#include "robogene/carrier/message.hpp"
#include "robogene/net/stream_reader.hpp"
#include "robogene/net/tcp_stream.hpp"

namespace robogene::carrier {

// A TCP stream with its read buffer; not movable because the reader points at the stream.
struct Link {
  explicit Link(net::TcpStream s) : stream(std::move(s)), reader(stream) {}
  Link(const Link&) = delete;
  Link& operator=(const Link&) = delete;
  net::TcpStream stream;
  net::StreamReader reader;
};

class Connection {
 public:
  virtual ~Connection() = default;
  virtual const std::string& carrier_name() const = 0;
  // The port name of the other side ("/w", "admin", "anon_rpc", ...).
  virtual const std::string& remote_name() const = 0;
  virtual std::string peer_text() const = 0;  // "127.0.0.1:40012" for logs and errors
  virtual bool is_text() const = 0;
  // Wakes a thread blocked on this connection; later calls fail. Safe from any thread.
  virtual void interrupt() noexcept = 0;
  // The socket this end's own packets (data, replies, acks) leave by, for per-connection QoS
  // (IP_TOS, set by the admin message [prop] [set] /peer (qos ...)); -1 when it sends none.
  virtual int socket_fd() const noexcept { return -1; }
};

class OutboundConnection;

class InboundConnection : public Connection {
 public:
  // Reads the next message into `m` (buffers are reused). Returns false when the peer closed
  // cleanly between messages. Throws NetworkError / ParseError naming the peer on bad input.
  virtual bool read(InboundMessage& m) = 0;
  // Answers the current message; the bytes go out with the ack in finish().
  virtual void reply(const Bottle& b) = 0;
  virtual void reply_raw(const void* data, std::size_t size) = 0;
  // Ends the current message: flushes any reply and sends the carrier's ack, if it has one.
  // For a binary 'd' that got no reply an empty Bottle is sent so the requester never stalls.
  virtual void finish() = 0;
  // Turns the connection around after an 'r' command: the peer becomes a reader of our output.
  virtual std::unique_ptr<OutboundConnection> reverse() = 0;
};

class OutboundConnection : public Connection {
 public:
  // Sends one message. When `reply` is given and the message key is 'd' or 'a', waits for the
  // reply Bottle. Then waits for the carrier's ack, if any. Throws NetworkError on failure.
  void send(const OutboundMessage& m, Bottle* reply = nullptr) {
    write_message(m);
    await_completion(reply);
  }
  // The two halves of send(), so that a port writing to many readers can put the message on
  // every connection before waiting for any ack. The Bottle may be released after write_message.
  virtual void write_message(const OutboundMessage& m) = 0;
  // Reads the reply (for 'd' / 'a', into `reply` when given) and the ack of the last message.
  virtual void await_completion(Bottle* reply) = 0;
  // Bounds every later send (and the ack wait): a reader that stops reading makes send() throw.
  virtual void set_timeout(net::Millis t) = 0;
  // Polite close: sends the carrier's quit message where it has one, ignoring failures.
  virtual void close() noexcept = 0;
};

}  // namespace robogene::carrier
