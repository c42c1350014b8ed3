// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// Connections over CRC-framed datagrams, shared by udp and mcast (reference section 3.6): each
// message is the tcp message (index + PortCommand + payload) cut into datagrams of at most
// 65507 bytes, each prefixed `int32 crc32(rest), int32 counter`. No acks, no replies.
// `Socket` is anything with UdpSocket's receive / send_to / interrupt / close (private to
// src/carrier).
#pragma once

#include <algorithm>
#include <cstring>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "binary_framing.hpp"
#include "robogene/carrier/crc32.hpp"
#include "grow_read.hpp"
#include "payload_reader.hpp"
#include "robogene/carrier/connection.hpp"
#include "robogene/carrier/encoded_payload.hpp"
#include "robogene/carrier/yarp_number.hpp"
#include "robogene/error.hpp"
#include "robogene/log.hpp"
#include "robogene/net/endpoint.hpp"

namespace robogene::carrier::detail {

constexpr std::size_t kMaxDatagram = 65507;
constexpr std::size_t kDatagramPrefix = 8;

template <typename Socket>
class DatagramInbound final : public InboundConnection {
 public:
  DatagramInbound(Socket sock, std::string carrier, std::string remote, std::string peer,
                  std::size_t max_size)
      : sock_(std::move(sock)), carrier_(std::move(carrier)), remote_(std::move(remote)),
        peer_(std::move(peer)), max_size_(max_size), buf_(kMaxDatagram + 64) {}
  const std::string& carrier_name() const override { return carrier_; }
  const std::string& remote_name() const override { return remote_; }
  std::string peer_text() const override { return peer_; }
  bool is_text() const override { return false; }
  void interrupt() noexcept override { sock_.interrupt(); }

  bool read(InboundMessage& m) override {
    for (;;) {
      if (!head_waiting_ && !next_datagram(net::kNoTimeout, true)) return false;
      head_waiting_ = false;
      if (counter_ != 0) continue;  // the tail of a message whose head was lost
      try {
        expected_ = 1;
        std::uint8_t first8[8];
        pull(first8, 8);
        read_message_after_first8(
            first8, [&](void* p, std::size_t n) { pull(p, n); },
            [&](std::size_t n, InboundMessage& mm) {
              mm.detached_blobs.clear();
              mm.detached_blob_ordinals.clear();
              mm.payload.clear();
              // Big messages count in the process's bytes in transit, as on tcp.
              std::optional<ReceivingBytes> budget;
              if (n >= kDetachBlobsFrom) {
                budget.emplace(remote_ + "'s " + carrier_ + " message of " + std::to_string(n) + " bytes");
              }
              append_growing(*this, mm.payload, n, budget ? &*budget : nullptr);
            },
            m, max_size_, remote_ + " (" + carrier_ + " " + peer_ + ")");
        m.reply_expected = false;  // connectionless: nobody waits for a reply
        return true;
      } catch (const Error& e) {
        log::warn(remote_, "dropped a " + carrier_ + " message: " + e.what());
      }
    }
  }
  void reply(const Bottle&) override {}
  void reply_raw(const void*, std::size_t) override {}
  void finish() override {}
  std::unique_ptr<OutboundConnection> reverse() override {
    throw Error(carrier_ + " connection from " + remote_ + " cannot be reversed (connectionless)");
  }

 private:
  // Receives one datagram and checks its CRC; false when interrupted or timed out.
  bool next_datagram(net::Millis timeout, bool skip_bad) {
    for (;;) {
      net::Endpoint from;
      auto n = sock_.receive(buf_.data(), buf_.size(), timeout, &from);
      if (!n) return false;
      if (*n < kDatagramPrefix) {
        if (skip_bad) continue;
        throw ParseError(0, "datagram of " + std::to_string(*n) + " bytes is shorter than its prefix");
      }
      std::uint32_t crc = static_cast<std::uint32_t>(get_int32(buf_.data()));
      if (crc != crc32(buf_.data() + kDatagramPrefix, *n - kDatagramPrefix)) {
        std::string what = carrier_ + " datagram from " + from.to_string() + " failed its CRC check";
        if (!skip_bad) throw ParseError(0, what);
        log::warn(remote_, what);
        continue;
      }
      counter_ = get_int32(buf_.data() + 4);
      pos_ = kDatagramPrefix;
      len_ = *n;
      return true;
    }
  }

 public:
  // The source append_growing reads from: the datagrams of the current message.
  void read_exact(void* out, std::size_t n) { pull(out, n); }

 private:
  void pull(void* out, std::size_t n) {
    auto* p = static_cast<std::uint8_t*>(out);
    while (n > 0) {
      if (pos_ == len_) {
        if (!next_datagram(net::Millis{2000}, false)) {
          throw NetworkError(carrier_ + " message from " + remote_ + " stopped arriving mid-message");
        }
        if (counter_ != expected_) {
          // The first datagram of the next message: this one lost its tail, that one is whole.
          head_waiting_ = counter_ == 0;
          throw ParseError(0, carrier_ + " datagram " + std::to_string(expected_) + " of a message from " +
                                  remote_ + " was lost (got number " + std::to_string(counter_) + ")");
        }
        ++expected_;
      }
      std::size_t take = std::min(n, len_ - pos_);
      std::memcpy(p, buf_.data() + pos_, take);
      pos_ += take;
      p += take;
      n -= take;
    }
  }

  Socket sock_;
  std::string carrier_;
  std::string remote_;
  std::string peer_;
  std::size_t max_size_;
  std::vector<std::uint8_t> buf_;
  std::size_t pos_ = 0;
  std::size_t len_ = 0;
  std::int32_t counter_ = 0;
  std::int32_t expected_ = 0;
  bool head_waiting_ = false;  // buf_ holds the first datagram of a message not read yet
};

// Frames one outbound message as datagrams; `emit(iov, 2)` sends each (prefix, slice).
class DatagramFramer {
 public:
  template <typename Emit>
  void send(const OutboundMessage& m, Emit&& emit) {
    if (m.bottle) {
      payload_.encode(*m.bottle);
      frame_message(m, &payload_, head_, iov_);
    } else {
      frame_message(m, nullptr, head_, iov_);
    }
    bytes_.clear();
    for (const iovec& v : iov_) {
      auto* p = static_cast<const std::uint8_t*>(v.iov_base);
      bytes_.insert(bytes_.end(), p, p + v.iov_len);
    }
    payload_.clear();
    std::int32_t counter = 0;
    const std::size_t slice = kMaxDatagram - kDatagramPrefix;
    for (std::size_t at = 0; at < bytes_.size(); at += slice, ++counter) {
      std::size_t n = std::min(slice, bytes_.size() - at);
      std::uint8_t prefix[kDatagramPrefix];
      put_int32(prefix, static_cast<std::int32_t>(crc32(bytes_.data() + at, n)));
      put_int32(prefix + 4, counter);
      iovec parts[2] = {{prefix, kDatagramPrefix}, {bytes_.data() + at, n}};
      emit(parts, 2);
    }
  }

 private:
  EncodedPayload payload_;
  std::vector<std::uint8_t> head_;
  std::vector<iovec> iov_;
  std::vector<std::uint8_t> bytes_;
};

}  // namespace robogene::carrier::detail
