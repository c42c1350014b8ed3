// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "binary_connections.hpp"

#include <algorithm>
#include <cstring>

#include "binary_framing.hpp"
#include "payload_reader.hpp"
#include "grow_read.hpp"
#include "robogene/carrier/bottle_framer.hpp"
#include "robogene/error.hpp"

namespace robogene::carrier::detail {

namespace {
// An empty Bottle: what a 'd' gets when its reader had nothing to say.
const std::uint8_t kEmptyBottle[8] = {0x00, 0x01, 0, 0, 0, 0, 0, 0};
}  // namespace

BinaryInbound::BinaryInbound(std::unique_ptr<Link> link, std::string carrier, bool acks,
                             std::string remote, std::size_t max_message_size,
                             net::Millis message_timeout)
    : link_(std::move(link)),
      carrier_(std::move(carrier)),
      acks_(acks),
      remote_(std::move(remote)),
      max_message_size_(max_message_size),
      message_timeout_(message_timeout) {
  // Once a message has started, the rest must follow within the timeout; between messages a
  // connection may stay idle for ever (read() polls for the first byte without a timeout).
  link_->stream.set_read_timeout(message_timeout_);
}

bool BinaryInbound::read(InboundMessage& m) {
  reply_expected_ = false;
  replied_ = false;
  reply_.clear();
  auto& r = link_->reader;
  if (r.buffered() == 0) {
    link_->stream.wait_readable(net::kNoTimeout);
    if (!r.wait_for_data()) return false;
  }
  std::uint8_t first8[8];
  r.read_exact(first8, 8);
  read_message_after_first8(
      first8, [&](void* p, std::size_t n) { r.read_exact(p, n); },
      [&](std::size_t n, InboundMessage& mm) { read_payload(r, n, mm); }, m, max_message_size_,
      remote_ + " (" + peer_text() + ")");
  reply_expected_ = m.reply_expected;
  return true;
}

void BinaryInbound::reply(const Bottle& b) {
  if (!reply_expected_) return;  // a 'D' sender is not reading: a reply would corrupt the stream
  b.append_bytes(reply_);
  replied_ = true;
}

void BinaryInbound::reply_raw(const void* data, std::size_t size) {
  if (!reply_expected_) return;
  auto* p = static_cast<const std::uint8_t*>(data);
  reply_.insert(reply_.end(), p, p + size);
  replied_ = true;
}

void BinaryInbound::finish() {
  iovec iov[3];
  std::size_t n = 0;
  if (reply_expected_) {
    if (replied_) {
      iov[n++] = iovec{reply_.data(), reply_.size()};
    } else {
      iov[n++] = iovec{const_cast<std::uint8_t*>(kEmptyBottle), sizeof kEmptyBottle};
    }
  }
  if (acks_) iov[n++] = iovec{const_cast<std::uint8_t*>(kAck), sizeof kAck};
  if (n) link_->stream.writev_all(iov, n);
  reply_expected_ = false;
  replied_ = false;
  reply_.clear();
}

std::unique_ptr<OutboundConnection> BinaryInbound::reverse() {
  return std::make_unique<BinaryOutbound>(std::move(link_), carrier_, acks_, remote_,
                                          max_message_size_);
}

BinaryOutbound::BinaryOutbound(std::unique_ptr<Link> link, std::string carrier, bool acks,
                               std::string remote, std::size_t max_reply_size)
    : link_(std::move(link)),
      carrier_(std::move(carrier)),
      acks_(acks),
      remote_(std::move(remote)),
      max_reply_size_(max_reply_size),
      reply_budget_("reply from " + remote_) {}

void BinaryOutbound::set_timeout(net::Millis t) {
  link_->stream.set_read_timeout(t);
  link_->stream.set_write_timeout(t);
}

void BinaryOutbound::write_message(const OutboundMessage& m) {
  last_key_ = m.key;
  if (m.bottle) {
    payload_.encode(*m.bottle);
    frame_message(m, &payload_, head_, iov_);
  } else {
    frame_message(m, nullptr, head_, iov_);
  }
  link_->stream.writev_all(iov_.data(), iov_.size());
  if (m.bottle) payload_.clear();  // drop references into the caller's blobs
}

void BinaryOutbound::await_completion(Bottle* reply) {
  bool reply_comes = last_key_ == 'd' || last_key_ == 'a';
  last_key_ = 0;
  std::uint8_t first8[8];
  if (reply_comes) {
    link_->reader.read_exact(first8, 8);
    if (acks_ && std::memcmp(first8, kAck, 8) == 0) {
      // The reader did not reply (a plain YARP reader does that): only the ack came.
      if (reply) reply->clear();
      return;
    }
    reply_bytes_.clear();
    DecodeLimits limits;
    limits.max_bytes = max_reply_size_;
    ReleaseOnExit release(reply_budget_, &reply_bytes_);
    read_bottle_bytes(link_->reader, reply_bytes_, limits, first8, &reply_budget_);
    if (reply) *reply = Bottle::from_bytes(reply_bytes_, limits);
  }
  if (acks_) {
    link_->reader.read_exact(first8, 8);
    expect_ack(first8);
  }
}

void BinaryOutbound::expect_ack(const std::uint8_t* first8) {
  auto n = read_yarp_number(first8);
  if (!n || *n < 0) {
    throw NetworkError("expected an ack YA 00 00 00 00 RP from " + remote_ + " (" + peer_text() +
                       "), got " + hex_bytes(first8, 8));
  }
  // The ack may announce bytes to skip (always 0 in practice): read and dropped a piece at a
  // time, never as one buffer of the announced size, and no more than a reply may hold.
  auto skip = static_cast<std::size_t>(*n);
  if (skip > max_reply_size_) {
    throw NetworkError("ack from " + remote_ + " (" + peer_text() + ") announces " +
                       std::to_string(skip) + " bytes to skip, more than the " +
                       std::to_string(max_reply_size_) + "-byte limit of a reply");
  }
  std::uint8_t sink[4096];
  while (skip > 0) {
    std::size_t step = std::min(skip, sizeof sink);
    link_->reader.read_exact(sink, step);
    skip -= step;
  }
}

void BinaryOutbound::close() noexcept {
  if (closed_ || !link_) return;
  closed_ = true;
  try {
    link_->stream.set_read_timeout(net::Millis{1000});
    link_->stream.set_write_timeout(net::Millis{1000});
    OutboundMessage q;
    q.key = 'q';
    send(q, nullptr);
  } catch (const std::exception&) {
    // The peer may be gone already; closing is all that is left to do.
  }
  link_->stream.shutdown();
  link_->stream.close();
}

}  // namespace robogene::carrier::detail
