// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// What the name server answers. yarpserver has two shapes (reference section 4.2): "old style"
// text lines closed by `*** end of message` (what YARP's own clients parse), and Bottles for
// `bot ...` requests and a few commands such as `announce`.
#pragma once

#include <string>
#include <vector>

#include "robogene/bottle.hpp"

namespace robogene::name {

struct NameReply {
  bool old_style = true;
  std::vector<std::string> lines;  // old style: one entry per line, without terminator
  Bottle bottle;                   // otherwise

  // The bytes a text-mode peer (name_ser, text, text_ack, a raw `NAME_SERVER` line) receives:
  // each line + "\r\n" then "*** end of message\r\n", or the Bottle's text form + "\r\n".
  std::string to_text_wire() const;
  // The bytes a binary (tcp) peer receives: old style goes out as the same raw text lines (as
  // yarpserver does), a Bottle in its binary form.
  std::vector<std::uint8_t> to_binary_wire() const;
};

// One old-style line from items, rendered as yarpserver does: the Bottle text form with every
// double quote removed ("registration name /x ip 127.0.0.1 port 10002 type tcp").
std::string old_style_line(const Bottle& items);

}  // namespace robogene::name
