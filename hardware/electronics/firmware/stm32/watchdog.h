// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// The independent watchdog (IWDG, its own 32 kHz LSI): the control loop refreshes it once per
// period; a loop stuck for 50 ms resets the board, which comes back with its bridges off.
#ifndef WATCHDOG_H
#define WATCHDOG_H

void watchdog_start(void);
void watchdog_refresh(void);

#endif  // WATCHDOG_H
