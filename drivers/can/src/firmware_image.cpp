// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "robogene/can/firmware_image.hpp"

#include <cstdio>
#include <cstring>
#include <fstream>
#include <iterator>
#include <sstream>

#include "rg_crc32.h"
#include "rg_image.h"
#include "rg_revision.h"
#include "generated/robogene_can_motor_control.h"

namespace robogene::can {
namespace {

std::string hex32(std::uint32_t v) {
  char buf[16];
  std::snprintf(buf, sizeof buf, "0x%08X", v);
  return buf;
}

bool ends_with(const std::string& s, const std::string& tail) {
  return s.size() >= tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
}

bool read_vector(void* ctx, std::uint32_t offset, std::uint8_t* out, std::uint32_t len) {
  const auto& v = *static_cast<const std::vector<std::uint8_t>*>(ctx);
  if (offset > v.size() || len > v.size() - offset) return false;
  std::memcpy(out, v.data() + offset, len);
  return true;
}

int hex_digit(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  return -1;
}

// Intel HEX (record types 00 data, 01 end, 02 and 04 base addresses, 03 and 05 start addresses).
std::vector<std::uint8_t> read_hex(const std::string& path, std::istream& in) {
  std::vector<std::uint8_t> out;
  std::uint32_t base = 0;
  bool ended = false;
  std::string line;
  for (int number = 1; std::getline(in, line); ++number) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.empty()) continue;
    const std::string where = path + ":" + std::to_string(number) + ": ";
    if (ended) throw FirmwareImageError(where + "a record after the end-of-file record");
    if (line[0] != ':' || line.size() < 11 || line.size() % 2 == 0) {
      throw FirmwareImageError(where + "not an Intel HEX record (':' and an even number of hex digits)");
    }
    std::vector<std::uint8_t> rec;
    for (std::size_t i = 1; i + 1 < line.size(); i += 2) {
      const int hi = hex_digit(line[i]), lo = hex_digit(line[i + 1]);
      if (hi < 0 || lo < 0) throw FirmwareImageError(where + "'" + line.substr(i, 2) + "' is not a hex byte");
      rec.push_back(static_cast<std::uint8_t>(hi * 16 + lo));
    }
    std::uint8_t sum = 0;
    for (auto b : rec) sum = static_cast<std::uint8_t>(sum + b);
    if (sum != 0) throw FirmwareImageError(where + "checksum does not match");
    const std::size_t count = rec[0];
    if (rec.size() != count + 5) throw FirmwareImageError(where + "the byte count " + std::to_string(count) + " does not match the record's length");
    const std::uint32_t offset = (std::uint32_t{rec[1]} << 8) | rec[2];
    const std::uint8_t type = rec[3];
    const std::uint8_t* data = rec.data() + 4;
    switch (type) {
      case 0x00: {
        const std::uint64_t at = std::uint64_t{base} + offset;
        if (at < kApplicationBase || at + count > std::uint64_t{kApplicationBase} + kApplicationRegionBytes) {
          throw FirmwareImageError(where + "data at " + hex32(static_cast<std::uint32_t>(at)) +
                                   " is outside the application region (" + hex32(kApplicationBase) + ", " +
                                   std::to_string(kApplicationRegionBytes / 1024) + " KiB): not an application image");
        }
        const std::size_t rel = static_cast<std::size_t>(at - kApplicationBase);
        if (out.size() < rel + count) out.resize(rel + count, 0xFF);
        std::memcpy(out.data() + rel, data, count);
        break;
      }
      case 0x01: ended = true; break;
      case 0x02:
        if (count != 2) throw FirmwareImageError(where + "an extended segment address record carries 2 bytes");
        base = ((std::uint32_t{data[0]} << 8) | data[1]) << 4;
        break;
      case 0x04:
        if (count != 2) throw FirmwareImageError(where + "an extended linear address record carries 2 bytes");
        base = ((std::uint32_t{data[0]} << 8) | data[1]) << 16;
        break;
      case 0x03:
      case 0x05: break;  // start addresses: the vector table says where the image starts
      default: throw FirmwareImageError(where + "unknown record type " + std::to_string(type));
    }
  }
  if (!ended) throw FirmwareImageError(path + ": no end-of-file record (a truncated HEX file?)");
  return out;
}

}  // namespace

char board_revision() { return static_cast<char>(ROBOGENE_BOARD_REVISION); }

FirmwareImage firmware_image_from_bytes(std::vector<std::uint8_t> bytes, const std::string& source) {
  if (bytes.size() < RG_IMAGE_HEADER_END) {
    throw FirmwareImageError(source + ": " + std::to_string(bytes.size()) + " bytes, too short for an application image (its header ends at " +
                             std::to_string(RG_IMAGE_HEADER_END) + ")");
  }
  if (bytes.size() > kApplicationRegionBytes) {
    throw FirmwareImageError(source + ": " + std::to_string(bytes.size()) + " bytes do not fit the " +
                             std::to_string(kApplicationRegionBytes) + "-byte application region");
  }
  rg_image_header_t h;
  rg_image_parse_header(bytes.data() + RG_IMAGE_HEADER_OFFSET, &h);
  if (h.magic != RG_IMAGE_MAGIC || h.header_version != RG_IMAGE_HEADER_VERSION) {
    throw FirmwareImageError(source + ": no image header at offset 0x200 (magic " + hex32(h.magic) +
                             "): not an application image stamped by `make firmware` (a bootloader image, or a raw binary?)");
  }
  if (h.size != bytes.size()) {
    throw FirmwareImageError(source + ": the header says " + std::to_string(h.size) + " bytes, the file holds " +
                             std::to_string(bytes.size()) + " (truncated or padded)");
  }
  bool ok = false;
  const std::uint32_t crc = rg_image_crc(read_vector, &bytes, h.size, &ok);
  if (!ok || crc != h.crc) {
    throw FirmwareImageError(source + ": CRC-32 mismatch: the header says " + hex32(h.crc) + ", the bytes give " + hex32(crc) +
                             " (the file is corrupted or was changed after the build stamped it)");
  }
  FirmwareImage img;
  img.source = source;
  img.bytes = std::move(bytes);
  img.size = h.size;
  img.crc = h.crc;
  img.board_type = h.board_type;
  img.board_id = h.board_id;
  img.revision = h.revision;
  img.version_major = h.version_major;
  img.version_minor = h.version_minor;
  img.version_build = h.version_build;
  return img;
}

FirmwareImage read_firmware_image(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw FirmwareImageError(path + ": cannot open the image");
  if (ends_with(path, ".hex") || ends_with(path, ".ihex")) return firmware_image_from_bytes(read_hex(path, in), path);
  if (ends_with(path, ".elf")) {
    throw FirmwareImageError(path + ": give the .bin or .hex `make firmware` writes next to the ELF");
  }
  std::vector<std::uint8_t> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  return firmware_image_from_bytes(std::move(bytes), path);
}

std::vector<std::uint8_t> make_stamped_image(std::uint8_t board_id, std::uint8_t revision, std::uint32_t size,
                                             std::uint8_t version_major, std::uint8_t version_minor) {
  if (size < RG_IMAGE_HEADER_END || size > kApplicationRegionBytes) throw Error("make_stamped_image: bad size " + std::to_string(size));
  std::vector<std::uint8_t> img(size);
  for (std::uint32_t i = 0; i < size; ++i) img[i] = static_cast<std::uint8_t>((i * 131u + board_id) >> 3);
  rg_image_header_t h{};
  h.magic = RG_IMAGE_MAGIC;
  h.size = size;
  h.header_version = RG_IMAGE_HEADER_VERSION;
  h.board_type = ROBOGENE_CAN_BOARD_TYPE_ROBOGENE_MOTOR_BOARD;
  h.board_id = board_id;
  h.revision = revision;
  h.version_major = version_major;
  h.version_minor = version_minor;
  std::uint8_t* raw = img.data() + RG_IMAGE_HEADER_OFFSET;
  auto put32 = [&](std::size_t at, std::uint32_t v) {
    for (int i = 0; i < 4; ++i) raw[at + static_cast<std::size_t>(i)] = static_cast<std::uint8_t>(v >> (8 * i));
  };
  std::memset(raw, 0, RG_IMAGE_HEADER_SIZE);
  put32(RG_IMAGE_MAGIC_AT, h.magic);
  put32(RG_IMAGE_SIZE_AT, h.size);
  raw[RG_IMAGE_HEADER_VERSION_AT] = h.header_version;
  raw[RG_IMAGE_BOARD_TYPE_AT] = h.board_type;
  raw[RG_IMAGE_BOARD_ID_AT] = h.board_id;
  raw[RG_IMAGE_REVISION_AT] = h.revision;
  raw[RG_IMAGE_VERSION_AT] = h.version_major;
  raw[RG_IMAGE_VERSION_AT + 1] = h.version_minor;
  bool ok = false;
  put32(RG_IMAGE_CRC_AT, rg_image_crc(read_vector, &img, size, &ok));
  return img;
}

std::string describe(const FirmwareImage& image) {
  std::ostringstream s;
  s << "board " << int(image.board_id) << ", revision " << static_cast<char>(image.revision) << ", firmware "
    << int(image.version_major) << "." << int(image.version_minor) << "." << int(image.version_build) << ", "
    << image.size << " bytes, CRC-32 " << hex32(image.crc);
  return s.str();
}

}  // namespace robogene::can
