// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "watchdog.h"

#include "generated/stm32g431_regs.h"

#define IWDG_KEY_START 0xCCCCu
#define IWDG_KEY_REFRESH 0xAAAAu
#define IWDG_KEY_UNLOCK 0x5555u

void watchdog_start(void) {
  IWDG_KR = IWDG_KEY_START;  // also starts the LSI
  IWDG_KR = IWDG_KEY_UNLOCK;
  IWDG_PR = 0u;    // LSI / 4: 8 kHz
  IWDG_RLR = 400u;  // 400 ticks: 50 ms, more than a settings page erase (about 22 ms)
  while (IWDG_SR != 0u) {
  }
  IWDG_KR = IWDG_KEY_REFRESH;
}

void watchdog_refresh(void) { IWDG_KR = IWDG_KEY_REFRESH; }
