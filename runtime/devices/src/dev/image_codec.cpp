// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "robogene/dev/image_codec.hpp"

#include <cstring>
#include <limits>

namespace robogene::dev {
namespace {

// Bit 16 of the quantum field: set, the blob holds the rows bottom row first. YARP 3.5 reads it
// so (checked: an image a YARP Python program makes has the bit clear and its top row first; an
// image sent with the bit set and its top row first shows upside down in YARP). YARP's C++
// cameras (fakeFrameGrabber, sniff_image.txt) set it; we do too, so our bytes are theirs.
constexpr std::int32_t kRowsBottomUp = 1 << 16;
constexpr std::int64_t kMaxSide = 1 << 16;

std::size_t row_bytes(std::int64_t width, std::int64_t quantum) {
  const std::int64_t raw = width * 3;
  return static_cast<std::size_t>((raw + quantum - 1) / quantum * quantum);
}

}  // namespace

Bottle encode_image(const ImageRgb& image, int quantum) {
  if (quantum < 1) quantum = 1;
  const std::size_t row = row_bytes(image.width, quantum);
  const std::size_t packed = static_cast<std::size_t>(image.width) * 3u;
  std::vector<std::uint8_t> pixels(row * static_cast<std::size_t>(image.height), 0);
  for (int y = 0; packed != 0 && y < image.height; ++y) {  // an empty image's data() may be null: no memcpy
    const std::size_t wire_row = static_cast<std::size_t>(image.height - 1 - y);
    std::memcpy(pixels.data() + row * wire_row, image.pixels.data() + packed * static_cast<std::size_t>(y), packed);
  }
  Bottle b;
  b.add(Value::vocab(vocab("mat")));
  b.add(Value::vocab(vocab("rgb")));
  Bottle& header = b.add_list();
  header.add(Value::int32(3));
  header.add(Value::int32(static_cast<std::int32_t>(pixels.size())));
  header.add(Value::int32(quantum | kRowsBottomUp));
  header.add(Value::int32(image.width));
  header.add(Value::int32(image.height));
  b.add(Value::blob(std::move(pixels)));
  return b;
}

bool decode_image(const Bottle& m, ImageRgb& out, std::string& error) {
  if (m.size() != 4 || !m[0].is_vocab() || m[0].as_vocab() != vocab("mat")) {
    error = "not an image: expected [mat] <pixel code> (header) {pixels}, got " +
            std::to_string(m.size()) + " items";
    return false;
  }
  if (!m[1].is_vocab() || m[1].as_vocab() != vocab("rgb")) {
    error = "pixel code " + m[1].to_text() + " is not [rgb]";
    return false;
  }
  if (!m[2].is_list() || m[2].as_list().size() != 5) {
    error = "image header is not a list of 5 integers: " + m[2].to_text();
    return false;
  }
  std::int64_t f[5];
  for (std::size_t i = 0; i < 5; ++i) {
    const Value& v = m[2].as_list()[i];
    if (!v.is_int()) {
      error = "image header field " + std::to_string(i) + " is not an integer: " + v.to_text();
      return false;
    }
    f[i] = v.as_int64();
  }
  const std::int64_t quantum = f[2] & 0xffff, width = f[3], height = f[4];
  if (f[0] != 3) {
    error = "image depth " + std::to_string(f[0]) + " is not 3 (RGB)";
    return false;
  }
  if (width < 0 || height < 0 || width > kMaxSide || height > kMaxSide || quantum < 1) {
    error = "image size " + std::to_string(width) + "x" + std::to_string(height) + " or quantum " +
            std::to_string(quantum) + " is out of range";
    return false;
  }
  const std::size_t row = row_bytes(width, quantum);
  const std::size_t expected = row * static_cast<std::size_t>(height);
  if (!m[3].is_blob() || m[3].as_blob().size() != expected ||
      static_cast<std::uint64_t>(f[1]) != expected) {
    error = "image of " + std::to_string(width) + "x" + std::to_string(height) + " with quantum " +
            std::to_string(quantum) + " needs " + std::to_string(expected) + " pixel bytes, header says " +
            std::to_string(f[1]) + ", blob has " +
            (m[3].is_blob() ? std::to_string(m[3].as_blob().size()) : std::string("none"));
    return false;
  }
  const bool bottom_up = (f[2] & kRowsBottomUp) != 0;
  out.resize(static_cast<int>(width), static_cast<int>(height));
  const std::size_t packed = static_cast<std::size_t>(width) * 3u;
  if (packed == 0) return true;  // an empty image (0 x h): no pixels, and memcpy may not take its null data()
  for (std::int64_t y = 0; y < height; ++y) {
    const std::int64_t src_row = bottom_up ? height - 1 - y : y;
    std::memcpy(out.pixels.data() + packed * static_cast<std::size_t>(y),
                m[3].as_blob().data() + row * static_cast<std::size_t>(src_row), packed);
  }
  return true;
}

}  // namespace robogene::dev
