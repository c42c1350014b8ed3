// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "rg_image.h"

#include <string.h>

#include "rg_crc32.h"
#include "rg_wire.h"
#include "generated/robogene_can_motor_control.h"

_Static_assert(sizeof(rg_image_header_t) == RG_IMAGE_HEADER_SIZE, "the header is 32 bytes in flash");

void rg_image_parse_header(const uint8_t raw[RG_IMAGE_HEADER_SIZE], rg_image_header_t *out) {
  memset(out, 0, sizeof *out);
  out->magic = rg_get_u32(raw + RG_IMAGE_MAGIC_AT);
  out->size = rg_get_u32(raw + RG_IMAGE_SIZE_AT);
  out->crc = rg_get_u32(raw + RG_IMAGE_CRC_AT);
  out->header_version = raw[RG_IMAGE_HEADER_VERSION_AT];
  out->board_type = raw[RG_IMAGE_BOARD_TYPE_AT];
  out->board_id = raw[RG_IMAGE_BOARD_ID_AT];
  out->revision = raw[RG_IMAGE_REVISION_AT];
  out->version_major = raw[RG_IMAGE_VERSION_AT];
  out->version_minor = raw[RG_IMAGE_VERSION_AT + 1u];
  out->version_build = raw[RG_IMAGE_VERSION_AT + 2u];
}

uint8_t rg_image_check_header(const rg_image_header_t *h, const rg_image_target_t *target, uint32_t region_size) {
  if (h->magic != RG_IMAGE_MAGIC || h->header_version != RG_IMAGE_HEADER_VERSION || h->size < RG_IMAGE_HEADER_END) {
    return ROBOGENE_CAN_BOOT_STATUS_BAD_HEADER;
  }
  if (h->size > region_size) return ROBOGENE_CAN_BOOT_STATUS_OUT_OF_RANGE;
  if (h->board_type != target->board_type || h->board_id != target->board_id) return ROBOGENE_CAN_BOOT_STATUS_WRONG_BOARD;
  if (h->revision != target->revision) return ROBOGENE_CAN_BOOT_STATUS_WRONG_REVISION;
  return ROBOGENE_CAN_BOOT_STATUS_OK;
}

uint32_t rg_image_crc(rg_image_read_fn read, void *ctx, uint32_t size, bool *ok) {
  static const uint8_t zero[4] = {0u, 0u, 0u, 0u};
  const uint32_t crc_at = RG_IMAGE_HEADER_OFFSET + RG_IMAGE_CRC_AT;
  uint8_t chunk[64];
  uint32_t crc = 0u;
  *ok = true;
  for (uint32_t at = 0u; at < size;) {
    // Chunks stop at the crc field, which counts as four zero bytes.
    if (at == crc_at) {
      crc = rg_crc32(crc, zero, size - at < 4u ? size - at : 4u);
      at += 4u;
      continue;
    }
    uint32_t n = size - at < sizeof chunk ? size - at : (uint32_t)sizeof chunk;
    if (at < crc_at && at + n > crc_at) n = crc_at - at;
    if (!read(ctx, at, chunk, n)) {
      *ok = false;
      return 0u;
    }
    crc = rg_crc32(crc, chunk, n);
    at += n;
  }
  return crc;
}

uint8_t rg_image_check(rg_image_read_fn read, void *ctx, uint32_t region_size, const rg_image_target_t *target,
                       rg_image_header_t *header) {
  uint8_t raw[RG_IMAGE_HEADER_SIZE];
  rg_image_header_t h;
  if (region_size < RG_IMAGE_HEADER_END || !read(ctx, RG_IMAGE_HEADER_OFFSET, raw, sizeof raw)) {
    return ROBOGENE_CAN_BOOT_STATUS_BAD_HEADER;
  }
  rg_image_parse_header(raw, &h);
  if (header != NULL) *header = h;
  const uint8_t status = rg_image_check_header(&h, target, region_size);
  if (status != ROBOGENE_CAN_BOOT_STATUS_OK) return status;
  bool ok = false;
  const uint32_t crc = rg_image_crc(read, ctx, h.size, &ok);
  if (!ok) return ROBOGENE_CAN_BOOT_STATUS_FLASH_ERROR;
  return crc == h.crc ? ROBOGENE_CAN_BOOT_STATUS_OK : ROBOGENE_CAN_BOOT_STATUS_CRC_MISMATCH;
}
