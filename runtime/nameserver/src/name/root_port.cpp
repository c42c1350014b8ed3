// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "root_port.hpp"

#include <cstdio>
#include <string>

#include "robogene/error.hpp"

namespace robogene::name::detail {
namespace {

bool is_word(const Value& v, const char* w) {
  if (v.is_string()) return v.as_string() == w;
  if (v.is_vocab()) return vocab_to_string(v.as_vocab()) == w;
  return false;
}

// The administrative requests (reference 3.4) that make sense for /root, which has inputs but
// never outputs.
Bottle admin_reply(RootPortContext& c, const Bottle& request) {
  Bottle reply;
  const Value& cmd = request.get(0);
  if (is_word(cmd, "ver")) {
    reply = Bottle{Value::vocab("ver"), Value::int32(1), Value::int32(2), Value::int32(3)};
  } else if (is_word(cmd, "help")) {
    for (const char* line : {"[help]  this list", "[ver]  protocol version", "[list] [in]  input connections",
                             "[list] [in] $port  details of one input", "[list] [out]  output connections (none)"}) {
      reply.add(Value::string(line));
    }
  } else if (is_word(cmd, "list") && is_word(request.get(1), "out")) {
    // /root has no outputs: an empty reply, as any port without that connection gives.
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
    reply = Bottle{Value::int32(-1), Value::string("/root is the name server: it makes no output connections")};
  } else {
    reply = Bottle{Value::vocab("fail"), Value::string("send [help] for the list of administrative commands")};
  }
  return reply;
}

std::string describe_root(RootPortContext& c) {
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

const char kTextHelp[] =
    "This is the name server /root. One command per line:\r\n"
    "d       the next line is a request (try: d, then help, or: d, then query /port)\r\n"
    "a       the next line is an administrative request such as [ver] or [list] [in]\r\n"
    "*       describe this port and its connections\r\n"
    "?       this help\r\n"
    "q       close the connection\r\n"
    "*** end of message\r\n";

void reply_text(carrier::InboundConnection& in, const std::string& text) { in.reply_raw(text.data(), text.size()); }

}  // namespace

void serve_root_messages(RootPortContext& c, carrier::InboundConnection& in) {
  carrier::InboundMessage m;
  while (in.read(m)) {
    if (c.heard) c.heard();
    switch (m.key) {
      case 'd':
      case 'D': {
        NameReply reply;
        try {
          reply = c.service.apply(m.bottle(), c.peer_host);
        } catch (const ParseError& e) {
          std::string where = m.text_mode ? "column " : "byte ";
          reply.old_style = !in.is_text() ? false : true;
          if (reply.old_style) {
            reply.lines.push_back("*** error: bad request at " + where + std::to_string(e.position()) + ": " + e.what());
          } else {
            reply.bottle = Bottle{Value::string("error"), Value::string("bad bottle at " + where +
                                                                         std::to_string(e.position()) + ": " + e.what())};
          }
          std::fprintf(stderr, "robogene server: %s: bad request at %s%zu: %s\n", in.peer_text().c_str(), where.c_str(),
                       e.position(), e.what());
        }
        if (m.reply_expected) {
          if (reply.old_style) {
            reply_text(in, reply.to_text_wire());
          } else {
            in.reply(reply.bottle);
          }
        }
        break;
      }
      case 'a': {
        Bottle reply;
        try {
          reply = admin_reply(c, m.bottle());
        } catch (const ParseError& e) {
          reply = Bottle{Value::vocab("fail"), Value::string("bad administrative request at position " +
                                                             std::to_string(e.position()) + ": " + e.what())};
        }
        in.reply(reply);
        break;
      }
      case 'q':
        in.finish();  // YARP acks the disconnect too (yarp_write_to_sniff.flows.txt)
        return;
      case 0:
        continue;  // an empty line typed at a text connection
      case '*':
        reply_text(in, describe_root(c));
        break;
      case '?':
      case 'h':
        reply_text(in, kTextHelp);
        break;
      case 'r':
        break;  // reverse: the peer would read our output, but /root writes none
      case '/':
      case '!':
      case '~':
        reply_text(in, "/root is the name server: it makes no connections of its own\r\n");
        break;
      default:
        if (in.is_text()) {
          reply_text(in, "Unknown command \"" + m.command.substr(0, 40) +
                             "\": to send a request type d, then the request on the next line; ? for help\r\n");
        }
        break;
    }
    in.finish();
  }
}

}  // namespace robogene::name::detail
