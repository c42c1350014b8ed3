// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// Searchable-style lookups (YARP's Bottle::find / findGroup), used to read device configurations
// such as `(name /motors) (axes 4)` or `name /motors axes 4`.
#include <string_view>

#include "robogene/bottle.hpp"

namespace robogene {

namespace {

const Value kNull;

// YARP compares the key with the item's plain text; we match the two types a key can be
// written as: a string or a vocab (`[axes]` matches "axes").
bool is_key(const Value& v, std::string_view key) {
  if (v.is_string()) return v.as_string() == key;
  if (v.is_vocab()) return vocab_to_string(v.as_vocab()) == key && !key.empty();
  return false;
}

}  // namespace

const Value& Bottle::find(std::string_view key) const noexcept {
  for (std::size_t i = 0; i < items_.size(); ++i) {
    const Value& item = items_[i];
    if (item.is_list()) {
      const Bottle& group = item.as_list();
      if (!group.empty() && is_key(group[0], key)) return group.get(1);
    } else if (is_key(item, key)) {
      return get(i + 1);
    }
  }
  return kNull;
}

const Bottle* Bottle::find_group(std::string_view key) const noexcept {
  for (const Value& item : items_) {
    if (!item.is_list()) continue;
    const Bottle& group = item.as_list();
    if (!group.empty() && is_key(group[0], key)) return &group;
  }
  return nullptr;
}

}  // namespace robogene
