// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// Text codec beyond the shared vectors: classification details, line continuation, the
// completeness check used by text carriers, rendering of single values, locale independence.
#include <gtest/gtest.h>

#include <clocale>
#include <cmath>
#include <cstdio>
#include <cstdint>
#include <cstdlib>
#include <string>

#include "robogene/bottle.hpp"
#include "robogene/error.hpp"

namespace robogene {
namespace {

ParseError text_error(const std::string& text) {
  try {
    (void)Bottle::from_text(text);
  } catch (const ParseError& e) {
    return e;
  }
  ADD_FAILURE() << "parsed without error: " << text;
  return ParseError(0, "");
}

TEST(TextCodec, EmptyAndBlankTextIsAnEmptyBottle) {
  EXPECT_TRUE(Bottle::from_text("").empty());
  EXPECT_TRUE(Bottle::from_text(" \t\r\n,, ").empty());
  EXPECT_EQ(Bottle().to_text(), "");
}

TEST(TextCodec, IntegerWidthFollowsTheValue) {
  const Bottle b = Bottle::from_text("2147483647 2147483648 -2147483648 -2147483649 0xffffffff");
  EXPECT_EQ(b[0].type(), Type::Int32);
  EXPECT_EQ(b[1].type(), Type::Int64);
  EXPECT_EQ(b[2].type(), Type::Int32);
  EXPECT_EQ(b[3].type(), Type::Int64);
  EXPECT_EQ(b[4], Value::int64(4294967295));
  // Beyond int64 the value saturates, as strtoll does in YARP.
  EXPECT_EQ(Bottle::from_text("99999999999999999999 -99999999999999999999"),
            (Bottle{Value::int64(INT64_MAX), Value::int64(INT64_MIN)}));
}

TEST(TextCodec, SpecialFloats) {
  const Bottle b = Bottle::from_text("inf -inf nan 1e400");
  EXPECT_TRUE(std::isinf(b[0].as_float64()) && b[0].as_float64() > 0);
  EXPECT_TRUE(std::isinf(b[1].as_float64()) && b[1].as_float64() < 0);
  EXPECT_TRUE(std::isnan(b[2].as_float64()));
  EXPECT_TRUE(std::isinf(b[3].as_float64()));
  // Every NaN prints as nan (glibc's "-nan" would read back as a string).
  EXPECT_EQ(Bottle{-std::nan("")}.to_text(), "nan");
  EXPECT_EQ(Bottle{Value::float32(std::nanf(""))}.to_text(), "nan");
}

TEST(TextCodec, EscapesOutsideQuotes) {
  // YARP unescapes bare words too; an escaped separator joins the word.
  EXPECT_EQ(Bottle::from_text("a\\ b"), (Bottle{"a b"}));
  EXPECT_EQ(Bottle::from_text("x\\(1\\)"), (Bottle{"x(1)"}));
  EXPECT_EQ(Bottle::from_text("\"tab\\tq\""), (Bottle{"tabtq"}));  // unknown escape: the character itself
}

TEST(TextCodec, LineContinuationJoinsLines) {
  // `\` at the end of a line continues it with nothing in between (BottleImpl::read).
  EXPECT_EQ(Bottle::from_text("1 2\\\n3"), (Bottle{1, 23}));
  EXPECT_EQ(Bottle::from_text("1 2 \\\r\n3"), (Bottle{1, 2, 3}));
  EXPECT_EQ(Bottle::from_text("\"ab\\\ncd\""), (Bottle{"abcd"}));
  // An escaped backslash before a newline is a backslash, not a continuation.
  EXPECT_EQ(Bottle::from_text("\"a\\\\\nb\""), (Bottle{"a\\\nb"}));
}

TEST(TextCodec, NewlinesInsideQuotesAndListsAreKept) {
  EXPECT_EQ(Bottle::from_text("\"two\nlines\" (1\n2)"), (Bottle{"two\nlines", Bottle{1, 2}}));
}

TEST(TextCodec, ErrorColumnsAfterAContinuationPointIntoTheOriginalText) {
  const ParseError e = text_error("1 \\\n2 )");
  EXPECT_EQ(e.position(), 7u);
  EXPECT_NE(std::string(e.what()).find("line 2 column 3"), std::string::npos) << e.what();
}

TEST(TextCodec, NestingIsBounded) {
  EXPECT_NO_THROW((void)Bottle::from_text(std::string(64, '(') + std::string(64, ')')));
  const ParseError e = text_error(std::string(100000, '('));
  EXPECT_EQ(e.position(), 65u);
  EXPECT_NE(std::string(e.what()).find("nested deeper"), std::string::npos) << e.what();
}

TEST(TextCodec, ErrorMessagesSayWhereAndWhat) {
  EXPECT_STREQ(text_error("1 \"abc").what(), "column 3: string has no closing '\"'");
  EXPECT_STREQ(text_error("{1 300}").what(), "column 4: blob byte 300 is outside 0..255");
  EXPECT_STREQ(text_error("a b )").what(), "column 5: ')' has no matching '('");
}

TEST(TextCodec, CompletenessForMultiLineInput) {
  EXPECT_TRUE(Bottle::text_is_complete(""));
  EXPECT_TRUE(Bottle::text_is_complete("1 2 3"));
  EXPECT_TRUE(Bottle::text_is_complete("(1 (2)) {3} \"x\"\n"));
  EXPECT_FALSE(Bottle::text_is_complete("(1 (2)"));
  EXPECT_FALSE(Bottle::text_is_complete("{1 2"));
  EXPECT_FALSE(Bottle::text_is_complete("\"open ( string"));
  EXPECT_TRUE(Bottle::text_is_complete("\"closed ( string\""));
  EXPECT_FALSE(Bottle::text_is_complete("1 2 \\"));
  EXPECT_FALSE(Bottle::text_is_complete("1 2 \\\n"));
  EXPECT_TRUE(Bottle::text_is_complete("\"a\\\\\""));  // escaped backslash, then the closing quote
  EXPECT_FALSE(Bottle::text_is_complete("\"a\\\""));   // escaped quote: still open
  EXPECT_TRUE(Bottle::text_is_complete("1)"));          // more lines cannot repair it; from_text reports it
}

TEST(TextCodec, SingleValueRendering) {
  EXPECT_EQ(Value().to_text(), "null");
  EXPECT_EQ(Value::float32(0.1f).to_text(), "0.100000001490116119385");
  EXPECT_EQ(Value::vocab(0).to_text(), "false");
  EXPECT_EQ(Value::vocab("1").to_text(), "true");
  EXPECT_EQ(Value::blob({}).to_text(), "{}");
  EXPECT_EQ(Value(Bottle{}).to_text(), "()");
  EXPECT_EQ(Value("null").to_text(), "\"null\"");  // would read back as a vocab if bare
  EXPECT_EQ(Value(std::string("\0", 1)).to_text(), "\"\\0\"");
}

// A locale with a decimal comma: an installed one, or de_DE compiled from the `locales` sources.
const char* decimal_comma_locale() {
  for (const char* name : {"de_DE.UTF-8", "de_DE.utf8", "fr_FR.UTF-8", "it_IT.UTF-8"}) {
    if (std::setlocale(LC_ALL, name) != nullptr) return name;
  }
  const std::string dir = std::string(ROBOGENE_BINARY_DIR) + "/test-locales";
  const std::string cmd = "mkdir -p '" + dir + "' && localedef -i de_DE -f UTF-8 '" + dir + "/de_DE.UTF-8' >/dev/null 2>&1";
  (void)std::system(cmd.c_str());  // localedef may warn (exit 1) and still write the locale
  setenv("LOCPATH", dir.c_str(), 1);
  if (std::setlocale(LC_ALL, "de_DE.UTF-8") != nullptr) return "de_DE.UTF-8 (compiled)";
  return nullptr;
}

TEST(TextCodec, IndependentOfTheCLocale) {
  const char* chosen = decimal_comma_locale();
  if (chosen == nullptr) GTEST_SKIP() << "no decimal-comma locale (needs the Debian package locales)";
  char printed[16];
  std::snprintf(printed, sizeof printed, "%.1f", 2.5);
  const Bottle b = Bottle::from_text("2.5 0.1 (1.5)");
  const std::string text = b.to_text();
  std::setlocale(LC_ALL, "C");
  EXPECT_STREQ(printed, "2,5") << "the locale " << chosen << " should really use a decimal comma";
  EXPECT_EQ(b, (Bottle{2.5, 0.1, Bottle{1.5}})) << chosen;
  EXPECT_EQ(text, "2.5 0.100000000000000005551 (1.5)") << chosen;
}

// A vocab is four bytes from the network: one with a NUL before its last character, or with a
// separator, ']' or '\' in it, used to come back from text as another code ("[ab]" for
// 'a' NUL 'b'). Such bytes are now escaped; ordinary vocabs are written as YARP writes them.
TEST(TextCodec, EveryVocabCodeRoundTripsThroughText) {
  const auto code = [](std::uint32_t v) { return static_cast<vocab_t>(v); };
  EXPECT_EQ(Value::vocab(code(0x00620061)).to_text(), "[a\\0b]");
  EXPECT_EQ(Value::vocab(code(0x61000000)).to_text(), "[\\0\\0\\0a]");
  EXPECT_EQ(Value::vocab(code(0x005d2061)).to_text(), "[a\\ \\]]");
  EXPECT_EQ(Value::vocab("set").to_text(), "[set]");
  EXPECT_EQ(Value::vocab("a\\b").to_text(), "[a\\\\b]");
  EXPECT_EQ(Value::vocab(code(0x7b282261)).to_text(), "[a\\\"\\(\\{]");
  for (std::uint32_t v : {0x7b282261u, 0x00620061u, 0x61000000u, 0x005d2061u, 0x0a0d092cu, 0x5c5c5c5cu, 0xff00ff00u, 0x00000031u,
                          0x00003100u, 0x6c6c756eu, 0x0000005du}) {
    const Bottle b(Bottle{Value::vocab(code(v))});
    const Bottle back = Bottle::from_text(b.to_text());
    ASSERT_EQ(back.size(), 1u) << b.to_text();
    EXPECT_TRUE(back[0].is_vocab()) << b.to_text();
    EXPECT_EQ(static_cast<std::uint32_t>(back[0].as_vocab()), v) << b.to_text();
  }
  // Pseudo-random codes: every one comes back.
  std::uint32_t x = 12345;
  for (int i = 0; i < 20000; ++i) {
    x = x * 1664525u + 1013904223u;
    if (x == 0 || x == static_cast<std::uint32_t>(vocab("1"))) continue;  // false / true: their own words
    const Bottle original{Value::vocab(code(x))};
    const Bottle back = Bottle::from_text(original.to_text());
    ASSERT_EQ(static_cast<std::uint32_t>(back[0].as_vocab()), x) << original.to_text();
    // A text carrier would otherwise wait for the rest of a "multi-line" bottle.
    ASSERT_TRUE(Bottle::text_is_complete(original.to_text())) << original.to_text();
  }
}

}  // namespace
}  // namespace robogene
