// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// The motor board's bootloader, in the first 16 KiB of flash where the part boots. At reset it
// starts the application at once, before touching any peripheral, when the application region
// holds an image for this board that checks (header and CRC-32, core/rg_image.h) and the
// application did not ask to stay here. Otherwise it stays: the CPU on the 16 MHz HSI, FDCAN1 on
// the 8 MHz crystal as in the application, the status LED lit, and the bootloader's protocol
// (core/rg_boot.c) at the board's CAN address. One image per board of the head, like the
// application's: the image it accepts must have been built for the same board and revision.
#include <stdbool.h>

#include "app_flash.h"
#include "board_pins.h"
#include "fdcan.h"
#include "gpio.h"
#include "handoff.h"
#include "rg_boot.h"
#include "rg_revision.h"
#include "generated/robogene_can_motor_control.h"
#include "settings.h"
#include "generated/stm32g431_regs.h"

#ifndef ROBOGENE_BOARD_ADDRESS
#error "build one bootloader per board: -DROBOGENE_BOARD_ADDRESS=<the board's address in the head table>"
#endif

static bool send(void *ctx, const rg_can_frame_t *f) {
  (void)ctx;
  return fdcan_send(f);
}

// bootloader_start's reply is queued: let it go, then reset; the reset path starts the image.
static void start_application(void *ctx) {
  (void)ctx;
  (void)fdcan_flush(1000u);
  handoff_reset();
}

static const rg_boot_hal_t hal = {
    .ctx = 0,
    .region_size = 0u,  // set in main: the linker's symbol is not a constant expression
    .page_size = APP_FLASH_PAGE_BYTES,
    .erase_page = app_flash_erase_page,
    .program = app_flash_program,
    .read = app_flash_read,
    .can_send = send,
    .start_application = start_application,
};

// Into the application with the part as reset left it: its vector table, its stack, its reset handler.
__attribute__((noreturn)) static void jump_to_application(void) {
  const uint32_t *vectors = (const uint32_t *)(uintptr_t)app_flash_base();
  SCB_VTOR = app_flash_base();
  __asm__ volatile("msr msp, %0\n\tbx %1" : : "r"(vectors[0]), "r"(vectors[1]) : "memory");
  __builtin_unreachable();
}

int main(void) {
  static rg_boot_hal_t board_hal;
  static rg_boot_t boot;
  board_hal = hal;
  board_hal.region_size = app_flash_size();
  const rg_image_target_t target = {ROBOGENE_CAN_BOARD_TYPE_ROBOGENE_MOTOR_BOARD, ROBOGENE_BOARD_ADDRESS,
                                    (uint8_t)ROBOGENE_BOARD_REVISION};
  const bool asked_to_stay = handoff_take_bootloader_request();
  if (!asked_to_stay && rg_boot_image_valid(&board_hal, &target)) jump_to_application();

  RCC_CR |= RCC_CR_HSEON_Msk;  // FDCAN1's kernel clock; the CPU stays on the HSI
  while (!(RCC_CR & RCC_CR_HSERDY_Msk)) {
  }
  RCC_AHB2ENR |= RCC_AHB2ENR_GPIOAEN_Msk | RCC_AHB2ENR_GPIOBEN_Msk;
  // The LED is on PB8 since board revision D (PA4, its rev C pin, now releases brake 2 when high). The
  // brake pins stay as reset left them: their pull-downs hold the brakes while the bootloader runs.
  gpio_mode(GPIOB_BASE, PIN_BOOT0, GPIO_OUTPUT, GPIO_NO_PULL);
  gpio_write(GPIOB_BASE, PIN_BOOT0, 1);  // steady: the bootloader (the application blinks)
  const uint8_t address = settings_address(ROBOGENE_BOARD_ADDRESS);
  fdcan_init(address);
  rg_boot_init(&boot, address, &target, &board_hal);
  for (;;) {
    rg_can_frame_t frame;
    while (fdcan_receive(&frame)) rg_boot_receive(&boot, &frame);
    (void)fdcan_recover();
  }
}
