// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "handoff.h"

#include <stdint.h>

#include "generated/stm32g431_regs.h"

extern volatile uint32_t rg_boot_handoff[4];

#define STAY_MAGIC 0x59415453u  // "STAY"
#define AIRCR_VECTKEY (0x05FAu << 16)
#define AIRCR_SYSRESETREQ (1u << 2)

static void system_reset(void) {
  __asm__ volatile("dsb" ::: "memory");
  SCB_AIRCR = AIRCR_VECTKEY | AIRCR_SYSRESETREQ;
  __asm__ volatile("dsb" ::: "memory");
  for (;;) {
  }
}

void handoff_reset_into_bootloader(void) {
  rg_boot_handoff[0] = STAY_MAGIC;
  rg_boot_handoff[1] = ~STAY_MAGIC;  // a pair, so power-up garbage is not taken for a request
  system_reset();
}

void handoff_reset(void) {
  rg_boot_handoff[0] = 0u;
  rg_boot_handoff[1] = 0u;
  system_reset();
}

bool handoff_take_bootloader_request(void) {
  const bool asked = rg_boot_handoff[0] == STAY_MAGIC && rg_boot_handoff[1] == ~STAY_MAGIC;
  rg_boot_handoff[0] = 0u;
  rg_boot_handoff[1] = 0u;
  return asked;
}
