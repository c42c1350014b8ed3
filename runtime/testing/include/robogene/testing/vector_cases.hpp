// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// Loader for tests/vectors/bottles.json, the Bottle vectors shared with the Python tests.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "robogene/bottle.hpp"

namespace robogene::testing {

struct BottleCase {
  std::string name;
  std::string text;
  std::string canonical_text;
  std::vector<std::uint8_t> bytes;
  std::string bytes_from;  // "capture" or "rules"
  Bottle value;
  std::string source;
};

struct MalformedCase {
  std::string input;  // text, or the raw bytes for binary cases
  std::size_t position;
  std::string message;
};

struct BottleVectors {
  std::vector<BottleCase> cases;
  std::vector<MalformedCase> malformed_text;
  std::vector<MalformedCase> malformed_binary;
};

// Loaded once; throws robogene::Error with the file name when it is missing or malformed.
const BottleVectors& bottle_vectors();

std::vector<std::uint8_t> from_hex(const std::string& hex);
std::string to_hex(const std::vector<std::uint8_t>& bytes);

}  // namespace robogene::testing
