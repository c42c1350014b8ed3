// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "robogene/name/name_ser_carrier.hpp"

#include <sys/socket.h>

#include <cstring>
#include <string>

#include "robogene/error.hpp"

namespace robogene::name {
namespace {

constexpr char kHeader[] = "NAME_SER";
const std::string kCarrierName = "name_ser";

// Acceptor side: one line, one request ("NAME_SERVER ..." once the header is put back).
class NameSerInbound final : public carrier::InboundConnection {
 public:
  NameSerInbound(std::unique_ptr<carrier::Link> link, std::size_t max_line)
      : link_(std::move(link)), max_line_(max_line) {}
  const std::string& carrier_name() const override { return kCarrierName; }
  const std::string& remote_name() const override { return remote_; }
  std::string peer_text() const override { return link_->stream.peer_text(); }
  bool is_text() const override { return true; }
  void interrupt() noexcept override { link_->stream.shutdown(); }
  int socket_fd() const noexcept override { return link_->stream.fd(); }

  bool read(carrier::InboundMessage& m) override {
    std::string line;
    if (first_) {
      first_ = false;
      line = kHeader + link_->reader.read_line(max_line_);  // the header is the start of the line
      if (line.compare(0, 12, "NAME_SERVER ") != 0 && line != "NAME_SERVER") {
        throw ParseError(0, "name_ser connection from " + peer_text() +
                                " does not start with \"NAME_SERVER \": \"" + line.substr(0, 40) + "\"");
      }
    } else {
      // One request per connection, as YARP's clients send: closing after the reply tells a
      // client that reads until EOF (replies such as "[ok]" have no end marker) that we are done.
      return false;
    }
    m.key = 'd';
    m.command = "d";
    m.envelope.clear();
    m.text_mode = true;
    m.reply_expected = true;
    m.payload.assign(line.begin(), line.end());
    return true;
  }

  void reply(const Bottle& b) override { out_ += b.to_text() + "\r\n"; }
  void reply_raw(const void* data, std::size_t size) override { out_.append(static_cast<const char*>(data), size); }
  void finish() override {
    if (!out_.empty()) link_->stream.write_all(out_.data(), out_.size());
    out_.clear();
  }
  std::unique_ptr<carrier::OutboundConnection> reverse() override {
    throw Error("a name_ser connection from " + peer_text() + " cannot be reversed");
  }

 private:
  std::unique_ptr<carrier::Link> link_;
  std::size_t max_line_;
  std::string remote_ = "anonymous";
  bool first_ = true;
  std::string out_;
};

// Initiator side: one request per connection, as YARP's NameClient does. The reply lines (without
// "*** end of message") come back as a Bottle of strings.
class NameSerOutbound final : public carrier::OutboundConnection {
 public:
  NameSerOutbound(std::unique_ptr<carrier::Link> link, std::string target)
      : link_(std::move(link)), remote_(std::move(target)) {}
  const std::string& carrier_name() const override { return kCarrierName; }
  const std::string& remote_name() const override { return remote_; }
  std::string peer_text() const override { return link_->stream.peer_text(); }
  bool is_text() const override { return true; }
  void interrupt() noexcept override { link_->stream.shutdown(); }
  int socket_fd() const noexcept override { return link_->stream.fd(); }

  void write_message(const carrier::OutboundMessage& m) override {
    if (used_) throw Error("name_ser carries one request per connection (to " + peer_text() + ")");
    used_ = true;
    if (!m.bottle) throw Error("name_ser: nothing to send to " + peer_text());
    // The 8 header bytes were sent by connect(); "VER " completes "NAME_SERVER".
    std::string line = "VER " + m.bottle->to_text() + "\r\n";
    link_->stream.write_all(line.data(), line.size());
    ::shutdown(link_->stream.fd(), SHUT_WR);
  }
  void await_completion(Bottle* reply) override {
    Bottle lines;
    while (link_->reader.wait_for_data()) {
      std::string text = link_->reader.read_line(1u << 20);
      if (text == "*** end of message") break;
      lines.add(Value::string(text));
    }
    if (reply) *reply = std::move(lines);
  }
  void set_timeout(net::Millis t) override {
    link_->stream.set_read_timeout(t);
    link_->stream.set_write_timeout(t);
  }
  void close() noexcept override { link_->stream.close(); }

 private:
  std::unique_ptr<carrier::Link> link_;
  std::string remote_;
  bool used_ = false;
};

class NameSerCarrier final : public carrier::Carrier {
 public:
  std::string name() const override { return kCarrierName; }
  bool matches(const carrier::Header& h) const override { return std::memcmp(h.data(), kHeader, 8) == 0; }
  carrier::Header header() const override {
    carrier::Header h;
    std::memcpy(h.data(), kHeader, 8);
    return h;
  }
  bool is_text() const override { return true; }
  std::unique_ptr<carrier::InboundConnection> accept(std::unique_ptr<carrier::Link> link,
                                                     const carrier::AcceptContext& ctx) const override {
    link->stream.set_read_timeout(ctx.handshake_timeout);
    return std::make_unique<NameSerInbound>(std::move(link), ctx.max_line_length);
  }
  std::unique_ptr<carrier::OutboundConnection> connect(std::unique_ptr<carrier::Link> link,
                                                       const carrier::ConnectContext& ctx) const override {
    link->stream.set_read_timeout(ctx.timeout);
    link->stream.set_write_timeout(ctx.timeout);
    carrier::Header h = header();
    link->stream.write_all(h.data(), h.size());
    return std::make_unique<NameSerOutbound>(std::move(link), ctx.target_name);
  }
};

}  // namespace

std::shared_ptr<const carrier::Carrier> make_name_ser_carrier() { return std::make_shared<NameSerCarrier>(); }

}  // namespace robogene::name
