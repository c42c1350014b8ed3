// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// Reads the typed value trees of bottles.json ({"int32": 1}, {"list": [...]}, ...) into Bottles.
#include "robogene/testing/vector_cases.hpp"

#include <cmath>
#include <fstream>
#include <limits>
#include <nlohmann/json.hpp>

#include "robogene/error.hpp"

namespace robogene::testing {

namespace {

using nlohmann::json;

double float_of(const json& j) {
  if (j.is_string()) {
    const std::string s = j.get<std::string>();
    if (s == "nan") return std::numeric_limits<double>::quiet_NaN();
    if (s == "inf") return std::numeric_limits<double>::infinity();
    if (s == "-inf") return -std::numeric_limits<double>::infinity();
    throw Error("bottles.json: bad float '" + s + "'");
  }
  return j.get<double>();
}

Bottle bottle_of(const json& items);

Value value_of(const json& j) {
  if (!j.is_object() || j.size() != 1) throw Error("bottles.json: a value must be a one-key object: " + j.dump());
  const auto it = j.begin();
  const std::string kind = it.key();
  const json& x = it.value();
  if (kind == "int8") return Value::int8(x.get<std::int8_t>());
  if (kind == "int16") return Value::int16(x.get<std::int16_t>());
  if (kind == "int32") return Value::int32(x.get<std::int32_t>());
  if (kind == "int64") return Value::int64(x.get<std::int64_t>());
  if (kind == "float32") return Value::float32(static_cast<float>(float_of(x)));
  if (kind == "float64") return Value::float64(float_of(x));
  if (kind == "vocab") return Value::vocab(x.get<std::string>());
  if (kind == "string") return Value::string(x.get<std::string>());
  if (kind == "blob") return Value::blob(from_hex(x.get<std::string>()));
  if (kind == "list") return Value::list(bottle_of(x));
  throw Error("bottles.json: unknown value kind '" + kind + "'");
}

Bottle bottle_of(const json& items) {
  Bottle b;
  for (const json& item : items) b.add(value_of(item));
  return b;
}

BottleVectors load() {
  const std::string path = std::string(ROBOGENE_SOURCE_DIR) + "/tests/vectors/bottles.json";
  std::ifstream in(path);
  if (!in) throw Error("cannot open " + path);
  const json doc = json::parse(in);
  BottleVectors v;
  for (const json& c : doc.at("cases")) {
    v.cases.push_back({c.at("name"), c.at("text"), c.at("canonical_text"), from_hex(c.at("hex")), c.at("hex_from"),
                       bottle_of(c.at("value")), c.at("source")});
  }
  for (const json& c : doc.at("malformed_text")) {
    v.malformed_text.push_back({c.at("text"), c.at("column"), c.at("message")});
  }
  for (const json& c : doc.at("malformed_hex")) {
    const auto bytes = from_hex(c.at("hex"));
    v.malformed_binary.push_back({std::string(bytes.begin(), bytes.end()), c.at("offset"), c.at("message")});
  }
  return v;
}

}  // namespace

const BottleVectors& bottle_vectors() {
  static const BottleVectors vectors = load();
  return vectors;
}

std::vector<std::uint8_t> from_hex(const std::string& hex) {
  if (hex.size() % 2 != 0) throw Error("odd-length hex string");
  std::vector<std::uint8_t> out;
  out.reserve(hex.size() / 2);
  for (std::size_t i = 0; i < hex.size(); i += 2) {
    out.push_back(static_cast<std::uint8_t>(std::stoul(hex.substr(i, 2), nullptr, 16)));
  }
  return out;
}

std::string to_hex(const std::vector<std::uint8_t>& bytes) {
  static const char digits[] = "0123456789abcdef";
  std::string out;
  for (const std::uint8_t b : bytes) {
    out += digits[b >> 4];
    out += digits[b & 15];
  }
  return out;
}

}  // namespace robogene::testing
