// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// tcp / fast_tcp connections after the handshake (private to src/carrier).
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "robogene/carrier/connection.hpp"
#include "robogene/carrier/encoded_payload.hpp"
#include "robogene/limits.hpp"

namespace robogene::carrier::detail {

class BinaryInbound final : public InboundConnection {
 public:
  BinaryInbound(std::unique_ptr<Link> link, std::string carrier, bool acks, std::string remote,
                std::size_t max_message_size, net::Millis message_timeout);
  const std::string& carrier_name() const override { return carrier_; }
  const std::string& remote_name() const override { return remote_; }
  std::string peer_text() const override { return link_->stream.peer_text(); }
  bool is_text() const override { return false; }
  void interrupt() noexcept override { link_->stream.shutdown(); }
  int socket_fd() const noexcept override { return link_->stream.fd(); }

  bool read(InboundMessage& m) override;
  void reply(const Bottle& b) override;
  void reply_raw(const void* data, std::size_t size) override;
  void finish() override;
  std::unique_ptr<OutboundConnection> reverse() override;

 private:
  std::unique_ptr<Link> link_;
  std::string carrier_;
  bool acks_;
  std::string remote_;
  std::size_t max_message_size_;
  net::Millis message_timeout_;
  bool reply_expected_ = false;
  bool replied_ = false;
  std::vector<std::uint8_t> reply_;
};

class BinaryOutbound final : public OutboundConnection {
 public:
  BinaryOutbound(std::unique_ptr<Link> link, std::string carrier, bool acks, std::string remote,
                 std::size_t max_reply_size);
  const std::string& carrier_name() const override { return carrier_; }
  const std::string& remote_name() const override { return remote_; }
  std::string peer_text() const override { return link_->stream.peer_text(); }
  bool is_text() const override { return false; }
  void interrupt() noexcept override { link_->stream.shutdown(); }
  int socket_fd() const noexcept override { return link_->stream.fd(); }

  void write_message(const OutboundMessage& m) override;
  void await_completion(Bottle* reply) override;
  void set_timeout(net::Millis t) override;
  void close() noexcept override;

 private:
  void expect_ack(const std::uint8_t* first8);
  char last_key_ = 0;

  std::unique_ptr<Link> link_;
  std::string carrier_;
  bool acks_;
  std::string remote_;
  std::size_t max_reply_size_;
  EncodedPayload payload_;
  std::vector<std::uint8_t> head_;
  std::vector<iovec> iov_;
  std::vector<std::uint8_t> reply_bytes_;
  ReceivingBytes reply_budget_;  // the reply's bytes in the process's bytes-in-transit total
  bool closed_ = false;
};

}  // namespace robogene::carrier::detail
