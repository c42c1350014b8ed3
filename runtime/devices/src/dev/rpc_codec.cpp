// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "robogene/dev/rpc_codec.hpp"

#include <limits>

namespace robogene::dev::rpc {

bool read(const Value& v, std::int32_t& out) {
  if (!v.is_int()) return false;
  const std::int64_t n = v.as_int64();
  if (n < std::numeric_limits<std::int32_t>::min() || n > std::numeric_limits<std::int32_t>::max()) {
    return false;
  }
  out = static_cast<std::int32_t>(n);
  return true;
}

bool read(const Value& v, double& out) {
  if (!v.is_number()) return false;
  out = v.as_float64();
  return true;
}

bool read(const Value& v, bool& out) {
  if (v.is_int() && (v.as_int64() == 0 || v.as_int64() == 1)) {
    out = v.as_int64() == 1;
    return true;
  }
  if (v.is_vocab() && (v.as_vocab() == 0 || v.as_vocab() == vocab("1"))) {
    out = v.as_vocab() != 0;  // YARP's true / false
    return true;
  }
  return false;
}

bool read(const Value& v, std::string& out) {
  if (!v.is_string()) return false;
  out = v.as_string();
  return true;
}

vocab_t vocab_of(const Value& v) noexcept {
  if (v.is_vocab()) return v.as_vocab();
  if (v.is_string() && !v.as_string().empty()) {  // truncated to 4 chars, as YARP does
    return vocab(v.as_string());
  }
  return 0;
}

bool read_vocab(const Value& v, vocab_t& out) {
  const vocab_t code = vocab_of(v);
  if (code == 0) return false;
  out = code;
  return true;
}

void write(Bottle& b, std::int32_t v) { b.add(Value::int32(v)); }
void write(Bottle& b, double v) { b.add(Value::float64(v)); }
void write(Bottle& b, bool v) { b.add(Value::int32(v ? 1 : 0)); }
void write(Bottle& b, const std::string& v) { b.add(Value::string(v)); }
void write_vocab(Bottle& b, vocab_t v) { b.add(Value::vocab(v)); }

void finish_value_reply(Bottle& reply, std::int32_t count, double time) {
  reply.add(Value::vocab(vocab("tsta")));
  reply.add(Value::int32(count));
  reply.add(Value::float64(time));
  reply.add(Value::vocab(vocab("ok")));
}

}  // namespace robogene::dev::rpc
