// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "robogene/contact.hpp"

#include "robogene/error.hpp"

namespace robogene {

Target parse_target(std::string_view text) {
  Target t;
  auto mark = text.find(":/");
  if (mark != std::string_view::npos && mark > 0 && text.substr(0, mark).find('/') == std::string_view::npos) {
    t.carrier = std::string(text.substr(0, mark));
    t.name = std::string(text.substr(mark + 2));
  } else {
    t.name = std::string(text);
  }
  if (t.name.size() < 2 || t.name[0] != '/') {
    throw Error("\"" + std::string(text) + "\" is not a port name (expected /name or carrier://name)");
  }
  return t;
}

}  // namespace robogene
