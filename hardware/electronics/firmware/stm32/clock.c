// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "clock.h"

#include "generated/stm32g431_regs.h"

void clock_init(void) {
  RCC_CR |= RCC_CR_HSEON_Msk;
  while (!(RCC_CR & RCC_CR_HSERDY_Msk)) {
  }
  // 150 MHz in range 1 normal mode needs 4 wait states (RM0440 table 9); set them before switching.
  FLASH_ACR = (FLASH_ACR & ~FLASH_ACR_LATENCY_Msk) | (4u << FLASH_ACR_LATENCY_Pos) | FLASH_ACR_PRFTEN_Msk |
              FLASH_ACR_ICEN_Msk | FLASH_ACR_DCEN_Msk;
  while ((FLASH_ACR & FLASH_ACR_LATENCY_Msk) != (4u << FLASH_ACR_LATENCY_Pos)) {
  }
  // HSE 8 MHz / M 2 = 4 MHz, x N 75 = 300 MHz VCO, / R 2 = 150 MHz.
  RCC_PLLCFGR = (3u << RCC_PLLCFGR_PLLSRC_Pos) | ((2u - 1u) << RCC_PLLCFGR_PLLM_Pos) | (75u << RCC_PLLCFGR_PLLN_Pos) |
                (0u << RCC_PLLCFGR_PLLR_Pos) | RCC_PLLCFGR_PLLREN_Msk;
  RCC_CR |= RCC_CR_PLLON_Msk;
  while (!(RCC_CR & RCC_CR_PLLRDY_Msk)) {
  }
  // AHB and both APBs undivided: timers and the ADC clock run at 150 MHz.
  RCC_CFGR = (RCC_CFGR & ~(RCC_CFGR_SW_Msk | RCC_CFGR_HPRE_Msk | RCC_CFGR_PPRE1_Msk | RCC_CFGR_PPRE2_Msk)) |
             (3u << RCC_CFGR_SW_Pos);
  while ((RCC_CFGR & RCC_CFGR_SWS_Msk) != (3u << RCC_CFGR_SWS_Pos)) {
  }
}

void clock_delay_us(uint32_t us) {
  // SysTick as a down-counter at the core clock, one microsecond at a time.
  STK_LOAD = SYSCLK_HZ / 1000000u - 1u;
  STK_VAL = 0u;
  STK_CTRL = STK_CTRL_CLKSOURCE_Msk | STK_CTRL_ENABLE_Msk;
  for (uint32_t i = 0; i < us; ++i) {
    while (!(STK_CTRL & STK_CTRL_COUNTFLAG_Msk)) {
    }
  }
  STK_CTRL = 0u;
}
