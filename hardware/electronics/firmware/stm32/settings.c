// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "settings.h"

#include "generated/stm32g431_regs.h"

extern const uint32_t rg_settings_page[];

// Record slots (double words) in the page.
#define SLOT_ADDRESS 0u
#define SLOT_JOINT_ZERO0 1u
#define ADDRESS_MAGIC 0x52474144u     // "RGAD"
#define JOINT_ZERO_MAGIC0 0x52475A30u // "RGZ0", "RGZ1" for axis 1
#define FLASH_KEY1 0x45670123u
#define FLASH_KEY2 0xCDEF89ABu
#define FLASH_ERRORS (FLASH_SR_PROGERR_Msk | FLASH_SR_WRPERR_Msk | FLASH_SR_PGAERR_Msk | FLASH_SR_SIZERR_Msk | FLASH_SR_PGSERR_Msk)

void settings_load(settings_t *out) {
  out->has_address = false;
  out->address = 0;
  const uint32_t magic = rg_settings_page[2u * SLOT_ADDRESS], value = rg_settings_page[2u * SLOT_ADDRESS + 1u];
  if (magic == ADDRESS_MAGIC && (value & 0xFFu) == (~(value >> 8) & 0xFFu)) {
    const uint8_t address = (uint8_t)(value & 0xFFu);
    out->has_address = address >= 1u && address <= 14u;
    out->address = out->has_address ? address : 0u;
  }
  for (unsigned i = 0; i < 2u; ++i) {
    const uint32_t zm = rg_settings_page[2u * (SLOT_JOINT_ZERO0 + i)], zv = rg_settings_page[2u * (SLOT_JOINT_ZERO0 + i) + 1u];
    out->has_joint_zero[i] = zm == JOINT_ZERO_MAGIC0 + i && (zv & 0xFFFFu) == (~(zv >> 16) & 0xFFFFu);
    out->joint_zero[i] = out->has_joint_zero[i] ? (uint16_t)(zv & 0xFFFFu) : 0u;
  }
}

uint8_t settings_address(uint8_t fallback) {
  settings_t s;
  settings_load(&s);
  return s.has_address ? s.address : fallback;
}

static bool wait_idle(void) {
  while (FLASH_SR & FLASH_SR_BSY_Msk) {
  }
  const bool ok = (FLASH_SR & FLASH_ERRORS) == 0u;
  FLASH_SR = FLASH_ERRORS | FLASH_SR_EOP_Msk;  // write 1 to clear
  return ok;
}

// One double word (the G4 programs 64 bits at a time) into an erased slot.
static bool program(unsigned slot, uint32_t magic, uint32_t value) {
  volatile uint32_t *dst = (volatile uint32_t *)(uintptr_t)rg_settings_page;
  dst[2u * slot] = magic;
  dst[2u * slot + 1u] = value;
  return wait_idle();
}

bool settings_store(const settings_t *s) {
  const uint32_t page = ((uint32_t)(uintptr_t)rg_settings_page - 0x08000000u) / 2048u;
  FLASH_KEYR = FLASH_KEY1;
  FLASH_KEYR = FLASH_KEY2;
  bool ok = wait_idle();
  FLASH_CR = FLASH_CR_PER_Msk | (page << FLASH_CR_PNB_Pos);
  FLASH_CR |= FLASH_CR_STRT_Msk;
  ok = wait_idle() && ok;
  FLASH_CR = FLASH_CR_PG_Msk;
  if (s->has_address) {
    ok = program(SLOT_ADDRESS, ADDRESS_MAGIC, (uint32_t)s->address | ((uint32_t)(uint8_t)~s->address << 8)) && ok;
  }
  for (unsigned i = 0; i < 2u; ++i) {
    if (!s->has_joint_zero[i]) continue;
    const uint16_t z = s->joint_zero[i];
    ok = program(SLOT_JOINT_ZERO0 + i, JOINT_ZERO_MAGIC0 + i, (uint32_t)z | ((uint32_t)(uint16_t)~z << 16)) && ok;
  }
  FLASH_CR = FLASH_CR_LOCK_Msk;
  return ok;
}
