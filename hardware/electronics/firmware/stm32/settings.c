// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "settings.h"

#include "generated/stm32g431_regs.h"

extern const uint32_t rg_settings_page[];

#define RECORD_MAGIC 0x52474144u  // "RGAD"
#define FLASH_KEY1 0x45670123u
#define FLASH_KEY2 0xCDEF89ABu
#define FLASH_ERRORS (FLASH_SR_PROGERR_Msk | FLASH_SR_WRPERR_Msk | FLASH_SR_PGAERR_Msk | FLASH_SR_SIZERR_Msk | FLASH_SR_PGSERR_Msk)

uint8_t settings_address(uint8_t fallback) {
  const uint32_t magic = rg_settings_page[0], value = rg_settings_page[1];
  if (magic != RECORD_MAGIC || (value & 0xFFu) != (~(value >> 8) & 0xFFu)) return fallback;
  const uint8_t address = (uint8_t)(value & 0xFFu);
  return address >= 1u && address <= 14u ? address : fallback;
}

static bool wait_idle(void) {
  while (FLASH_SR & FLASH_SR_BSY_Msk) {
  }
  const bool ok = (FLASH_SR & FLASH_ERRORS) == 0u;
  FLASH_SR = FLASH_ERRORS | FLASH_SR_EOP_Msk;  // write 1 to clear
  return ok;
}

bool settings_save_address(uint8_t address) {
  const uint32_t page = ((uint32_t)(uintptr_t)rg_settings_page - 0x08000000u) / 2048u;
  FLASH_KEYR = FLASH_KEY1;
  FLASH_KEYR = FLASH_KEY2;
  bool ok = wait_idle();
  FLASH_CR = FLASH_CR_PER_Msk | (page << FLASH_CR_PNB_Pos);
  FLASH_CR |= FLASH_CR_STRT_Msk;
  ok = wait_idle() && ok;
  // One double word (the G4 programs 64 bits at a time): magic, then address and its complement.
  FLASH_CR = FLASH_CR_PG_Msk;
  volatile uint32_t *dst = (volatile uint32_t *)(uintptr_t)rg_settings_page;
  dst[0] = RECORD_MAGIC;
  dst[1] = (uint32_t)address | ((uint32_t)(uint8_t)~address << 8);
  ok = wait_idle() && ok;
  FLASH_CR = FLASH_CR_LOCK_Msk;
  return ok;
}
