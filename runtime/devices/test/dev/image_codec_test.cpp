// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
#include <gtest/gtest.h>

#include "robogene/dev/image_codec.hpp"

using namespace robogene;
using namespace robogene::dev;

// The 60-byte header of a 640x480 RGB image sent by YARP 3 (reference capture sniff_image.txt).
TEST(ImageCodec, HeaderIsYarpsByteForByte) {
  ImageRgb image;
  image.resize(640, 480);
  const auto bytes = encode_image(image).to_bytes();
  const std::vector<std::uint8_t> header = {
      0x00, 0x01, 0x00, 0x00, 0x04, 0x00, 0x00, 0x00, 0x09, 0x00, 0x00, 0x00, 0x6d, 0x61, 0x74, 0x00,
      0x09, 0x00, 0x00, 0x00, 0x72, 0x67, 0x62, 0x00, 0x01, 0x01, 0x00, 0x00, 0x05, 0x00, 0x00, 0x00,
      0x03, 0x00, 0x00, 0x00, 0x00, 0x10, 0x0e, 0x00, 0x08, 0x00, 0x01, 0x00, 0x80, 0x02, 0x00, 0x00,
      0xe0, 0x01, 0x00, 0x00, 0x0c, 0x00, 0x00, 0x00, 0x00, 0x10, 0x0e, 0x00};
  ASSERT_EQ(bytes.size(), 60u + 921600u);
  EXPECT_EQ(std::vector<std::uint8_t>(bytes.begin(), bytes.begin() + 60), header);
}

TEST(ImageCodec, RowsArePaddedAndRoundTrip) {
  ImageRgb image;
  image.resize(5, 3);  // 15 bytes per row, padded to 16
  for (std::size_t i = 0; i < image.pixels.size(); ++i) image.pixels[i] = static_cast<std::uint8_t>(i + 1);
  const Bottle b = encode_image(image);
  EXPECT_EQ(b[2].to_text(), "(3 48 65544 5 3)");
  ASSERT_EQ(b[3].as_blob().size(), 48u);
  EXPECT_EQ(b[3].as_blob()[15], 0);   // padding
  EXPECT_EQ(b[3].as_blob()[16], 16);  // second row starts after it
  ImageRgb back;
  std::string error;
  ASSERT_TRUE(decode_image(Bottle::from_bytes(b.to_bytes()), back, error)) << error;
  EXPECT_EQ(back.width, 5);
  EXPECT_EQ(back.height, 3);
  EXPECT_EQ(back.pixels, image.pixels);
}

TEST(ImageCodec, MalformedImagesAreRefusedWithTheReason) {
  std::string error;
  ImageRgb out;
  EXPECT_FALSE(decode_image(Bottle::from_text("[mat] [mono] (1 4 65544 2 2) {0 0 0 0}"), out, error));
  EXPECT_EQ(error, "pixel code [mono] is not [rgb]");
  EXPECT_FALSE(decode_image(Bottle::from_text("[mat] [rgb] (3 48 65544 5 3) {1 2 3}"), out, error));
  EXPECT_EQ(error, "image of 5x3 with quantum 8 needs 48 pixel bytes, header says 48, blob has 3");
  EXPECT_FALSE(decode_image(Bottle::from_text("[mat] [rgb] (3 0 65544 -1 3) {}"), out, error));
  EXPECT_EQ(error, "image size -1x3 or quantum 8 is out of range");
  EXPECT_FALSE(decode_image(Bottle::from_text("[mat] [rgb] (3 x 65544 1 1) {0 0 0 0 0 0 0 0}"), out, error));
  EXPECT_EQ(error, "image header field 1 is not an integer: x");
  EXPECT_FALSE(decode_image(Bottle::from_text("1 2 3"), out, error));
}

// A zero-width image has rows but no pixels: it decodes as an empty image of that height and encodes back. The
// fuzzer found both copies passing the empty image's null data() to memcpy (undefined behaviour, UBSan); its input
// is the regression seed runtime/fuzz/corpus/image_codec_fuzz/regression-zero-width.
TEST(ImageCodec, AZeroWidthImageDecodesEmptyAndRoundTrips) {
  ImageRgb out;
  std::string error;
  ASSERT_TRUE(decode_image(Bottle::from_text("[mat] [rgb] (3 0 65544 0 4) {}"), out, error)) << error;
  EXPECT_EQ(out.width, 0);
  EXPECT_EQ(out.height, 4);
  EXPECT_TRUE(out.pixels.empty());
  const Bottle again = encode_image(out);
  EXPECT_EQ(again[2].to_text(), "(3 0 65544 0 4)");
  ImageRgb back;
  ASSERT_TRUE(decode_image(Bottle::from_bytes(again.to_bytes()), back, error)) << error;
  EXPECT_EQ(back.height, 4);
}

// Row order, as YARP 3.5 reads it: an image its Python binding made (green = 10 * y, red = x)
// arrives with bit 16 clear and the top row first; ours go with the bit set, bottom row first.
TEST(ImageCodec, RowOrderFollowsBit16AsYarpReadsIt) {
  const std::string yarp_python_image =
      "(3 48 8 4 3) {0 0 7 1 0 7 2 0 7 3 0 7 89 127 0 0 0 10 7 1 10 7 2 10 7 3 10 7 89 127 0 0 "
      "0 20 7 1 20 7 2 20 7 3 20 7 255 127 0 0}";
  ImageRgb in;
  std::string error;
  ASSERT_TRUE(decode_image(Bottle::from_text("[mat] [rgb] " + yarp_python_image), in, error)) << error;
  for (int y = 0; y < 3; ++y) {
    EXPECT_EQ(in.at(2, y)[0], 2) << y;
    EXPECT_EQ(in.at(2, y)[1], 10 * y) << y;
  }
  const Bottle out = encode_image(in);
  EXPECT_EQ(out[2].to_text(), "(3 48 65544 4 3)");
  EXPECT_EQ(out[3].as_blob()[1], 20);       // the first row on the wire is the bottom one
  EXPECT_EQ(out[3].as_blob()[2 * 16 + 1], 0);  // the last is the top one
  ImageRgb back;
  ASSERT_TRUE(decode_image(out, back, error)) << error;
  EXPECT_EQ(back.pixels, in.pixels);
}
