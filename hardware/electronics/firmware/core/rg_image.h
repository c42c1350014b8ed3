// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// The header the build stamps into every application image (docs/firmware.md#the-image-header),
// and the checks the bootloader, the simulator and `robogene can-flash` make of an image with it.
// The header sits at a fixed offset, right after the vector table; its size and CRC fields are
// written after linking (tools/stamp_image.py), the rest by the compiler.
#ifndef RG_IMAGE_H
#define RG_IMAGE_H

#include <stdbool.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

#define RG_IMAGE_HEADER_OFFSET 0x200u  // the vector table (118 entries, 472 bytes) fits before it
#define RG_IMAGE_HEADER_SIZE 32u
#define RG_IMAGE_HEADER_END (RG_IMAGE_HEADER_OFFSET + RG_IMAGE_HEADER_SIZE)
#define RG_IMAGE_MAGIC 0x4D494752u  // "RGIM" in memory order
#define RG_IMAGE_HEADER_VERSION 1u
// Byte offsets inside the header; multi-byte fields little-endian.
#define RG_IMAGE_MAGIC_AT 0u
#define RG_IMAGE_SIZE_AT 4u
#define RG_IMAGE_CRC_AT 8u  // CRC-32 of the image's `size` bytes with these four read as zero
#define RG_IMAGE_HEADER_VERSION_AT 12u
#define RG_IMAGE_BOARD_TYPE_AT 13u
#define RG_IMAGE_BOARD_ID_AT 14u
#define RG_IMAGE_REVISION_AT 15u
#define RG_IMAGE_VERSION_AT 16u  // major, minor, build

typedef struct {
  uint32_t magic;
  uint32_t size;                 // bytes from the vector table to the end of the image
  uint32_t crc;
  uint8_t header_version;
  uint8_t board_type;            // ROBOGENE_CAN_BOARD_TYPE_*
  uint8_t board_id;              // the head-table address the image was built for
  uint8_t revision;              // the board revision, an ASCII letter
  uint8_t version_major, version_minor, version_build;
  uint8_t reserved[13];
} rg_image_header_t;             // the in-flash layout on the little-endian Cortex-M4

// What an image must have been built for to run on a board.
typedef struct {
  uint8_t board_type, board_id, revision;
} rg_image_target_t;

// Reads `len` bytes at `offset` of the image (the application region); false when it cannot.
typedef bool (*rg_image_read_fn)(void *ctx, uint32_t offset, uint8_t *out, uint32_t len);

void rg_image_parse_header(const uint8_t raw[RG_IMAGE_HEADER_SIZE], rg_image_header_t *out);

// The header alone: ROBOGENE_CAN_BOOT_STATUS_OK, or BAD_HEADER (no magic, unknown header version,
// a size that cannot hold the header), OUT_OF_RANGE (bigger than `region_size`), WRONG_BOARD
// (board type or id) or WRONG_REVISION.
uint8_t rg_image_check_header(const rg_image_header_t *h, const rg_image_target_t *target, uint32_t region_size);

// The CRC the header's crc field must hold for the first `size` bytes `read` gives; false in
// *ok when a read failed.
uint32_t rg_image_crc(rg_image_read_fn read, void *ctx, uint32_t size, bool *ok);

// Header and CRC: OK only for an image this board may start. `header` may be NULL.
uint8_t rg_image_check(rg_image_read_fn read, void *ctx, uint32_t region_size, const rg_image_target_t *target,
                       rg_image_header_t *header);

#ifdef __cplusplus
}
#endif

#endif  // RG_IMAGE_H
