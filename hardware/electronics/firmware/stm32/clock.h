// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// System clock: the board's 8 MHz crystal (HSE) through the PLL to 150 MHz, the most voltage range 1
// allows without boost mode (RM0440 6.1.5), with the flash wait states that speed needs.
#ifndef CLOCK_H
#define CLOCK_H

#include <stdint.h>

#define SYSCLK_HZ 150000000u
#define HSE_HZ 8000000u

void clock_init(void);
// Busy-waits `us` microseconds (SysTick must not be running yet: used during start-up only).
void clock_delay_us(uint32_t us);

#endif  // CLOCK_H
