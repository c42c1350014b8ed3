// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// Binary codec beyond the shared vectors: scatter-gather output of a real image bottle, the
// narrow types, dict decoding, NUL handling, limits, and a decoder that never crashes on damage.
#include <gtest/gtest.h>

#include <cstring>
#include <random>

#include "robogene/bottle.hpp"
#include "robogene/error.hpp"
#include "robogene/testing/vector_cases.hpp"

namespace robogene {
namespace {

using testing::from_hex;
using testing::to_hex;

// Records how the encoder hands over its bytes.
class RecordingSink final : public ByteSink {
 public:
  struct Piece {
    bool referenced;
    const void* data;
    std::vector<std::uint8_t> bytes;
  };
  void append(const void* data, std::size_t size) override { record(false, data, size); }
  void reference(const void* data, std::size_t size) override { record(true, data, size); }
  std::vector<Piece> pieces;
  std::size_t appends = 0;

 private:
  void record(bool referenced, const void* data, std::size_t size) {
    const auto* p = static_cast<const std::uint8_t*>(data);
    pieces.push_back({referenced, data, std::vector<std::uint8_t>(p, p + size)});
    appends += referenced ? 0 : 1;
  }
};

ParseError parse_error_of(const std::vector<std::uint8_t>& bytes, const DecodeLimits& limits = {}) {
  try {
    (void)Bottle::from_bytes(bytes, limits);
  } catch (const ParseError& e) {
    return e;
  }
  ADD_FAILURE() << "decoded without error: " << to_hex(bytes);
  return ParseError(0, "");
}

// The 640x480 RGB image of sniff_image.txt: header block of 60 bytes, then the pixels.
Bottle image_bottle() {
  Bottle b{Value::vocab("mat"), Value::vocab("rgb"), Bottle{3, 921600, 65544, 640, 480}};
  b.add(Value::blob(std::vector<std::uint8_t>(921600, 0)));
  return b;
}
const char* const kImageHeaderHex =
    "0001000004000000090000006d617400090000007267620001010000050000000300000000100e00"
    "08000100800200" "00e00100000c00000000100e00";

TEST(BinaryCodec, ImageBlobIsReferencedNotCopied) {
  const Bottle img = image_bottle();
  RecordingSink sink;
  img.encode_to(sink);
  // YARP's writer sends this bottle as blocks [60, 921600]; ours hands over the same split.
  ASSERT_EQ(sink.pieces.size(), 2u);
  EXPECT_FALSE(sink.pieces[0].referenced);
  EXPECT_EQ(to_hex(sink.pieces[0].bytes), kImageHeaderHex);
  EXPECT_TRUE(sink.pieces[1].referenced);
  EXPECT_EQ(sink.pieces[1].data, img[3].as_blob().data());
  EXPECT_EQ(sink.pieces[1].bytes.size(), 921600u);
  EXPECT_EQ(img.encoded_size(), 60u + 921600u);
}

TEST(BinaryCodec, ImageDecodesWithItsBlob) {
  std::vector<std::uint8_t> wire = from_hex(kImageHeaderHex);
  wire.resize(wire.size() + 921600, 0x5a);
  const Bottle b = Bottle::from_bytes(wire);
  ASSERT_EQ(b.size(), 4u);
  EXPECT_EQ(b[2], Value(Bottle{3, 921600, 65544, 640, 480}));
  ASSERT_EQ(b[3].as_blob().size(), 921600u);
  EXPECT_EQ(b[3].as_blob().front(), 0x5a);
  EXPECT_EQ(b[3].as_blob().back(), 0x5a);
}

TEST(BinaryCodec, SmallFieldsAreBatched) {
  Bottle b;
  for (int i = 0; i < 1000; ++i) b.add(i % 2 == 0 ? Value(i) : Value("s"));
  RecordingSink sink;
  b.encode_to(sink);
  std::vector<std::uint8_t> joined;
  for (const auto& p : sink.pieces) joined.insert(joined.end(), p.bytes.begin(), p.bytes.end());
  EXPECT_EQ(joined, b.to_bytes());
  EXPECT_LT(sink.appends, joined.size() / 256);  // chunks, not a call per field
}

TEST(BinaryCodec, NarrowTypesUseTheirTags) {
  const Bottle b{Value::int8(-2), Value::int16(-3), Value::float32(1.5f), Value::int64(-1)};
  EXPECT_EQ(to_hex(b.to_bytes()),
            "00010000" "04000000" "20000000fe" "40000000fdff" "800000000000c03f" "11000000ffffffffffffffff");
  EXPECT_EQ(Bottle::from_bytes(b.to_bytes()), b);
  EXPECT_EQ(b.to_text(), "-2 -3 1.5 -1");
}

TEST(BinaryCodec, HomogeneousNarrowLists) {
  const Bottle b{Value::int8(1), Value::int8(2)};
  EXPECT_EQ(to_hex(b.to_bytes()), "20010000" "02000000" "0102");
  const Bottle f{Value::float32(1.0f), Value::float32(-2.0f)};
  EXPECT_EQ(to_hex(f.to_bytes()), "80010000" "02000000" "0000803f" "000000c0");
  EXPECT_EQ(Bottle::from_bytes(f.to_bytes()), f);
  // A nested homogeneous int16 list carries 0x140 and no item tags.
  const Bottle n{Value(Bottle{Value::int16(5), Value::int16(6)}), 1};
  EXPECT_EQ(to_hex(n.to_bytes()), "00010000" "02000000" "40010000" "02000000" "05000600" "01000000" "01000000");
  EXPECT_EQ(Bottle::from_bytes(n.to_bytes()), n);
}

TEST(BinaryCodec, ReadsTaggedItemsInsideASpecialisedList) {
  // A writer that never specialises (YARP accepts both) must read the same.
  const auto tagged = from_hex("00010000" "02000000" "01000000" "05000000" "01000000" "06000000");
  EXPECT_EQ(Bottle::from_bytes(tagged), (Bottle{5, 6}));
  EXPECT_EQ(to_hex(Bottle::from_bytes(tagged).to_bytes()), "01010000" "02000000" "05000000" "06000000");
}

TEST(BinaryCodec, DictDecodesToKeyValueLists) {
  // item tag 768 followed by a whole bottle of (key value) pairs (Property::write).
  const auto wire = from_hex(
      "00010000" "01000000" "00030000"
      "00010000" "01000000" "00010000" "02000000" "04000000" "01000000" "61" "01000000" "07000000");
  const Bottle b = Bottle::from_bytes(wire);
  EXPECT_EQ(b.to_text(), "((a 7))");
  EXPECT_EQ(b[0].as_list().find("a").as_int32(), 7);
}

TEST(BinaryCodec, StringNulHandling) {
  // Pre-2015 peers counted a NUL terminator; exactly one trailing NUL is dropped on read.
  const auto old_style = from_hex("00010000" "01000000" "04000000" "03000000" "686900");
  EXPECT_EQ(Bottle::from_bytes(old_style)[0].as_string(), "hi");
  const auto two_nuls = from_hex("04010000" "01000000" "04000000" "68690000");
  EXPECT_EQ(Bottle::from_bytes(two_nuls)[0].as_string(), std::string("hi\0", 3));
  // Written without a terminator; an inner NUL survives.
  const Bottle inner{std::string("a\0b", 3)};
  EXPECT_EQ(to_hex(inner.to_bytes()), "04010000" "01000000" "03000000" "610062");
  EXPECT_EQ(Bottle::from_bytes(inner.to_bytes()), inner);
  // Blobs are never trimmed.
  const Bottle blob{Value::blob({1, 0})};
  EXPECT_EQ(Bottle::from_bytes(blob.to_bytes()), blob);
}

TEST(BinaryCodec, NullCannotBeEncoded) {
  Bottle b{1};
  b.add(Value());
  EXPECT_THROW((void)b.to_bytes(), Error);
  EXPECT_THROW((void)b.encoded_size(), Error);
}

TEST(BinaryCodec, AppendBytesKeepsWhatIsThere) {
  std::vector<std::uint8_t> out{0xaa};
  Bottle{Value::vocab("ok")}.append_bytes(out);
  EXPECT_EQ(to_hex(out), "aa" "09010000" "01000000" "6f6b0000");
}

TEST(BinaryCodec, PrefixDecodeReportsWhatItUsed) {
  std::vector<std::uint8_t> two = Bottle{1}.to_bytes();
  const auto second = Bottle{"x"}.to_bytes();
  two.insert(two.end(), second.begin(), second.end());
  std::size_t used = 0;
  EXPECT_EQ(Bottle::from_bytes_prefix(two.data(), two.size(), &used), (Bottle{1}));
  EXPECT_EQ(used, 12u);
  EXPECT_EQ(Bottle::from_bytes_prefix(two.data() + used, two.size() - used, &used), (Bottle{"x"}));
  EXPECT_EQ(used, 13u);
  EXPECT_EQ(parse_error_of(two).position(), 12u);
}

// `depth` lists each holding the next, the innermost holding int32 1; built as bytes because a
// Bottle that deep would be too deep to build and free recursively.
std::vector<std::uint8_t> nested(std::size_t depth) {
  if (depth == 0) return from_hex("01010000" "01000000" "01000000");
  std::string hex = "00010000" "01000000";                             // top level: one item
  for (std::size_t i = 1; i < depth; ++i) hex += "00010000" "01000000";  // a list holding a list
  hex += "01010000" "01000000" "01000000";                             // an int32 list holding 1
  return from_hex(hex);
}

TEST(BinaryCodec, NestingDepthIsLimited) {
  EXPECT_NO_THROW((void)Bottle::from_bytes(nested(64)));
  const ParseError e = parse_error_of(nested(65));
  EXPECT_NE(std::string(e.what()).find("nested deeper than the limit of 64"), std::string::npos) << e.what();
  EXPECT_EQ(e.position(), 8u + 64u * 8u);  // the tag of the 65th nested list
  DecodeLimits shallow;
  shallow.max_depth = 2;
  EXPECT_NO_THROW((void)Bottle::from_bytes(nested(2), shallow));
  EXPECT_THROW((void)Bottle::from_bytes(nested(3), shallow), ParseError);
  // Far deeper than the stack could take recursively: rejected at the limit, no crash.
  EXPECT_THROW((void)Bottle::from_bytes(nested(100000)), ParseError);
}

TEST(BinaryCodec, SizeLimitIsEnforced) {
  const auto wire = Bottle{Value::blob(std::vector<std::uint8_t>(1000, 1))}.to_bytes();
  DecodeLimits small;
  small.max_bytes = 100;
  const ParseError whole = parse_error_of(wire, small);
  EXPECT_NE(std::string(whole.what()).find("exceeds the decode limit of 100 bytes"), std::string::npos) << whole.what();
  std::size_t used = 0;
  try {
    (void)Bottle::from_bytes_prefix(wire.data(), wire.size(), &used, small);
    ADD_FAILURE() << "no error";
  } catch (const ParseError& e) {
    EXPECT_EQ(e.position(), 8u);  // the blob length (a one-blob list is specialised: no item tag)
    EXPECT_NE(std::string(e.what()).find("decode limit of 100 bytes"), std::string::npos) << e.what();
  }
}

TEST(BinaryCodec, HugeCountsFailBeforeAllocating) {
  // 2^31-1 items of 8 bytes claimed by a 12-byte message: refused from the arithmetic alone.
  const auto wire = from_hex("0a010000" "ffffff7f" "00000000");
  const ParseError e = parse_error_of(wire);
  EXPECT_EQ(std::string(e.what()), "byte 4: list count 2147483647 needs at least 17179869176 bytes, only 4 remain");
}

TEST(BinaryCodec, DamagedInputNeverCrashes) {
  // Every truncation and thousands of random corruptions of every vector: a Bottle or a
  // ParseError, nothing else.
  std::mt19937 rng(20260522);
  std::size_t decoded = 0;
  std::size_t rejected = 0;
  for (const auto& c : testing::bottle_vectors().cases) {
    for (std::size_t n = 0; n < c.bytes.size(); ++n) {
      EXPECT_THROW((void)Bottle::from_bytes(c.bytes.data(), n), ParseError) << c.name << " cut at " << n;
    }
    for (int round = 0; round < 200 && !c.bytes.empty(); ++round) {
      std::vector<std::uint8_t> damaged = c.bytes;
      const int flips = 1 + static_cast<int>(rng() % 4);
      for (int f = 0; f < flips; ++f) damaged[rng() % damaged.size()] = static_cast<std::uint8_t>(rng());
      try {
        const Bottle b = Bottle::from_bytes(damaged);
        (void)b.to_text();
        ++decoded;
      } catch (const ParseError&) {
        ++rejected;
      }
    }
  }
  EXPECT_GT(decoded, 0u);
  EXPECT_GT(rejected, 0u);
}

}  // namespace
}  // namespace robogene
