// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "name_sessions.hpp"

#include <cstdio>
#include <string>

#include "robogene/error.hpp"

namespace robogene::name::detail {
namespace {

constexpr std::size_t kMaxSenderName = 1000;  // as YARP's expectSenderSpecifier

void send_text(SessionContext& c, const std::string& text) { c.stream.write_all(text.data(), text.size()); }

void send_bytes(SessionContext& c, const std::vector<std::uint8_t>& bytes) {
  if (!bytes.empty()) c.stream.write_all(bytes.data(), bytes.size());
}

std::string hex(const std::uint8_t* p, std::size_t n) {
  static const char digits[] = "0123456789abcdef";
  std::string out;
  for (std::size_t i = 0; i < n; ++i) {
    if (i) out += ' ';
    out += digits[p[i] >> 4];
    out += digits[p[i] & 15];
  }
  return out;
}

// Parses `text` as a request and applies it; a malformed bottle gets an old-style error naming
// the column.
NameReply apply_text(SessionContext& c, const std::string& text) {
  Bottle request;
  try {
    request = Bottle::from_text(text);
  } catch (const ParseError& e) {
    NameReply reply;
    reply.lines.push_back("*** error: column " + std::to_string(e.position()) + ": " + e.what());
    return reply;
  }
  return c.service.apply(request, c.stream.peer().host);
}

bool is_word(const Value& v, const char* w) {
  if (v.is_string()) return v.as_string() == w;
  if (v.is_vocab()) return vocab_to_string(v.as_vocab()) == w;
  return false;
}

// The port-administration requests (reference 3.4) that make sense for /root, which has inputs
// but never outputs.
Bottle admin_reply(SessionContext& c, const Bottle& request) {
  Bottle reply;
  const Value& cmd = request.get(0);
  if (is_word(cmd, "ver")) {
    reply.add(Value::vocab("ver"));
    reply.add(Value::int32(1));
    reply.add(Value::int32(2));
    reply.add(Value::int32(3));
  } else if (is_word(cmd, "help")) {
    for (const char* line : {"[help]  this list", "[ver]  protocol version", "[list] [in]  input connections",
                             "[list] [in] $port  details of one input", "[list] [out]  output connections (none)"}) {
      reply.add(Value::string(line));
    }
  } else if (is_word(cmd, "list") && is_word(request.get(1), "out")) {
    // /root has no outputs: an empty reply, as a port without that connection gives.
  } else if (is_word(cmd, "list") && is_word(request.get(1), "in")) {
    const Value& which = request.get(2);
    for (const auto& p : c.peers()) {
      if (which.is_null()) {
        reply.add(Value::string(p.name));
      } else if (which.is_string() && which.as_string() == p.name) {
        reply.add(Value::list(Bottle{Value::string("from"), Value::string(p.name)}));
        reply.add(Value::list(Bottle{Value::string("to"), Value::string("/root")}));
        reply.add(Value::list(Bottle{Value::string("carrier"), Value::string(p.carrier)}));
        break;
      }
    }
  } else if (is_word(cmd, "add") || is_word(cmd, "del")) {
    reply.add(Value::int32(-1));
    reply.add(Value::string("/root is the name server: it makes no output connections"));
  } else {
    reply.add(Value::vocab("fail"));
    reply.add(Value::string("send [help] for the list of administrative commands"));
  }
  return reply;
}

std::string describe_root(SessionContext& c) {
  std::string out = "This is /root at " + c.root_address + "\r\n";
  out += "There are no outgoing connections\r\n";
  auto peers = c.peers();
  if (peers.empty()) out += "There are no incoming connections\r\n";
  for (const auto& p : peers) {
    out += "There is an input connection from " + p.name + " to /root using " + p.carrier + "\r\n";
  }
  out += "*** end of message\r\n";
  return out;
}

const char* const kTextHelp =
    "This is the name server /root, speaking the text carrier. One command per line:\r\n"
    "d       the next line is a request (try: d, then help, or: d, then query /port)\r\n"
    "a       the next line is an administrative request such as [ver] or [list] [in]\r\n"
    "*       describe this port and its connections\r\n"
    "?       this help\r\n"
    "q       close the connection\r\n"
    "*** end of message\r\n";

}  // namespace

void SessionContext::log(const std::string& what) const {
  std::fprintf(stderr, "robogene server: %s: %s\n", stream.peer_text().c_str(), what.c_str());
}

void serve_name_ser(SessionContext& c, const wire::Header& header) {
  c.identify("anonymous", "name_ser");
  std::string first(header.begin(), header.end());
  first += c.reader.read_line(c.limits.max_line);
  if (first.compare(0, 12, "NAME_SERVER ") != 0 && first != "NAME_SERVER") {
    send_text(c, "*** error: a name_ser connection must start with \"NAME_SERVER \", got \"" + first.substr(0, 40) +
                     "\"\r\n*** end of message\r\n");
    c.log("name_ser request does not start with \"NAME_SERVER \"");
    return;
  }
  send_text(c, apply_text(c, first).to_text_wire());
  // YARP clients send one request per connection; further lines are served the same way.
  while (c.reader.wait_for_data()) {
    std::string line = c.reader.read_line(c.limits.max_line);
    if (line.empty()) continue;
    send_text(c, apply_text(c, line).to_text_wire());
  }
}

void serve_text(SessionContext& c, bool with_acks) {
  std::string name = c.reader.read_line(kMaxSenderName);
  c.identify(name, with_acks ? "text_ack" : "text");
  send_text(c, "Welcome " + name + "\r\n");
  const std::string ack = with_acks ? "<ACK>\r\n" : "";
  c.stream.set_read_timeout(net::Millis{c.limits.idle_timeout_ms});
  while (c.reader.wait_for_data()) {
    std::string line = c.reader.read_line(c.limits.max_line);
    if (line.empty()) continue;
    switch (line[0]) {
      case 'd': {
        // A bottle may span lines (unbalanced quotes or brackets pull in the next one).
        std::string text = c.reader.read_line(c.limits.max_line);
        while (!Bottle::text_is_complete(text)) {
          if (text.size() > c.limits.max_line) {
            send_text(c, "*** error: request longer than " + std::to_string(c.limits.max_line) +
                             " bytes without closing its quotes or brackets\r\n*** end of message\r\n" + ack);
            c.log("text request too long");
            return;
          }
          text += "\n" + c.reader.read_line(c.limits.max_line);
        }
        send_text(c, apply_text(c, text).to_text_wire() + ack);
        break;
      }
      case 'a': {
        std::string text = c.reader.read_line(c.limits.max_line);
        std::string out;
        try {
          out = admin_reply(c, Bottle::from_text(text)).to_text() + "\r\n";
        } catch (const ParseError& e) {
          out = "[fail] \"column " + std::to_string(e.position()) + ": " + e.what() + "\"\r\n";
        }
        send_text(c, out + ack);
        break;
      }
      case 'q':
        return;
      case '*':
        send_text(c, describe_root(c) + ack);
        break;
      case '?':
      case 'h':
        send_text(c, kTextHelp + ack);
        break;
      case 'r':
        // Reverse: the peer would read our output, but /root writes none. Nothing to send.
        send_text(c, ack);
        break;
      case '/':
      case '!':
      case '~':
        send_text(c, "/root is the name server: it makes no connections of its own\r\n" + ack);
        break;
      default:
        send_text(c, "Unknown command \"" + line.substr(0, 40) +
                         "\": to send a request type d, then the request on the next line; ? for help\r\n" + ack);
        break;
    }
  }
}

void serve_tcp(SessionContext& c, bool with_acks) {
  std::uint8_t len_bytes[4];
  c.reader.read_exact(len_bytes, 4);
  std::int32_t len = wire::le32(len_bytes);
  if (len <= 0 || static_cast<std::size_t>(len) > kMaxSenderName) {
    c.log("sender name length " + std::to_string(len) + " at byte offset 8 is outside 1.." +
          std::to_string(kMaxSenderName));
    return;
  }
  std::string name(static_cast<std::size_t>(len), '\0');
  c.reader.read_exact(name.data(), name.size());
  while (!name.empty() && name.back() == '\0') name.pop_back();
  c.identify(name, with_acks ? "tcp" : "fast_tcp");
  auto reply_header = wire::yarp_number(c.stream.local().port);
  c.stream.write_all(reply_header.data(), reply_header.size());
  c.stream.set_read_timeout(net::Millis{c.limits.idle_timeout_ms});
  const wire::Header ack = wire::yarp_number(0);

  while (c.reader.wait_for_data()) {
    const std::uint64_t at = c.reader.consumed();
    wire::Header index;
    c.reader.read_exact(index.data(), index.size());
    auto index_len = wire::read_yarp_number(index);
    if (!index_len || *index_len != 10) {
      c.log("expected a message index \"YA 0a 00 00 00 RP\" at byte offset " + std::to_string(at) + ", got " +
            hex(index.data(), index.size()));
      return;
    }
    std::uint8_t counts[10];
    c.reader.read_exact(counts, sizeof counts);
    const std::size_t blocks = std::size_t{counts[0]} + counts[1];
    std::size_t total = 0;
    for (std::size_t i = 0; i < blocks; ++i) {
      c.reader.read_exact(len_bytes, 4);
      std::int32_t n = wire::le32(len_bytes);
      if (n < 0 || total + static_cast<std::size_t>(n) > c.limits.max_message) {
        c.log("block length " + std::to_string(n) + " in the index at byte offset " + std::to_string(at) +
              " is negative or exceeds the " + std::to_string(c.limits.max_message) + "-byte limit");
        return;
      }
      total += static_cast<std::size_t>(n);
    }
    std::vector<std::uint8_t> body(total);
    if (total) c.reader.read_exact(body.data(), total);
    const std::uint64_t body_at = c.reader.consumed() - total;
    if (total < 8 || body[4] != '~') {
      c.log("expected a PortCommand ('~') at byte offset " + std::to_string(body_at + 4));
      return;
    }
    char ch = static_cast<char>(body[5]);
    std::size_t payload_at = 8;
    if (ch == 0) {
      std::int32_t slen = wire::le32(body.data());
      if (slen < 1 || 8 + static_cast<std::size_t>(slen) > total) {
        c.log("PortCommand string length " + std::to_string(slen) + " at byte offset " + std::to_string(body_at) +
              " does not fit the message");
        return;
      }
      ch = static_cast<char>(body[8]);
      payload_at = 8 + static_cast<std::size_t>(slen);
    }
    if (ch == 'q') {
      if (with_acks) c.stream.write_all(ack.data(), ack.size());
      return;
    }
    const std::uint8_t* payload = body.data() + payload_at;
    const std::size_t payload_size = total - payload_at;
    if (ch == 'd' || ch == 'D' || ch == 'a') {
      std::vector<std::uint8_t> reply;
      try {
        Bottle request = Bottle::from_bytes(payload, payload_size);
        if (ch == 'a') {
          reply = admin_reply(c, request).to_bytes();
        } else {
          reply = c.service.apply(request, c.stream.peer().host).to_binary_wire();
        }
      } catch (const ParseError& e) {
        c.log("bad bottle at byte offset " + std::to_string(body_at + payload_at + e.position()) + ": " + e.what());
        reply = Bottle{Value::string("error"),
                       Value::string("bad bottle at byte " + std::to_string(e.position()) + " of the payload: " +
                                     e.what())}
                    .to_bytes();
      }
      if (ch != 'D') send_bytes(c, reply);
    } else if (ch != 'r') {
      c.log(std::string("unknown PortCommand '") + ch + "' at byte offset " + std::to_string(body_at + 5));
      return;
    }
    if (with_acks) c.stream.write_all(ack.data(), ack.size());
  }
}

void refuse_unknown_carrier(SessionContext& c, const wire::Header& header) {
  c.log("no carrier starts with " + hex(header.data(), header.size()));
  send_text(c, "* Error: no carrier starts with the bytes " + hex(header.data(), header.size()) +
                   ".\r\n* If you are a human, try typing \"CONNECT foo\" and then \"?\".\r\n");
}

}  // namespace robogene::name::detail
