// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// ImageRgb: packed 8-bit RGB pixels, rows top to bottom without padding. It is what a frame
// grabber returns; YARP 3's image header (reference section 6) is added only when it travels.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace robogene::dev {

struct ImageRgb {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> pixels;  // width * height * 3 bytes

  void resize(int w, int h) {
    width = w;
    height = h;
    pixels.assign(static_cast<std::size_t>(w) * static_cast<std::size_t>(h) * 3u, 0);
  }
  const std::uint8_t* at(int x, int y) const {
    return pixels.data() + (static_cast<std::size_t>(y) * static_cast<std::size_t>(width) +
                            static_cast<std::size_t>(x)) * 3u;
  }
  std::uint8_t* at(int x, int y) {
    return pixels.data() + (static_cast<std::size_t>(y) * static_cast<std::size_t>(width) +
                            static_cast<std::size_t>(x)) * 3u;
  }
};

}  // namespace robogene::dev
