// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// What the board keeps across resets, in the flash page the linker script sets aside
// (rg_settings_page): the CAN address set_board_id gave, and each axis's joint-encoder zero
// set_joint_encoder_zero gave. One double word per record (magic, value and its complement); the page
// is erased and every record written again on each save, so a save keeps the others.
#ifndef SETTINGS_H
#define SETTINGS_H

#include <stdbool.h>
#include <stdint.h>

typedef struct {
  bool has_address;
  uint8_t address;
  bool has_joint_zero[2];
  uint16_t joint_zero[2];
} settings_t;

// The records that are present and check.
void settings_load(settings_t *out);
// Erases the page and writes the records present; false when the flash reports an error.
bool settings_store(const settings_t *s);
// The stored address, or `fallback` when the page is erased or holds no valid record.
uint8_t settings_address(uint8_t fallback);

#endif  // SETTINGS_H
