// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// The board's CAN address across resets, in the flash page the linker script sets aside
// (rg_settings_page): set_board_id writes it, start-up reads it.
#ifndef SETTINGS_H
#define SETTINGS_H

#include <stdbool.h>
#include <stdint.h>

// The stored address, or `fallback` when the page is erased or holds no valid record.
uint8_t settings_address(uint8_t fallback);
// Erases the page and writes the record; false when the flash reports an error.
bool settings_save_address(uint8_t address);

#endif  // SETTINGS_H
