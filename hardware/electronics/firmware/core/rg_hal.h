// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// The hardware the control core needs, and nothing more. The board's firmware fills this table
// with register-level functions (stm32/), the simulator with a DC motor model
// (drivers/can/src/sim/host_hal.cpp). Functions are called from the control tick only, so an
// implementation needs no locking towards the core. `ctx` is passed back unchanged: the simulator
// runs several boards in one process, each with its own motors.
#ifndef RG_HAL_H
#define RG_HAL_H

#include <stdbool.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

// One classic CAN frame, 11-bit identifier.
typedef struct {
  uint16_t id;
  uint8_t len;
  uint8_t data[8];
} rg_can_frame_t;

typedef struct rg_hal {
  void *ctx;
  // The quadrature counter of motor 0 or 1 (x4 decoding), free-running and wrapping at 16 bits.
  uint16_t (*encoder_raw)(void *ctx, unsigned motor);
  // The motor current in mA, signed like the PWM that drives it.
  int32_t (*current_ma)(void *ctx, unsigned motor);
  // The motor supply in mV.
  uint32_t (*supply_mv)(void *ctx);
  // True while the H-bridges' shared fault output is asserted.
  bool (*bridge_fault)(void *ctx);
  // Drive motor 0 or 1 with `duty` PWM steps of the board's full scale (sign = direction);
  // enabled false puts both bridge outputs low (coast).
  void (*set_pwm)(void *ctx, unsigned motor, int32_t duty, bool enabled);
  // Queue a frame for sending; false when the transmit queue is full (the frame is dropped).
  bool (*can_send)(void *ctx, const rg_can_frame_t *frame);
  // Keep the board's CAN address across resets (flash on the board); may be NULL.
  void (*save_address)(void *ctx, uint8_t address);
  // The CAN controller's error counters and state (ROBOGENE_CAN_CAN_STATUS_* bits) for the status
  // broadcast; may be NULL (all zero).
  void (*can_errors)(void *ctx, uint8_t *tx_errors, uint8_t *rx_errors, uint8_t *status);
  // Restart into the bootloader and stay there (enter_bootloader), the bridges already off; may be
  // NULL (the command is then ignored). Called from rg_board_receive.
  void (*enter_bootloader)(void *ctx);
  // Release (true) or apply (false) the power-off holding brake of motor 0 or 1: the brake output's
  // gate (board revision D). Called only for motors whose axis has_brake; may be NULL (no brake outputs).
  void (*set_brake)(void *ctx, unsigned motor, bool released);
  // One 16-bit SPI frame from joint encoder 0 or 1, the one on the connector beside motor 0 or 1 (axis i's;
  // on the eye board the left and right pan's): what came back on its data line for the 0xFFFF (read angle)
  // it was sent. Called only where the axis table gives encoder bits; may be NULL (no SPI: it reads as missing).
  uint16_t (*joint_encoder_frame)(void *ctx, unsigned encoder);
  // Keep joint encoder 0's or 1's zero across resets (flash on the board); may be NULL.
  void (*save_joint_zero)(void *ctx, unsigned encoder, uint16_t zero);
} rg_hal_t;

#ifdef __cplusplus
}
#endif

#endif  // RG_HAL_H
