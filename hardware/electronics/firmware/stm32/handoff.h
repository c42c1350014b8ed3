// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// The bootloader and the application hand over through a reset, never by a jump between
// configured peripherals: the application asks to stay in the bootloader by leaving a word in the
// first 16 bytes of SRAM (rg_boot_handoff, kept out of .data and .bss by both linker scripts)
// and resetting; the bootloader starts an application by resetting with the word cleared, and
// jumps to it before it sets up any peripheral.
#ifndef HANDOFF_H
#define HANDOFF_H

#include <stdbool.h>

// Leaves the request and resets the part; does not return.
void handoff_reset_into_bootloader(void);
// Clears any request and resets the part; does not return.
void handoff_reset(void);
// True once after handoff_reset_into_bootloader(); the request is cleared on reading.
bool handoff_take_bootloader_request(void);

#endif  // HANDOFF_H
