// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// shmem: ports on one host exchange messages through shared memory. The header is YARP's
// (`YA 6f 1e 00 00 RP`, specifier 14) and so is the sender name; then the acceptor creates a
// POSIX shm segment with two rings and answers `YA <n> RP` followed by the segment's n-byte
// NUL-terminated name; the initiator maps it and confirms with `YA 00 00 00 00 RP`, and the
// acceptor unlinks the name (the memory lives on while mapped, and nothing is left behind
// if either process dies). YARP's own shmem answers with the number of a second tcp port and
// uses ACE shared memory, which Robogene does not speak: docs/protocol/connections.md section 9.
#include <cstring>
#include <memory>
#include <string>
#include <vector>

#include "binary_framing.hpp"
#include "robogene/carrier/binary_handshake.hpp"
#include "robogene/carrier/builtin_carriers.hpp"
#include "robogene/carrier/yarp_number.hpp"
#include "robogene/error.hpp"
#include "shmem_connections.hpp"

namespace robogene::carrier {

namespace {

constexpr std::int32_t kShmemSpecifier = 7777 + 14;
// Messages (initiator to acceptor) get the bigger ring: several camera frames fit at once.
constexpr std::uint32_t kForwardRing = 8u << 20;
constexpr std::uint32_t kBackwardRing = 1u << 20;
constexpr std::int32_t kMaxSegmentName = 255;

class ShmemCarrier final : public Carrier {
 public:
  std::string name() const override { return "shmem"; }
  Header header() const override { return make_yarp_number(kShmemSpecifier); }
  bool matches(const Header& h) const override {
    auto n = read_yarp_number(h.data());
    return n && *n >= 7777 && (*n - 7777) % 16 == 14;
  }

  std::unique_ptr<InboundConnection> accept(std::unique_ptr<Link> link,
                                            const AcceptContext& ctx) const override {
    std::string remote = read_binary_sender_name(*link, ctx.max_name_length);
    // Shared memory works only between processes of one host: a peer on another host gets no
    // segment (9 MB each) for a handshake that cannot succeed. A local peer is one whose
    // address is ours (loopback, or the interface it reached us on).
    const std::string& from = link->stream.peer().host;
    if (from != link->stream.local().host && from.rfind("127.", 0) != 0) {
      throw NetworkError("shmem connection from " + remote + " (" + link->stream.peer_text() +
                         "): refused, the peer is on another host (shmem needs both ports on one host)");
    }
    auto seg = detail::ShmSegment::create(kForwardRing, kBackwardRing);
    std::vector<std::uint8_t> answer;
    Header n = make_yarp_number(static_cast<std::int32_t>(seg->name().size() + 1));
    answer.insert(answer.end(), n.begin(), n.end());
    answer.insert(answer.end(), seg->name().begin(), seg->name().end());
    answer.push_back(0);
    link->stream.write_all(answer.data(), answer.size());
    std::uint8_t confirm[8];
    link->reader.read_exact(confirm, 8);  // within the handshake timeout
    if (std::memcmp(confirm, detail::kAck, 8) != 0) {
      throw NetworkError("shmem handshake with " + remote + " (" + link->stream.peer_text() +
                         "): expected YA 00 00 00 00 RP once the segment was mapped, got " +
                         detail::hex_bytes(confirm, 8));
    }
    seg->unlink();
    link->stream.set_read_timeout(net::kNoTimeout);
    auto ch = std::make_unique<detail::ShmChannel>(std::move(seg), std::move(link), 0, 1);
    return std::make_unique<detail::ShmemInbound>(std::move(ch), remote, ctx.max_message_size,
                                                  ctx.handshake_timeout);
  }

  std::unique_ptr<OutboundConnection> connect(std::unique_ptr<Link> link,
                                              const ConnectContext& ctx) const override {
    link->stream.set_read_timeout(ctx.timeout);
    link->stream.set_write_timeout(ctx.timeout);
    send_binary_hello(*link, header(), ctx.sender_name);
    const std::string where = "shmem handshake with " + ctx.target_name + " (" + link->stream.peer_text() + ")";
    const std::int32_t len = read_binary_answer(*link, where, "YA <n> RP");
    if (len < 2 || len > kMaxSegmentName) {
      throw NetworkError(where + ": the peer answered YA " + std::to_string(len) +
                         " RP, as YARP's ACE shmem does (a second tcp port); Robogene speaks only its "
                         "POSIX shared-memory variant");
    }
    std::string seg_name(static_cast<std::size_t>(len), '\0');
    link->reader.read_exact(seg_name.data(), seg_name.size());
    if (seg_name.back() != '\0' || seg_name[0] != '/' || seg_name.find('\0') != seg_name.size() - 1) {
      throw NetworkError(where + ": the segment name is not a NUL-terminated \"/name\"");
    }
    seg_name.pop_back();
    auto seg = detail::ShmSegment::open(seg_name);
    link->stream.write_all(detail::kAck, 8);
    link->stream.set_read_timeout(net::kNoTimeout);
    auto ch = std::make_unique<detail::ShmChannel>(std::move(seg), std::move(link), 1, 0);
    return std::make_unique<detail::ShmemOutbound>(std::move(ch), ctx.target_name, ctx.max_message_size,
                                                   ctx.timeout);
  }
};

}  // namespace

std::shared_ptr<const Carrier> make_shmem_carrier() { return std::make_shared<ShmemCarrier>(); }

}  // namespace robogene::carrier
