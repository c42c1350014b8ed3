// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "app_flash.h"

#include <string.h>

#include "generated/stm32g431_regs.h"

extern const uint8_t rg_app_region[];
extern const uint8_t rg_app_region_size[];  // a linker symbol: its address is the size

#define FLASH_BASE_ADDRESS 0x08000000u
#define FLASH_KEY1 0x45670123u
#define FLASH_KEY2 0xCDEF89ABu
#define FLASH_ERRORS \
  (FLASH_SR_PROGERR_Msk | FLASH_SR_WRPERR_Msk | FLASH_SR_PGAERR_Msk | FLASH_SR_SIZERR_Msk | FLASH_SR_PGSERR_Msk)

uint32_t app_flash_base(void) { return (uint32_t)(uintptr_t)rg_app_region; }
uint32_t app_flash_size(void) { return (uint32_t)(uintptr_t)rg_app_region_size; }

static bool wait_idle(void) {
  while (FLASH_SR & FLASH_SR_BSY_Msk) {
  }
  const bool ok = (FLASH_SR & FLASH_ERRORS) == 0u;
  FLASH_SR = FLASH_ERRORS | FLASH_SR_EOP_Msk;  // write 1 to clear
  return ok;
}

static void unlock(void) {
  if (FLASH_CR & FLASH_CR_LOCK_Msk) {
    FLASH_KEYR = FLASH_KEY1;
    FLASH_KEYR = FLASH_KEY2;
  }
}

bool app_flash_erase_page(void *ctx, uint32_t page) {
  (void)ctx;
  if ((page + 1u) * APP_FLASH_PAGE_BYTES > app_flash_size()) return false;
  // Page numbers count from the start of flash (single bank, 2 KiB pages).
  const uint32_t pnb = (app_flash_base() - FLASH_BASE_ADDRESS) / APP_FLASH_PAGE_BYTES + page;
  unlock();
  bool ok = wait_idle();
  FLASH_CR = FLASH_CR_PER_Msk | ((pnb << FLASH_CR_PNB_Pos) & FLASH_CR_PNB_Msk);
  FLASH_CR |= FLASH_CR_STRT_Msk;
  ok = wait_idle() && ok;
  FLASH_CR = FLASH_CR_LOCK_Msk;
  return ok;
}

bool app_flash_program(void *ctx, uint32_t offset, const uint8_t *data) {
  (void)ctx;
  if ((offset & 7u) != 0u || offset + 8u > app_flash_size()) return false;
  uint32_t words[2];
  memcpy(words, data, sizeof words);
  volatile uint32_t *dst = (volatile uint32_t *)(uintptr_t)(app_flash_base() + offset);
  unlock();
  bool ok = wait_idle();
  FLASH_CR = FLASH_CR_PG_Msk;
  dst[0] = words[0];  // the first word, then the second: the G4 programs the pair together
  dst[1] = words[1];
  ok = wait_idle() && ok;
  FLASH_CR = FLASH_CR_LOCK_Msk;
  // Read back: a cell that was not erased programs wrong without always raising PROGERR.
  return ok && memcmp((const void *)(uintptr_t)(app_flash_base() + offset), data, 8u) == 0;
}

bool app_flash_read(void *ctx, uint32_t offset, uint8_t *out, uint32_t len) {
  (void)ctx;
  if (offset > app_flash_size() || len > app_flash_size() - offset) return false;
  memcpy(out, rg_app_region + offset, len);
  return true;
}
