// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "rg_boot.h"

#include <string.h>

#include "rg_wire.h"
#include "generated/robogene_can_motor_control.h"

static bool region_read(void *ctx, uint32_t offset, uint8_t *out, uint32_t len) {
  const rg_boot_hal_t *hal = (const rg_boot_hal_t *)ctx;
  if (offset > hal->region_size || len > hal->region_size - offset) return false;
  return hal->read(hal->ctx, offset, out, len);
}

static uint8_t check_region(const rg_boot_hal_t *hal, const rg_image_target_t *target) {
  return rg_image_check(region_read, (void *)(uintptr_t)hal, hal->region_size, target, NULL);
}

bool rg_boot_image_valid(const rg_boot_hal_t *hal, const rg_image_target_t *target) {
  return check_region(hal, target) == ROBOGENE_CAN_BOOT_STATUS_OK;
}

void rg_boot_init(rg_boot_t *b, uint8_t address, const rg_image_target_t *target, const rg_boot_hal_t *hal) {
  memset(b, 0, sizeof *b);
  b->hal = hal;
  b->address = address;
  b->target = *target;
  b->state = RG_BOOT_IDLE;
  b->image_valid = rg_boot_image_valid(hal, target);
}

static void reply(const rg_boot_t *b, const rg_can_frame_t *in, const uint8_t *payload, uint8_t len) {
  rg_can_frame_t f;
  const unsigned source = (in->id & ROBOGENE_CAN_SOURCE_MASK) >> ROBOGENE_CAN_SOURCE_SHIFT;
  f.id = (uint16_t)ROBOGENE_CAN_ID(ROBOGENE_CAN_CLASS_BOOTLOADER, b->address, source);
  f.len = len;
  memset(f.data, 0, sizeof f.data);
  f.data[0] = in->data[0];
  memcpy(f.data + 1, payload, (size_t)len - 1u);
  (void)b->hal->can_send(b->hal->ctx, &f);
}

static void reply_status(const rg_boot_t *b, const rg_can_frame_t *in, uint8_t status) {
  reply(b, in, &status, 2u);
}

static void identify(const rg_boot_t *b, const rg_can_frame_t *in) {
  uint8_t r[ROBOGENE_CAN_LEN_BOOTLOADER_IDENTIFY_REPLY];
  r[ROBOGENE_CAN_BOOTLOADER_IDENTIFY_REPLY_BOARD_TYPE_BYTE] = b->target.board_type;
  r[ROBOGENE_CAN_BOOTLOADER_IDENTIFY_REPLY_BOARD_ID_BYTE] = b->target.board_id;
  r[ROBOGENE_CAN_BOOTLOADER_IDENTIFY_REPLY_REVISION_BYTE] = b->target.revision;
  r[ROBOGENE_CAN_BOOTLOADER_IDENTIFY_REPLY_STAGE_BYTE] = ROBOGENE_CAN_FIRMWARE_STAGE_BOOTLOADER;
  r[ROBOGENE_CAN_BOOTLOADER_IDENTIFY_REPLY_IMAGE_VALID_BYTE] = (uint8_t)b->image_valid;
  r[ROBOGENE_CAN_BOOTLOADER_IDENTIFY_REPLY_VERSION_MAJOR_BYTE] = RG_BOOT_VERSION_MAJOR;
  r[ROBOGENE_CAN_BOOTLOADER_IDENTIFY_REPLY_VERSION_MINOR_BYTE] = RG_BOOT_VERSION_MINOR;
  reply(b, in, r + 1, sizeof r);
}

static uint8_t erase(rg_boot_t *b, uint32_t size) {
  const rg_boot_hal_t *hal = b->hal;
  if (size < RG_IMAGE_HEADER_END) return ROBOGENE_CAN_BOOT_STATUS_BAD_HEADER;  // cannot hold a header
  if (size > hal->region_size) return ROBOGENE_CAN_BOOT_STATUS_OUT_OF_RANGE;
  // From here on the region holds no valid image, whatever happens next.
  b->image_valid = false;
  b->state = RG_BOOT_IDLE;
  const uint32_t pages = (size + hal->page_size - 1u) / hal->page_size;
  for (uint32_t p = 0; p < pages; ++p) {
    if (!hal->erase_page(hal->ctx, p)) return ROBOGENE_CAN_BOOT_STATUS_FLASH_ERROR;
  }
  b->size = size;
  b->next_sequence = 0u;
  b->pending_len = 0u;
  b->state = RG_BOOT_WRITING;
  return ROBOGENE_CAN_BOOT_STATUS_OK;
}

// Programs the buffered unit (padded with the erased value) at the unit's offset.
static bool flush(rg_boot_t *b, uint32_t unit_offset) {
  if (b->pending_len == 0u) return true;
  memset(b->pending + b->pending_len, 0xFF, RG_BOOT_PROGRAM_UNIT - b->pending_len);
  b->pending_len = 0u;
  return b->hal->program(b->hal->ctx, unit_offset, b->pending);
}

// The header as soon as it is in flash: an image for another board is refused before the rest
// of it is written, and never verified.
static uint8_t check_written_header(const rg_boot_t *b) {
  uint8_t raw[RG_IMAGE_HEADER_SIZE];
  rg_image_header_t h;
  if (!b->hal->read(b->hal->ctx, RG_IMAGE_HEADER_OFFSET, raw, sizeof raw)) return ROBOGENE_CAN_BOOT_STATUS_FLASH_ERROR;
  rg_image_parse_header(raw, &h);
  const uint8_t status = rg_image_check_header(&h, &b->target, b->hal->region_size);
  if (status != ROBOGENE_CAN_BOOT_STATUS_OK) return status;
  return h.size == b->size ? ROBOGENE_CAN_BOOT_STATUS_OK : ROBOGENE_CAN_BOOT_STATUS_BAD_HEADER;
}

static uint8_t write_word(rg_boot_t *b, uint16_t sequence, const uint8_t *data) {
  const uint32_t offset = (uint32_t)sequence * 4u;
  if (offset >= b->size) return ROBOGENE_CAN_BOOT_STATUS_OUT_OF_RANGE;
  memcpy(b->pending + b->pending_len, data, 4u);
  b->pending_len += 4u;
  const uint32_t end = offset + 4u;
  const uint32_t unit = offset & ~(uint32_t)(RG_BOOT_PROGRAM_UNIT - 1u);
  if ((b->pending_len == RG_BOOT_PROGRAM_UNIT || end >= b->size) && !flush(b, unit)) {
    b->state = RG_BOOT_IDLE;
    return ROBOGENE_CAN_BOOT_STATUS_FLASH_ERROR;
  }
  b->next_sequence = (uint16_t)(sequence + 1u);
  if (end == RG_IMAGE_HEADER_END) {
    const uint8_t status = check_written_header(b);
    if (status != ROBOGENE_CAN_BOOT_STATUS_OK) {
      b->state = RG_BOOT_REFUSED;
      return status;
    }
  }
  if (end >= b->size) b->state = RG_BOOT_WRITTEN;
  return ROBOGENE_CAN_BOOT_STATUS_OK;
}

static void write(rg_boot_t *b, const rg_can_frame_t *in) {
  const uint16_t sequence = rg_get_u16(in->data + ROBOGENE_CAN_BOOTLOADER_WRITE_SEQUENCE_BYTE);
  uint8_t r[3];
  uint16_t answered = sequence;
  uint8_t status = ROBOGENE_CAN_BOOT_STATUS_OK;
  if (b->state == RG_BOOT_WRITING && sequence == b->next_sequence) {
    status = write_word(b, sequence, in->data + ROBOGENE_CAN_BOOTLOADER_WRITE_DATA_BYTE);
  } else if ((b->state == RG_BOOT_WRITING || b->state == RG_BOOT_WRITTEN) && b->next_sequence > 0u &&
             sequence == b->next_sequence - 1u) {
    // A repeat of the last write (its acknowledgement was lost): acknowledged again, not rewritten.
  } else if (b->state == RG_BOOT_WRITING) {
    status = ROBOGENE_CAN_BOOT_STATUS_BAD_SEQUENCE;
    answered = b->next_sequence;
  } else {
    status = ROBOGENE_CAN_BOOT_STATUS_BAD_STATE;
  }
  rg_put_u16(r, answered);
  r[2] = status;
  reply(b, in, r, ROBOGENE_CAN_LEN_BOOTLOADER_WRITE_REPLY);
}

static void verify(rg_boot_t *b, const rg_can_frame_t *in) {
  uint8_t r[5];
  uint32_t crc = 0u;
  uint8_t status = ROBOGENE_CAN_BOOT_STATUS_BAD_STATE;
  if (b->state == RG_BOOT_WRITTEN) {
    rg_image_header_t h;
    status = rg_image_check(region_read, (void *)(uintptr_t)b->hal, b->hal->region_size, &b->target, &h);
    if (status == ROBOGENE_CAN_BOOT_STATUS_OK && h.size != b->size) status = ROBOGENE_CAN_BOOT_STATUS_BAD_HEADER;
    bool ok = true;
    crc = rg_image_crc(region_read, (void *)(uintptr_t)b->hal, b->size, &ok);
    b->image_valid = status == ROBOGENE_CAN_BOOT_STATUS_OK;
  }
  r[0] = status;
  rg_put_u32(r + 1, crc);
  reply(b, in, r, ROBOGENE_CAN_LEN_BOOTLOADER_VERIFY_REPLY);
}

static void start(rg_boot_t *b, const rg_can_frame_t *in) {
  // Checked again, whatever the state: only an image that checks now is ever started.
  const uint8_t status = check_region(b->hal, &b->target);
  b->image_valid = status == ROBOGENE_CAN_BOOT_STATUS_OK;
  if (status != ROBOGENE_CAN_BOOT_STATUS_OK) {
    reply_status(b, in, status == ROBOGENE_CAN_BOOT_STATUS_FLASH_ERROR ? status : ROBOGENE_CAN_BOOT_STATUS_NO_IMAGE);
    return;
  }
  reply_status(b, in, ROBOGENE_CAN_BOOT_STATUS_OK);
  b->state = RG_BOOT_IDLE;
  b->hal->start_application(b->hal->ctx);
}

static uint8_t request_length(unsigned code) {
  switch (code) {
    case ROBOGENE_CAN_CMD_ENTER_BOOTLOADER: return ROBOGENE_CAN_LEN_ENTER_BOOTLOADER;
    case ROBOGENE_CAN_CMD_BOOTLOADER_IDENTIFY: return ROBOGENE_CAN_LEN_BOOTLOADER_IDENTIFY;
    case ROBOGENE_CAN_CMD_BOOTLOADER_ERASE: return ROBOGENE_CAN_LEN_BOOTLOADER_ERASE;
    case ROBOGENE_CAN_CMD_BOOTLOADER_WRITE: return ROBOGENE_CAN_LEN_BOOTLOADER_WRITE;
    case ROBOGENE_CAN_CMD_BOOTLOADER_VERIFY: return ROBOGENE_CAN_LEN_BOOTLOADER_VERIFY;
    case ROBOGENE_CAN_CMD_BOOTLOADER_START: return ROBOGENE_CAN_LEN_BOOTLOADER_START;
    default: return 0u;
  }
}

void rg_boot_receive(rg_boot_t *b, const rg_can_frame_t *frame) {
  const unsigned message_class = (frame->id & ROBOGENE_CAN_MESSAGE_CLASS_MASK) >> ROBOGENE_CAN_MESSAGE_CLASS_SHIFT;
  const unsigned source = (frame->id & ROBOGENE_CAN_SOURCE_MASK) >> ROBOGENE_CAN_SOURCE_SHIFT;
  const unsigned destination = (frame->id & ROBOGENE_CAN_DESTINATION_MASK) >> ROBOGENE_CAN_DESTINATION_SHIFT;
  if (message_class != ROBOGENE_CAN_CLASS_BOOTLOADER || source != ROBOGENE_CAN_HOST_ADDRESS) return;
  const bool to_all = destination == ROBOGENE_CAN_BROADCAST_ADDRESS;
  if (destination != b->address && !to_all) return;
  const unsigned code = frame->len >= 1u ? (frame->data[0] & ~ROBOGENE_CAN_AXIS_BIT & 0xFFu) : 0xFFu;
  const unsigned length = request_length(code);
  if (length == 0u || frame->len != length) {
    ++b->rejected_frames;
    return;
  }
  // Several boards may hear a broadcast: it may only ask who they are, never change their flash.
  if (to_all && code != ROBOGENE_CAN_CMD_BOOTLOADER_IDENTIFY) return;
  switch (code) {
    case ROBOGENE_CAN_CMD_BOOTLOADER_IDENTIFY:
      identify(b, frame);
      break;
    case ROBOGENE_CAN_CMD_BOOTLOADER_ERASE:
      reply_status(b, frame, erase(b, rg_get_u32(frame->data + ROBOGENE_CAN_BOOTLOADER_ERASE_SIZE_BYTE)));
      break;
    case ROBOGENE_CAN_CMD_BOOTLOADER_WRITE:
      write(b, frame);
      break;
    case ROBOGENE_CAN_CMD_BOOTLOADER_VERIFY:
      verify(b, frame);
      break;
    case ROBOGENE_CAN_CMD_BOOTLOADER_START:
      start(b, frame);
      break;
    default:  // enter_bootloader: already here
      break;
  }
}
