// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// Reading arguments from, and writing results into, control-board RPC bottles the way YARP 3
// does: numbers convert (an int is accepted where a float64 is expected, as asFloat64 does),
// strings are accepted where vocabs are (as asVocab32 does), booleans travel as int32 0/1 and
// per-axis values as nested lists. Readers return false instead of throwing, so a malformed
// request becomes a [fail] reply, never an exception on the server's thread.
#pragma once

#include <cstdint>
#include <string>
#include <type_traits>
#include <vector>

#include "robogene/bottle.hpp"

namespace robogene::dev::rpc {

static_assert(std::is_same_v<int, std::int32_t>, "joint indices are int32 on the wire");

bool read(const Value& v, std::int32_t& out);
bool read(const Value& v, double& out);
bool read(const Value& v, bool& out);
bool read(const Value& v, std::string& out);
bool read_vocab(const Value& v, vocab_t& out);

void write(Bottle& b, std::int32_t v);
void write(Bottle& b, double v);
void write(Bottle& b, bool v);
void write(Bottle& b, const std::string& v);
void write_vocab(Bottle& b, vocab_t v);

// The vocab at `v` (string or vocab item), or 0 when `v` is neither; never throws.
vocab_t vocab_of(const Value& v) noexcept;

template <class T>
bool read(const Value& v, std::vector<T>& out) {
  if (!v.is_list()) return false;
  out.clear();
  out.reserve(v.as_list().size());
  for (const Value& item : v.as_list()) {
    T element{};
    if (!read(item, element)) return false;
    out.push_back(element);
  }
  return true;
}

template <class T>
void write(Bottle& b, const std::vector<T>& values) {
  Bottle& list = b.add_list();
  for (const auto& v : values) write(list, static_cast<T>(v));
}

// Appends YARP's `[tsta] <count> <time>` (appendTimeStamp) and `[ok]` to a value reply.
void finish_value_reply(Bottle& reply, std::int32_t count, double time);

}  // namespace robogene::dev::rpc
