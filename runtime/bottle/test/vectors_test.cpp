// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// Every shared vector through every path: text -> bottle -> bytes -> bottle -> text, against
// YARP 3's bytes and rendering; malformed inputs fail at the stated position with the stated words.
#include <gtest/gtest.h>

#include "robogene/bottle.hpp"
#include "robogene/error.hpp"
#include "robogene/testing/vector_cases.hpp"

namespace robogene::testing {
namespace {

TEST(BottleVectors, FileHoldsTheCapturedAndPaperCases) {
  const BottleVectors& v = bottle_vectors();
  EXPECT_GE(v.cases.size(), 50u);
  std::size_t captured = 0;
  bool paper = false;
  for (const auto& c : v.cases) {
    captured += c.bytes_from == "capture" ? 1 : 0;
    paper = paper || c.text == "action \"go left\" (10 20 30)";
  }
  EXPECT_GE(captured, 25u);
  EXPECT_TRUE(paper);
  EXPECT_GE(v.malformed_text.size(), 10u);
  EXPECT_GE(v.malformed_binary.size(), 10u);
}

class BottleCaseTest : public ::testing::TestWithParam<std::size_t> {
 protected:
  const BottleCase& c() const { return bottle_vectors().cases.at(GetParam()); }
};

TEST_P(BottleCaseTest, TextParsesToTheExpectedTree) {
  EXPECT_EQ(Bottle::from_text(c().text), c().value) << c().text;
}

TEST_P(BottleCaseTest, RendersAsYarp) { EXPECT_EQ(c().value.to_text(), c().canonical_text); }

TEST_P(BottleCaseTest, EncodesToTheExactBytes) {
  EXPECT_EQ(to_hex(c().value.to_bytes()), to_hex(c().bytes)) << c().source;
  EXPECT_EQ(c().value.encoded_size(), c().bytes.size());
}

TEST_P(BottleCaseTest, DecodesTheBytes) { EXPECT_EQ(Bottle::from_bytes(c().bytes), c().value); }

TEST_P(BottleCaseTest, FullRoundTrip) {
  const Bottle parsed = Bottle::from_text(c().text);
  const Bottle decoded = Bottle::from_bytes(parsed.to_bytes());
  EXPECT_EQ(decoded.to_text(), c().canonical_text);
  EXPECT_EQ(Bottle::from_text(decoded.to_text()), c().value);  // the canonical text reads back losslessly
  EXPECT_TRUE(Bottle::text_is_complete(c().text));
}

std::vector<std::size_t> case_indices() {
  std::vector<std::size_t> out;
  try {
    for (std::size_t i = 0; i < bottle_vectors().cases.size(); ++i) out.push_back(i);
  } catch (const std::exception&) {
    // Reported by FileHoldsTheCapturedAndPaperCases instead of aborting test discovery.
  }
  return out;
}

INSTANTIATE_TEST_SUITE_P(Vectors, BottleCaseTest, ::testing::ValuesIn(case_indices()),
                         [](const ::testing::TestParamInfo<std::size_t>& info) {
                           return bottle_vectors().cases.at(info.param).name;
                         });
GTEST_ALLOW_UNINSTANTIATED_PARAMETERIZED_TEST(BottleCaseTest);

TEST(BottleVectors, MalformedTextFailsAtTheColumn) {
  for (const auto& m : bottle_vectors().malformed_text) {
    SCOPED_TRACE(m.input);
    try {
      (void)Bottle::from_text(m.input);
      ADD_FAILURE() << "parsed without error";
    } catch (const ParseError& e) {
      EXPECT_EQ(e.position(), m.position) << e.what();
      EXPECT_NE(std::string(e.what()).find(m.message), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find("column"), std::string::npos) << e.what();
    }
  }
}

TEST(BottleVectors, MalformedBinaryFailsAtTheOffset) {
  for (const auto& m : bottle_vectors().malformed_binary) {
    SCOPED_TRACE(to_hex(std::vector<std::uint8_t>(m.input.begin(), m.input.end())));
    try {
      (void)Bottle::from_bytes(reinterpret_cast<const std::uint8_t*>(m.input.data()), m.input.size());
      ADD_FAILURE() << "decoded without error";
    } catch (const ParseError& e) {
      EXPECT_EQ(e.position(), m.position) << e.what();
      EXPECT_NE(std::string(e.what()).find(m.message), std::string::npos) << e.what();
      EXPECT_EQ(std::string(e.what()).rfind("byte " + std::to_string(m.position) + ": ", 0), 0u) << e.what();
    }
  }
}

}  // namespace
}  // namespace robogene::testing
