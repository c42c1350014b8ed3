// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// Every vector real YARP 3.5 produced (tests/vectors/yarp3_bottles.json: Bottle::fromString and
// the bytes yarp.Port.write sent; yarp3_typed_values.json: typed add* calls), checked without
// YARP: our text parser gives YARP's bytes, our decoder gives YARP's rendering, and re-encoding
// gives the bytes back. YARP accepts the "malformed_" texts in its own way; we refuse them with
// a column. tests/interop/test_vectors_are_yarps.py keeps the files equal to what YARP makes.
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "robogene/bottle.hpp"
#include "robogene/error.hpp"
#include "robogene/testing/vector_cases.hpp"

namespace robogene::testing {
namespace {

nlohmann::json load(const char* file) {
  const std::string path = std::string(ROBOGENE_SOURCE_DIR) + "/tests/vectors/" + file;
  std::ifstream in(path);
  if (!in) throw Error("cannot open " + path);
  return nlohmann::json::parse(in);
}

bool malformed(const nlohmann::json& c) { return c.at("name").get<std::string>().rfind("malformed_", 0) == 0; }

TEST(YarpVectors, TextParsesToYarpsBytesAndBytesRenderAsYarp) {
  const nlohmann::json cases = load("yarp3_bottles.json");
  std::size_t checked = 0;
  for (const auto& c : cases) {
    if (malformed(c)) continue;
    const std::string name = c.at("name");
    const std::string text = c.at("text");
    SCOPED_TRACE(name + ": " + text);
    const auto bytes = from_hex(c.at("hex"));
    EXPECT_EQ(to_hex(Bottle::from_text(text).to_bytes()), c.at("hex").get<std::string>());
    const Bottle decoded = Bottle::from_bytes(bytes);
    EXPECT_EQ(decoded.to_text(), c.at("canonical_text").get<std::string>());
    EXPECT_EQ(to_hex(decoded.to_bytes()), c.at("hex").get<std::string>());
    ++checked;
  }
  EXPECT_GE(checked, 130u);
}

TEST(YarpVectors, WhatYarpAcceptsAsMalformedWeRefuseWithAColumn) {
  std::size_t checked = 0;
  for (const auto& c : load("yarp3_bottles.json")) {
    if (!malformed(c)) continue;
    SCOPED_TRACE(c.at("name").get<std::string>());
    try {
      (void)Bottle::from_text(c.at("text").get<std::string>());
      ADD_FAILURE() << "parsed without error";
    } catch (const ParseError& e) {
      EXPECT_NE(std::string(e.what()).find("column"), std::string::npos) << e.what();
    }
    ++checked;
  }
  EXPECT_GE(checked, 5u);
}

TEST(YarpVectors, TypedValuesDecodeRenderAndReencode) {
  const nlohmann::json cases = load("yarp3_typed_values.json");
  EXPECT_GE(cases.size(), 20u);
  for (const auto& c : cases) {
    SCOPED_TRACE(c.at("name").get<std::string>());
    const Bottle decoded = Bottle::from_bytes(from_hex(c.at("hex")));
    EXPECT_EQ(decoded.to_text(), c.at("canonical_text").get<std::string>());
    EXPECT_EQ(to_hex(decoded.to_bytes()), c.at("hex").get<std::string>());
  }
}

}  // namespace
}  // namespace robogene::testing
