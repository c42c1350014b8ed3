// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// Images on the wire as YARP 3 sends them (reference section 6): a bottle
// [mat] [rgb] (depth size quantum|bottomUp<<16 width height) {pixels}, whose first 60 bytes are
// YARP's ImageNetworkHeader. Rows in the blob are padded to `quantum` bytes, bottom row first when
// bit 16 of the quantum field is set (as YARP's cameras send them), top row first otherwise.
#pragma once

#include <string>

#include "robogene/bottle.hpp"
#include "robogene/dev/image.hpp"

namespace robogene::dev {

Bottle encode_image(const ImageRgb& image, int quantum = 8);
// False with `error` saying which field is wrong (and how) for anything but a well-formed RGB
// image; a peer's bytes are never trusted for sizes.
bool decode_image(const Bottle& message, ImageRgb& out, std::string& error);

}  // namespace robogene::dev
