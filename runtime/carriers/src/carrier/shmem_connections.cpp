// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "shmem_connections.hpp"

#include <poll.h>
#include <sys/socket.h>

#include <cstring>

#include "binary_framing.hpp"
#include "bottle_framer_impl.hpp"
#include "payload_reader.hpp"
#include "robogene/error.hpp"

namespace robogene::carrier::detail {

namespace {
const std::string kShmem = "shmem";
const std::uint8_t kEmptyBottle[8] = {0x00, 0x01, 0, 0, 0, 0, 0, 0};
}  // namespace

ShmChannel::ShmChannel(std::unique_ptr<ShmSegment> s, std::unique_ptr<Link> l, int rx_ring, int tx_ring)
    : seg(std::move(s)), link(std::move(l)), peer(link->stream.peer_text() + " (shm " + seg->name() + ")"),
      rx_ring(rx_ring) {
  rx.emplace(*seg, rx_ring, peer, [this] { return peer_alive(); });
  tx.emplace(*seg, tx_ring, peer, [this] { return peer_alive(); });
}

void ShmChannel::turn_around() {
  const int was_rx = rx_ring;
  rx_ring = 1 - was_rx;
  rx.emplace(*seg, rx_ring, peer, [this] { return peer_alive(); });
  tx.emplace(*seg, was_rx, peer, [this] { return peer_alive(); });
}

ShmChannel::~ShmChannel() {
  interrupt();
  link->stream.close();
}

bool ShmChannel::peer_alive() const {
  // Nothing is ever sent on this socket after the handshake: readable means closed or broken.
  pollfd p{link->stream.fd(), POLLIN | POLLRDHUP, 0};
  int n = ::poll(&p, 1, 0);
  return n == 0;
}

void ShmChannel::interrupt() noexcept {
  rx->close();
  tx->close();
  link->stream.shutdown();
}

ShmemInbound::ShmemInbound(std::unique_ptr<ShmChannel> ch, std::string remote, std::size_t max_message_size,
                           net::Millis message_timeout)
    : ch_(std::move(ch)), remote_(std::move(remote)), max_message_size_(max_message_size),
      message_timeout_(message_timeout) {
  ch_->rx->set_read_timeout(message_timeout_);
}

const std::string& ShmemInbound::carrier_name() const { return kShmem; }

bool ShmemInbound::read(InboundMessage& m) {
  reply_expected_ = false;
  replied_ = false;
  reply_.clear();
  if (!ch_->rx->wait_readable()) return false;
  std::uint8_t first8[8];
  ch_->rx->read_exact(first8, 8);
  read_message_after_first8(
      first8, [&](void* p, std::size_t n) { ch_->rx->read_exact(p, n); },
      [&](std::size_t n, InboundMessage& mm) { read_payload_from(*ch_->rx, n, mm); }, m, max_message_size_,
      remote_ + " (shmem " + ch_->peer + ")");
  reply_expected_ = m.reply_expected;
  return true;
}

void ShmemInbound::reply(const Bottle& b) {
  if (!reply_expected_) return;
  b.append_bytes(reply_);
  replied_ = true;
}

void ShmemInbound::reply_raw(const void* data, std::size_t size) {
  if (!reply_expected_) return;
  auto* p = static_cast<const std::uint8_t*>(data);
  reply_.insert(reply_.end(), p, p + size);
  replied_ = true;
}

void ShmemInbound::finish() {
  iovec iov[2];
  std::size_t n = 0;
  if (reply_expected_) {
    iov[n++] = replied_ ? iovec{reply_.data(), reply_.size()}
                        : iovec{const_cast<std::uint8_t*>(kEmptyBottle), sizeof kEmptyBottle};
  }
  iov[n++] = iovec{const_cast<std::uint8_t*>(kAck), sizeof kAck};
  ch_->tx->write(iov, n, message_timeout_);
  reply_expected_ = false;
  replied_ = false;
  reply_.clear();
}

std::unique_ptr<OutboundConnection> ShmemInbound::reverse() {
  // Same rings, roles swapped: we now write messages where we wrote acks, and read acks back.
  ch_->turn_around();
  return std::make_unique<ShmemOutbound>(std::move(ch_), remote_, max_message_size_, message_timeout_);
}

ShmemOutbound::ShmemOutbound(std::unique_ptr<ShmChannel> ch, std::string remote, std::size_t max_reply_size,
                             net::Millis timeout)
    : ch_(std::move(ch)), remote_(std::move(remote)), max_reply_size_(max_reply_size),
      reply_budget_("reply from " + remote_) {
  set_timeout(timeout);
}

const std::string& ShmemOutbound::carrier_name() const { return kShmem; }

void ShmemOutbound::set_timeout(net::Millis t) {
  timeout_ = t;
  ch_->rx->set_read_timeout(t);
}

void ShmemOutbound::write_message(const OutboundMessage& m) {
  last_key_ = m.key;
  if (m.bottle) {
    payload_.encode(*m.bottle);
    frame_message(m, &payload_, head_, iov_);
  } else {
    frame_message(m, nullptr, head_, iov_);
  }
  ch_->tx->write(iov_.data(), iov_.size(), timeout_);
  if (m.bottle) payload_.clear();
}

void ShmemOutbound::await_completion(Bottle* reply) {
  bool reply_comes = last_key_ == 'd' || last_key_ == 'a';
  last_key_ = 0;
  std::uint8_t first8[8];
  if (reply_comes) {
    ch_->rx->read_exact(first8, 8);
    if (std::memcmp(first8, kAck, 8) == 0) {
      if (reply) reply->clear();
      return;
    }
    reply_bytes_.clear();
    DecodeLimits limits;
    limits.max_bytes = max_reply_size_;
    ReleaseOnExit release(reply_budget_, &reply_bytes_);
    read_bottle_bytes_from(*ch_->rx, reply_bytes_, limits, first8, &reply_budget_);
    if (reply) *reply = Bottle::from_bytes(reply_bytes_, limits);
  }
  ch_->rx->read_exact(first8, 8);
  if (std::memcmp(first8, kAck, 8) != 0) {
    throw NetworkError("expected an ack YA 00 00 00 00 RP from " + remote_ + " (" + ch_->peer + "), got " +
                       hex_bytes(first8, 8));
  }
}

void ShmemOutbound::close() noexcept {
  if (closed_ || !ch_) return;
  closed_ = true;
  try {
    set_timeout(net::Millis{1000});
    OutboundMessage q;
    q.key = 'q';
    send(q, nullptr);
  } catch (const std::exception&) {
    // The peer may be gone already; closing is all that is left to do.
  }
  ch_->interrupt();
}

}  // namespace robogene::carrier::detail
