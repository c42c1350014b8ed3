// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// Reset and the vector table: the Cortex-M4's 16 system entries and the STM32G431's 102 interrupt
// lines (RM0440), every one a trap but reset. The firmware polls its peripherals from the main loop,
// so an interrupt that fires is a fault, and the watchdog resets the board out of the trap.
#include <stdint.h>

#include "board_pins.h"
#include "generated/stm32g431_regs.h"

extern uint32_t _stack_top, _data_load, _data_start, _data_end, _bss_start, _bss_end;
int main(void);
void rg_reset_handler(void);

static void (*const vectors[16 + 102])(void);

static void trap(void) {
  // Apply both holding brakes at once rather than after the watchdog's reset (up to 50 ms): their gates
  // low. Harmless where they are not outputs (the bootloader, unbraked axes).
  RG_REG32(GPIOB_BASE + GPIOA_BSRR_OFFSET) = 1u << (16u + PIN_M1_BRAKE);
  RG_REG32(GPIOA_BASE + GPIOA_BSRR_OFFSET) = 1u << (16u + PIN_M2_BRAKE);
  for (;;) {
  }
}

void rg_reset_handler(void) {
  const uint32_t *from = &_data_load;
  for (uint32_t *to = &_data_start; to < &_data_end;) *to++ = *from++;
  for (uint32_t *to = &_bss_start; to < &_bss_end;) *to++ = 0u;
  // Exceptions through this image's own table: the application's is not where the part boots.
  SCB_VTOR = (uint32_t)(uintptr_t)&vectors;
  SCB_CPACR |= 0xFu << 20;  // CP10 and CP11 (the FPU): full access, before any float instruction
  __asm__ volatile("dsb\n isb" ::: "memory");
  (void)main();
  trap();
}

// 16 system entries + 102 interrupts = 118: the stack top, reset, then 116 traps.
#define T4 trap, trap, trap, trap,
#define T16 T4 T4 T4 T4
__attribute__((section(".vectors"), used)) static void (*const vectors[16 + 102])(void) = {
    (void (*)(void))(uintptr_t)&_stack_top, rg_reset_handler, T16 T16 T16 T16 T16 T16 T16 T4};
