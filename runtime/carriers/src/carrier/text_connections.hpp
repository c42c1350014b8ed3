// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// text / text_ack connections: one command per line, bottles in their text form, "<ACK>" after
// each message on text_ack (reference section 3.5). Private to src/carrier.
#pragma once

#include <memory>
#include <string>

#include "robogene/carrier/connection.hpp"
#include "robogene/limits.hpp"

namespace robogene::carrier::detail {

class TextInbound final : public InboundConnection {
 public:
  TextInbound(std::unique_ptr<Link> link, std::string carrier, bool acks, std::string remote,
              std::size_t max_message_size, std::size_t max_line);
  const std::string& carrier_name() const override { return carrier_; }
  const std::string& remote_name() const override { return remote_; }
  std::string peer_text() const override { return link_->stream.peer_text(); }
  bool is_text() const override { return true; }
  void interrupt() noexcept override { link_->stream.shutdown(); }
  int socket_fd() const noexcept override { return link_->stream.fd(); }

  bool read(InboundMessage& m) override;
  void reply(const Bottle& b) override;
  void reply_raw(const void* data, std::size_t size) override;
  void finish() override;
  std::unique_ptr<OutboundConnection> reverse() override;

 private:
  // Reads line(s) until they hold one whole bottle in text form.
  void read_bottle_text(InboundMessage& m);

  std::unique_ptr<Link> link_;
  std::string carrier_;
  bool acks_;
  std::string remote_;
  std::size_t max_message_size_;
  std::size_t max_line_;
  std::string out_;
};

class TextOutbound final : public OutboundConnection {
 public:
  // `reversed`: the peer turned this connection around with "r"; it is a person or a reader
  // that does not send "<ACK>" lines, so none are awaited. A reply is at most
  // `max_reply_size` bytes of text.
  TextOutbound(std::unique_ptr<Link> link, std::string carrier, bool acks, std::string remote,
               std::size_t max_line, std::size_t max_reply_size, bool reversed);
  const std::string& carrier_name() const override { return carrier_; }
  const std::string& remote_name() const override { return remote_; }
  std::string peer_text() const override { return link_->stream.peer_text(); }
  bool is_text() const override { return true; }
  void interrupt() noexcept override { link_->stream.shutdown(); }
  int socket_fd() const noexcept override { return link_->stream.fd(); }

  void write_message(const OutboundMessage& m) override;
  void await_completion(Bottle* reply) override;
  void set_timeout(net::Millis t) override;
  void close() noexcept override;

 private:
  std::unique_ptr<Link> link_;
  std::string carrier_;
  bool acks_;
  std::string remote_;
  std::size_t max_line_;
  std::size_t max_reply_size_;
  ReceivingBytes reply_budget_;  // the reply's bytes in the process's bytes-in-transit total
  bool reversed_;
  bool closed_ = false;
  bool awaiting_ = false;
};

}  // namespace robogene::carrier::detail
