// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// The motor board's firmware: the control core (../core) on this board's hardware. One image per
// board of the head (ROBOGENE_BOARD_ADDRESS picks its entry of the generated board table); the CAN
// address set_board_id stores in flash replaces the table's, and each axis's joint-encoder zero
// (set_joint_encoder_zero) is read from the same flash page. The main loop polls: CAN frames go to
// the core as they come, and every 1 ms (SysTick) the core runs one control period, after which
// the watchdog is refreshed.
#include <stdbool.h>

#include "board_pins.h"
#include "clock.h"
#include "fdcan.h"
#include "gpio.h"
#include "handoff.h"
#include "joint_encoders.h"
#include "motor_io.h"
#include "rg_board.h"
#include "rg_board_config.h"
#include "generated/robogene_can_motor_control.h"
#include "settings.h"
#include "generated/stm32g431_regs.h"
#include "watchdog.h"

#ifndef ROBOGENE_BOARD_ADDRESS
#error "build one image per board: -DROBOGENE_BOARD_ADDRESS=<the board's address in the head table>"
#endif

static rg_board_t board;
// What the settings page holds, and whether set_board_id or set_joint_encoder_zero changed it since: it is
// written when the axes rest (erasing the page stalls the CPU for about 22 ms).
static settings_t settings;
static bool settings_changed = false;

static uint16_t hal_encoder(void *ctx, unsigned m) {
  (void)ctx;
  return motor_io_encoder(m);
}
static int32_t hal_current(void *ctx, unsigned m) {
  (void)ctx;
  return motor_io_current_ma(m);
}
static uint32_t hal_supply(void *ctx) {
  (void)ctx;
  return motor_io_supply_mv();
}
static bool hal_fault(void *ctx) {
  (void)ctx;
  return motor_io_bridge_fault();
}
static void hal_pwm(void *ctx, unsigned m, int32_t duty, bool enabled) {
  (void)ctx;
  motor_io_set_pwm(m, duty, enabled);
}
static void hal_brake(void *ctx, unsigned m, bool released) {
  (void)ctx;
  motor_io_set_brake(m, released);
}
static bool hal_send(void *ctx, const rg_can_frame_t *f) {
  (void)ctx;
  return fdcan_send(f);
}
static void hal_save_address(void *ctx, uint8_t address) {
  (void)ctx;
  settings.has_address = true;
  settings.address = address;
  settings_changed = true;
}
static uint16_t hal_joint_encoder_frame(void *ctx, unsigned axis) {
  (void)ctx;
  return joint_encoders_frame(axis);
}
static void hal_save_joint_zero(void *ctx, unsigned axis, uint16_t zero) {
  (void)ctx;
  settings.has_joint_zero[axis & 1u] = true;
  settings.joint_zero[axis & 1u] = zero;
  settings_changed = true;
}

static void hal_can_errors(void *ctx, uint8_t *tx, uint8_t *rx, uint8_t *status) {
  (void)ctx;
  fdcan_errors(tx, rx, status);
}

// enter_bootloader: the core has switched the bridges off; let the reply-less command's frame
// go, then reset with the request to stay in the bootloader.
static void hal_enter_bootloader(void *ctx) {
  (void)ctx;
  fdcan_flush(1000u);
  handoff_reset_into_bootloader();
}

static const rg_hal_t hal = {0,        hal_encoder,      hal_current,    hal_supply,           hal_fault,
                             hal_pwm,  hal_send,         hal_save_address, hal_can_errors,     hal_enter_bootloader,
                             hal_brake, hal_joint_encoder_frame, hal_save_joint_zero};

static bool axes_at_rest(void) {
  for (unsigned i = 0; i < 2u; ++i) {
    const uint8_t m = board.axes[i].mode;
    if (m == ROBOGENE_CAN_CONTROL_MODE_POSITION || m == ROBOGENE_CAN_CONTROL_MODE_VELOCITY ||
        m == ROBOGENE_CAN_CONTROL_MODE_CALIBRATION) {
      return false;
    }
  }
  return true;
}

int main(void) {
  clock_init();
  RCC_AHB2ENR |= RCC_AHB2ENR_GPIOAEN_Msk | RCC_AHB2ENR_GPIOBEN_Msk;
  gpio_mode(GPIOB_BASE, PIN_BOOT0, GPIO_OUTPUT, GPIO_NO_PULL);  // the LED, once BOOT0 was sampled
  rg_board_params_t params;
  if (!rg_board_params_for_address(ROBOGENE_BOARD_ADDRESS, &params)) {
    for (;;) {  // built for a board the head does not have: blink fast, drive nothing
      gpio_write(GPIOB_BASE, PIN_BOOT0, 1);
      clock_delay_us(100000u);
      gpio_write(GPIOB_BASE, PIN_BOOT0, 0);
      clock_delay_us(100000u);
    }
  }
  settings_load(&settings);
  if (settings.has_address) params.address = settings.address;
  for (unsigned i = 0; i < 2u; ++i) {
    params.axes[i].joint_zero_stored = settings.has_joint_zero[i];
    params.axes[i].joint_zero = settings.joint_zero[i];
  }
  // Only a braked axis's pin becomes an output; the others stay as reset left them, held low by their pull-downs.
  unsigned brakes = 0u;
  for (unsigned i = 0; i < 2u; ++i) {
    if (params.coupling == RG_COUPLING_NONE && params.axes[i].present && params.axes[i].has_brake) brakes |= 1u << i;
  }
  motor_io_init(params.pwm_full_scale, brakes);
  // SPI1 and the chip selects also on a board whose axes have no joint encoder: the selects then stay high.
  joint_encoders_init();
  fdcan_init(params.address);
  rg_board_init(&board, &params, &hal);
  watchdog_start();
  uint8_t filtered_address = params.address;

  STK_LOAD = SYSCLK_HZ / 1000000u * params.control_period_us - 1u;
  STK_VAL = 0u;
  STK_CTRL = STK_CTRL_CLKSOURCE_Msk | STK_CTRL_ENABLE_Msk;
  uint32_t led = 0;
  bool late = false;  // a period ended while the last tick ran: run the next one at once
  for (;;) {
    rg_can_frame_t frame;
    while (fdcan_receive(&frame)) rg_board_receive(&board, &frame);
    // COUNTFLAG clears when read, so each period is seen once.
    if (!late && !(STK_CTRL & STK_CTRL_COUNTFLAG_Msk)) continue;
    late = false;
    rg_board_tick(&board);
    if (STK_CTRL & STK_CTRL_COUNTFLAG_Msk) {  // the next period began before this tick was done
      rg_board_note_overrun(&board);
      late = true;
    }
    (void)fdcan_recover();
    if (board.address != filtered_address) {  // set_board_id: take the new address's commands
      filtered_address = board.address;
      fdcan_init(filtered_address);
    }
    if (settings_changed && axes_at_rest()) {
      (void)settings_store(&settings);
      settings_changed = false;
    }
    watchdog_refresh();
    gpio_write(GPIOB_BASE, PIN_BOOT0, (++led / 500u) & 1u);  // 1 Hz blink: the loop is alive
  }
}
