// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// Bottle as a container: construction, checked and unchecked access, appending.
#include "robogene/bottle.hpp"

#include <string>
#include <utility>

#include "robogene/error.hpp"

namespace robogene {

namespace {
// What get() returns for a missing index; never modified.
const Value kNull;
}  // namespace

Bottle::Bottle(std::initializer_list<Value> items) : items_(items) {}

const Value& Bottle::at(std::size_t i) const {
  if (i >= items_.size()) {
    throw Error("bottle index " + std::to_string(i) + " out of range (size " + std::to_string(items_.size()) + ")");
  }
  return items_[i];
}

const Value& Bottle::get(std::size_t i) const noexcept { return i < items_.size() ? items_[i] : kNull; }

Bottle& Bottle::add(Value v) {
  items_.push_back(std::move(v));
  return *this;
}

Bottle& Bottle::add_list() {
  items_.emplace_back(Bottle{});
  return items_.back().as_list();
}

}  // namespace robogene
