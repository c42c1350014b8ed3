// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// The application's image header (core/rg_image.h), at 0x200 from the image's start (the linker
// script places .image_header). The compiler fills in what the image is for; size and CRC stay
// zero here and are stamped after linking by tools/stamp_image.py, which refuses an image whose
// header is not this one.
#include "rg_board.h"
#include "rg_image.h"
#include "rg_revision.h"
#include "generated/robogene_can_motor_control.h"

#ifndef ROBOGENE_BOARD_ADDRESS
#error "build one image per board: -DROBOGENE_BOARD_ADDRESS=<the board's address in the head table>"
#endif

__attribute__((section(".image_header"), used)) const rg_image_header_t rg_image_header = {
    .magic = RG_IMAGE_MAGIC,
    .size = 0u,
    .crc = 0u,
    .header_version = RG_IMAGE_HEADER_VERSION,
    .board_type = ROBOGENE_CAN_BOARD_TYPE_ROBOGENE_MOTOR_BOARD,
    .board_id = ROBOGENE_BOARD_ADDRESS,
    .revision = (uint8_t)ROBOGENE_BOARD_REVISION,
    .version_major = RG_FIRMWARE_VERSION,
    .version_minor = RG_FIRMWARE_REVISION,
    .version_build = RG_FIRMWARE_BUILD,
    .reserved = {0},
};
