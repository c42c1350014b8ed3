// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// What the running application answers of the bootloader class: who it is (so that
// `robogene can-flash` can check an image against the board before anything is erased) and the
// request to restart into the bootloader, taken only with its key and with the motors stopped.
#include <string.h>

#include "rg_boot.h"
#include "rg_board.h"
#include "rg_revision.h"
#include "rg_wire.h"
#include "generated/robogene_can_motor_control.h"

static void identify(const rg_board_t *b, const rg_can_frame_t *in, unsigned source) {
  rg_can_frame_t f;
  f.id = (uint16_t)ROBOGENE_CAN_ID(ROBOGENE_CAN_CLASS_BOOTLOADER, b->address, source);
  f.len = ROBOGENE_CAN_LEN_BOOTLOADER_IDENTIFY_REPLY;
  f.data[0] = in->data[0];
  f.data[ROBOGENE_CAN_BOOTLOADER_IDENTIFY_REPLY_BOARD_TYPE_BYTE] = ROBOGENE_CAN_BOARD_TYPE_ROBOGENE_MOTOR_BOARD;
  f.data[ROBOGENE_CAN_BOOTLOADER_IDENTIFY_REPLY_BOARD_ID_BYTE] = b->params.board_id;
  f.data[ROBOGENE_CAN_BOOTLOADER_IDENTIFY_REPLY_REVISION_BYTE] = (uint8_t)ROBOGENE_BOARD_REVISION;
  f.data[ROBOGENE_CAN_BOOTLOADER_IDENTIFY_REPLY_STAGE_BYTE] = ROBOGENE_CAN_FIRMWARE_STAGE_APPLICATION;
  f.data[ROBOGENE_CAN_BOOTLOADER_IDENTIFY_REPLY_IMAGE_VALID_BYTE] = 1u;  // the bootloader started it
  f.data[ROBOGENE_CAN_BOOTLOADER_IDENTIFY_REPLY_VERSION_MAJOR_BYTE] = RG_FIRMWARE_VERSION;
  f.data[ROBOGENE_CAN_BOOTLOADER_IDENTIFY_REPLY_VERSION_MINOR_BYTE] = RG_FIRMWARE_REVISION;
  (void)b->hal->can_send(b->hal->ctx, &f);
}

void rg_board_receive_bootloader(rg_board_t *b, const rg_can_frame_t *frame) {
  const unsigned source = (frame->id & ROBOGENE_CAN_SOURCE_MASK) >> ROBOGENE_CAN_SOURCE_SHIFT;
  const unsigned destination = (frame->id & ROBOGENE_CAN_DESTINATION_MASK) >> ROBOGENE_CAN_DESTINATION_SHIFT;
  if (source != ROBOGENE_CAN_HOST_ADDRESS) return;
  if (destination != b->address && destination != ROBOGENE_CAN_BROADCAST_ADDRESS) return;
  if (frame->len < 1u) {
    ++b->rejected_frames;
    return;
  }
  const unsigned code = frame->data[0] & ~ROBOGENE_CAN_AXIS_BIT & 0xFFu;
  if (code == ROBOGENE_CAN_CMD_BOOTLOADER_IDENTIFY && frame->len == ROBOGENE_CAN_LEN_BOOTLOADER_IDENTIFY) {
    identify(b, frame, source);
    return;
  }
  // Only addressed to this board: a broadcast must not restart the whole head.
  if (code == ROBOGENE_CAN_CMD_ENTER_BOOTLOADER && frame->len == ROBOGENE_CAN_LEN_ENTER_BOOTLOADER &&
      destination == b->address) {
    if (rg_get_u32(frame->data + ROBOGENE_CAN_ENTER_BOOTLOADER_KEY_BYTE) != RG_BOOT_ENTER_KEY) return;
    for (unsigned i = 0; i < 2u; ++i) {
      if (b->axes[i].present) rg_board_set_mode(b, i, ROBOGENE_CAN_CONTROL_MODE_IDLE);
    }
    rg_board_stop_motors(b);
    if (b->hal->enter_bootloader != NULL) b->hal->enter_bootloader(b->hal->ctx);
    return;
  }
  // The bootloader's own commands reach the application when a host mistakes the stage: ignored.
  if (code != ROBOGENE_CAN_CMD_BOOTLOADER_ERASE && code != ROBOGENE_CAN_CMD_BOOTLOADER_WRITE &&
      code != ROBOGENE_CAN_CMD_BOOTLOADER_VERIFY && code != ROBOGENE_CAN_CMD_BOOTLOADER_START) {
    ++b->rejected_frames;
  }
}
