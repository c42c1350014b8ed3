// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// libFuzzer target: an image message (YARP's ImageOf<PixelRgb> as a grabber publishes it) from
// arbitrary wire bytes. decode_image must accept or explain; an accepted image re-encodes and
// decodes to the same pixels (decode-encode-decode), whatever padding the sender used.
#include <cstddef>
#include <cstdint>
#include <string>

#include "robogene/bottle.hpp"
#include "robogene/dev/image_codec.hpp"
#include "robogene/error.hpp"

using namespace robogene;
using namespace robogene::dev;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  Bottle message;
  try {
    DecodeLimits limits;
    limits.max_bytes = 1u << 22;
    message = Bottle::from_bytes(data, size, limits);
  } catch (const ParseError&) {
    return 0;
  }
  ImageRgb image;
  std::string error;
  if (!decode_image(message, image, error)) {
    if (error.empty()) __builtin_trap();  // a refusal says why
    return 0;
  }
  if (image.pixels.size() != static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.height) * 3u) {
    __builtin_trap();
  }
  ImageRgb again;
  std::string again_error;
  if (!decode_image(Bottle::from_bytes(encode_image(image).to_bytes()), again, again_error)) __builtin_trap();
  if (again.width != image.width || again.height != image.height || again.pixels != image.pixels) __builtin_trap();
  return 0;
}
