// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "robogene/carrier/binary_handshake.hpp"

#include "binary_connections.hpp"
#include "binary_framing.hpp"
#include "robogene/error.hpp"

namespace robogene::carrier {

std::vector<std::uint8_t> binary_hello(const Header& header, const std::string& sender_name,
                                       const std::vector<std::uint8_t>& extra) {
  std::vector<std::uint8_t> out(header.begin(), header.end());
  out.resize(out.size() + 4);
  put_int32(out.data() + header.size(), static_cast<std::int32_t>(sender_name.size() + 1));
  out.insert(out.end(), sender_name.begin(), sender_name.end());
  out.push_back(0);
  out.insert(out.end(), extra.begin(), extra.end());
  return out;
}

void send_binary_hello(Link& link, const Header& header, const std::string& sender_name,
                       const std::vector<std::uint8_t>& extra) {
  const std::vector<std::uint8_t> hello = binary_hello(header, sender_name, extra);
  link.stream.write_all(hello.data(), hello.size());
}

std::int32_t read_binary_answer(Link& link, const std::string& where, const std::string& expected) {
  std::uint8_t answer[8];
  link.reader.read_exact(answer, 8);
  auto n = read_yarp_number(answer);
  if (!n) throw NetworkError(where + ": expected " + expected + ", got " + detail::hex_bytes(answer, 8));
  return *n;
}

std::string read_binary_sender_name(Link& link, std::size_t max_length) {
  std::uint8_t len_bytes[4];
  link.reader.read_exact(len_bytes, 4);
  std::int32_t len = get_int32(len_bytes);
  if (len < 1 || static_cast<std::size_t>(len) > max_length) {
    throw ParseError(8, "handshake from " + link.stream.peer_text() + ": sender name length " +
                            std::to_string(len) + " at byte offset 8 is outside 1.." +
                            std::to_string(max_length));
  }
  std::string name(static_cast<std::size_t>(len), '\0');
  link.reader.read_exact(name.data(), name.size());
  auto nul = name.find('\0');
  if (nul != std::string::npos) name.resize(nul);
  auto space = name.find(' ');
  if (space != std::string::npos) name.resize(space);
  return name;
}

void send_binary_answer(Link& link, std::int32_t n) {
  const Header answer = make_yarp_number(n);
  link.stream.write_all(answer.data(), answer.size());
}

std::unique_ptr<OutboundConnection> tcp_outbound_after_handshake(std::unique_ptr<Link> link, bool acks,
                                                                 const std::string& target,
                                                                 std::size_t max_reply_size) {
  return std::make_unique<detail::BinaryOutbound>(std::move(link), acks ? "tcp" : "fast_tcp", acks, target,
                                                  max_reply_size);
}

}  // namespace robogene::carrier
