// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// Value: types, conversions between accessors, type-mismatch errors, deep bitwise equality.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <functional>
#include <limits>

#include "robogene/bottle.hpp"
#include "robogene/error.hpp"

namespace robogene {
namespace {

std::string error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const Error& e) {
    return e.what();
  }
  return "<no error>";
}

TEST(Value, DefaultIsNull) {
  Value v;
  EXPECT_TRUE(v.is_null());
  EXPECT_EQ(v.type(), Type::Null);
  EXPECT_STREQ(type_name(v.type()), "null");
}

TEST(Value, ImplicitConstructorsPickTheTextTypes) {
  EXPECT_EQ(Value(7).type(), Type::Int32);
  EXPECT_EQ(Value(std::int64_t{7}).type(), Type::Int64);
  EXPECT_EQ(Value(2.5).type(), Type::Float64);
  EXPECT_EQ(Value("hi").type(), Type::String);
  EXPECT_EQ(Value(std::string("hi")).type(), Type::String);
  EXPECT_EQ(Value(std::string_view("hi")).type(), Type::String);
  EXPECT_EQ(Value(Bottle{1, 2}).type(), Type::List);
}

TEST(Value, FactoriesKeepTheirWidth) {
  EXPECT_EQ(Value::int8(-3).type(), Type::Int8);
  EXPECT_EQ(Value::int8(-3).as_int32(), -3);
  EXPECT_EQ(Value::int16(-300).as_int64(), -300);
  EXPECT_EQ(Value::float32(1.5f).type(), Type::Float32);
  EXPECT_EQ(Value::float32(1.5f).as_float64(), 1.5);
  EXPECT_EQ(Value::vocab("set").as_vocab(), vocab("set"));
  EXPECT_EQ(Value::vocab("toolong").as_vocab(), vocab("tool"));
  EXPECT_EQ(Value::blob({1, 2, 255}).as_blob(), (std::vector<std::uint8_t>{1, 2, 255}));
  const char raw[] = {'a', '\0', 'b'};
  EXPECT_EQ(Value::blob(raw, 3).as_blob().size(), 3u);
}

TEST(Value, NumericAccessorsConvert) {
  EXPECT_EQ(Value(7).as_float64(), 7.0);
  EXPECT_EQ(Value(2.9).as_int32(), 2);    // truncation toward zero, as YARP
  EXPECT_EQ(Value(-2.9).as_int64(), -2);
  EXPECT_EQ(Value(std::int64_t{5}).as_int32(), 5);
  EXPECT_EQ(Value::vocab("ok").as_int32(), vocab("ok"));  // a vocab is its integer code
  EXPECT_EQ(Value(3).as_vocab(), 3);
}

TEST(Value, AsVocabAcceptsAStringAsYarpDoes) {
  EXPECT_EQ(Value("axes").as_vocab(), vocab("axes"));
}

TEST(Value, ConversionsThatWouldLoseTheValueThrow) {
  EXPECT_EQ(error_of([] { (void)Value(std::int64_t{3000000000}).as_int32(); }),
            "int64 3000000000 does not fit in int32");
  EXPECT_NE(error_of([] { (void)Value(std::nan("")).as_int32(); }).find("does not fit in int32"), std::string::npos);
  EXPECT_NE(error_of([] { (void)Value(1e300).as_int64(); }).find("does not fit in int64"), std::string::npos);
  EXPECT_NE(error_of([] { (void)Value(2147483648.0).as_int32(); }).find("float64"), std::string::npos);
  EXPECT_EQ(Value(-2147483648.0).as_int32(), std::numeric_limits<std::int32_t>::min());
}

TEST(Value, TypeMismatchNamesBothTypes) {
  EXPECT_EQ(error_of([] { (void)Value("hi").as_int32(); }), "expected int32, got string");
  EXPECT_EQ(error_of([] { (void)Value(1).as_string(); }), "expected string, got int32");
  EXPECT_EQ(error_of([] { (void)Value(1.5).as_list(); }), "expected list, got float64");
  EXPECT_EQ(error_of([] { (void)Value::vocab("x").as_blob(); }), "expected blob, got vocab");
  EXPECT_EQ(error_of([] { (void)Value().as_float64(); }), "expected float64, got null");
  EXPECT_EQ(error_of([] { (void)Value::blob({}).as_vocab(); }), "expected vocab, got blob");
  EXPECT_EQ(error_of([] { (void)Value::vocab("x").as_float64(); }), "expected float64, got vocab");
}

TEST(Value, EqualityIsTypeSensitive) {
  EXPECT_NE(Value(1), Value(std::int64_t{1}));
  EXPECT_NE(Value(1), Value(1.0));
  EXPECT_NE(Value::int8(1), Value::int16(1));
  EXPECT_NE(Value("set"), Value::vocab("set"));
  EXPECT_EQ(Value(Bottle{1, "a", Bottle{2.5}}), Value(Bottle{1, "a", Bottle{2.5}}));
  EXPECT_NE(Value(Bottle{1, "a", Bottle{2.5}}), Value(Bottle{1, "a", Bottle{2.25}}));
  EXPECT_EQ(Value::blob({1, 2}), Value::blob({1, 2}));
  EXPECT_NE(Value::blob({1, 2}), Value::blob({1, 3}));
}

TEST(Value, FloatsCompareByBitPattern) {
  EXPECT_EQ(Value(std::nan("")), Value(std::nan("")));
  EXPECT_NE(Value(0.0), Value(-0.0));
  EXPECT_EQ(Value::float32(std::nanf("")), Value::float32(std::nanf("")));
  std::uint32_t bits = 0x7fa00001;  // a signalling NaN with a payload must survive storage
  float f;
  std::memcpy(&f, &bits, 4);
  const float back = Value::float32(f).as_float32();
  std::uint32_t back_bits;
  std::memcpy(&back_bits, &back, 4);
  EXPECT_EQ(back_bits, bits);
}

TEST(Value, CopyAndMoveOwnTheirHeapParts) {
  Value a(Bottle{"x", Value::blob({9}), Bottle{1}});
  Value b = a;
  b.as_list()[0] = "y";
  EXPECT_EQ(a.as_list()[0].as_string(), "x");
  Value c = std::move(b);
  EXPECT_TRUE(b.is_null());  // NOLINT: moved-from state is documented as null
  EXPECT_EQ(c.as_list()[0].as_string(), "y");
  // Assigning a value from inside itself must not read freed memory.
  Value nested(Bottle{Bottle{1, 2}});
  nested = nested.as_list()[0];
  EXPECT_EQ(nested, Value(Bottle{1, 2}));
  Value moved(Bottle{Bottle{3}});
  moved = std::move(moved.as_list()[0]);
  EXPECT_EQ(moved, Value(Bottle{3}));
  Value self("s");
  self = self;
  EXPECT_EQ(self.as_string(), "s");
}

TEST(Value, BlobIsMutableInPlace) {
  Value v = Value::blob({1});
  v.as_blob().push_back(2);
  EXPECT_EQ(v.as_blob().size(), 2u);
}

TEST(Vocab, PacksLittleEndianAndDecodesWithoutZeros) {
  EXPECT_EQ(vocab("set"), 0x00746573);
  EXPECT_EQ(vocab("tsta"), 0x61747374);
  EXPECT_EQ(vocab_to_string(vocab("set")), "set");
  EXPECT_EQ(vocab_to_string(0), "");
  EXPECT_EQ(vocab_to_string(0x00310000), "1");
}

}  // namespace
}  // namespace robogene
