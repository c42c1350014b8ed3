// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// Whether bottle text typed so far is a whole bottle (balanced quotes, parentheses and braces,
// no dangling `\`), kept up to date as text arrives: each byte is looked at once, so a text
// carrier reading a long message line by line costs time linear in its bytes.
#pragma once

#include <string_view>

namespace robogene {

class TextCompleteness {
 public:
  void feed(std::string_view text) noexcept;
  // Mirrors YARP's isComplete: a surplus ')' or '}' counts as complete (more lines cannot
  // repair it; the parser reports it).
  bool complete() const noexcept { return !escape_ && !quoted_ && parens_ <= 0 && braces_ <= 0; }

 private:
  bool quoted_ = false;
  bool escape_ = false;
  long parens_ = 0;
  long braces_ = 0;
};

}  // namespace robogene
