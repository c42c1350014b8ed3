// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// shmem connections after the handshake (private to src/carrier): tcp's message format (index,
// PortCommand, payload; raw reply; `YA 00 00 00 00 RP` ack) carried through the two rings of a
// shared segment. The handshake's tcp socket stays open, silent, so that each side notices at
// once when the other process is gone.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "robogene/carrier/connection.hpp"
#include "robogene/carrier/encoded_payload.hpp"
#include "robogene/limits.hpp"
#include "shm_segment.hpp"

namespace robogene::carrier::detail {

// The segment, the liveness socket and the two directions, shared by both ends' classes.
struct ShmChannel {
  ShmChannel(std::unique_ptr<ShmSegment> seg, std::unique_ptr<Link> link, int rx_ring, int tx_ring);
  ~ShmChannel();
  bool peer_alive() const;
  void interrupt() noexcept;
  // Swaps the directions (a reversed connection writes where it used to read).
  void turn_around();

  std::unique_ptr<ShmSegment> seg;
  std::unique_ptr<Link> link;
  std::string peer;  // "127.0.0.1:40112 (shm /robogene-shmem-...)"
  int rx_ring;
  std::optional<ShmStream> rx;
  std::optional<ShmStream> tx;
};

class ShmemInbound final : public InboundConnection {
 public:
  ShmemInbound(std::unique_ptr<ShmChannel> ch, std::string remote, std::size_t max_message_size,
               net::Millis message_timeout);
  const std::string& carrier_name() const override;
  const std::string& remote_name() const override { return remote_; }
  std::string peer_text() const override { return ch_->peer; }
  bool is_text() const override { return false; }
  void interrupt() noexcept override { ch_->interrupt(); }

  bool read(InboundMessage& m) override;
  void reply(const Bottle& b) override;
  void reply_raw(const void* data, std::size_t size) override;
  void finish() override;
  std::unique_ptr<OutboundConnection> reverse() override;

 private:
  std::unique_ptr<ShmChannel> ch_;
  std::string remote_;
  std::size_t max_message_size_;
  net::Millis message_timeout_;
  bool reply_expected_ = false;
  bool replied_ = false;
  std::vector<std::uint8_t> reply_;
};

class ShmemOutbound final : public OutboundConnection {
 public:
  ShmemOutbound(std::unique_ptr<ShmChannel> ch, std::string remote, std::size_t max_reply_size,
                net::Millis timeout);
  const std::string& carrier_name() const override;
  const std::string& remote_name() const override { return remote_; }
  std::string peer_text() const override { return ch_->peer; }
  bool is_text() const override { return false; }
  void interrupt() noexcept override { ch_->interrupt(); }

  void write_message(const OutboundMessage& m) override;
  void await_completion(Bottle* reply) override;
  void set_timeout(net::Millis t) override;
  void close() noexcept override;

 private:
  std::unique_ptr<ShmChannel> ch_;
  std::string remote_;
  std::size_t max_reply_size_;
  net::Millis timeout_;
  char last_key_ = 0;
  EncodedPayload payload_;
  std::vector<std::uint8_t> head_;
  std::vector<iovec> iov_;
  std::vector<std::uint8_t> reply_bytes_;
  ReceivingBytes reply_budget_;  // the reply's bytes in the process's bytes-in-transit total
  bool closed_ = false;
};

}  // namespace robogene::carrier::detail
