// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "rg_broadcasts.h"

#include <string.h>

#include "rg_board.h"
#include "rg_wire.h"
#include "generated/robogene_can_motor_control.h"

enum { SLOT_POSITION, SLOT_PID_OUTPUT, SLOT_STATUS, SLOT_CURRENT, SLOT_VELOCITY, SLOT_SUPPLY };

static bool due(rg_board_t *b, unsigned slot, uint32_t period_ms) {
  const uint32_t period_ticks = period_ms * 1000u / b->params.control_period_us;
  if (b->sent_once[slot] && b->tick - b->last_sent[slot] < period_ticks) return false;
  b->sent_once[slot] = true;
  b->last_sent[slot] = b->tick;
  return true;
}

static void send(rg_board_t *b, unsigned type, const uint8_t *data, uint8_t len) {
  rg_can_frame_t f;
  f.id = (uint16_t)ROBOGENE_CAN_ID(ROBOGENE_CAN_CLASS_PERIODIC_MOTOR_CONTROL, b->address, type);
  f.len = len;
  memset(f.data, 0, sizeof f.data);
  memcpy(f.data, data, len);
  (void)b->hal->can_send(b->hal->ctx, &f);
}

static int16_t milliamps(int32_t ma) { return (int16_t)(ma > 32767 ? 32767 : (ma < -32768 ? -32768 : ma)); }

static void status(rg_board_t *b) {
  uint8_t d[ROBOGENE_CAN_LEN_STATUS_BROADCAST] = {0};
  d[ROBOGENE_CAN_STATUS_BROADCAST_FAULTS0_BYTE] = b->axes[0].faults;
  d[ROBOGENE_CAN_STATUS_BROADCAST_MODE0_BYTE] = b->axes[0].mode;
  d[ROBOGENE_CAN_STATUS_BROADCAST_FAULTS1_BYTE] = b->axes[1].faults;
  d[ROBOGENE_CAN_STATUS_BROADCAST_MODE1_BYTE] = b->axes[1].mode;
  d[ROBOGENE_CAN_STATUS_BROADCAST_BOARD_FLAGS_BYTE] = b->board_flags;
  if (b->hal->can_errors) {
    b->hal->can_errors(b->hal->ctx, &d[ROBOGENE_CAN_STATUS_BROADCAST_TX_ERRORS_BYTE],
                       &d[ROBOGENE_CAN_STATUS_BROADCAST_RX_ERRORS_BYTE], &d[ROBOGENE_CAN_STATUS_BROADCAST_CAN_STATUS_BYTE]);
  }
  // A change of mode, fault or state is sent at once; the error counters ride along, as they
  // move too often to trigger a frame each.
  const bool changed = memcmp(d, b->last_status, ROBOGENE_CAN_STATUS_BROADCAST_TX_ERRORS_BYTE) != 0;
  if (changed || !b->sent_once[SLOT_STATUS]) {
    b->sent_once[SLOT_STATUS] = true;
    b->last_sent[SLOT_STATUS] = b->tick;
  } else if (!due(b, SLOT_STATUS, ROBOGENE_CAN_PERIOD_MS_STATUS)) {
    return;
  }
  memcpy(b->last_status, d, sizeof d);
  send(b, ROBOGENE_CAN_BCAST_STATUS, d, sizeof d);
}

void rg_send_broadcasts(rg_board_t *b) {
  const uint32_t policy = b->policy;
  if ((policy & ROBOGENE_CAN_BROADCAST_MASK_POSITION) && due(b, SLOT_POSITION, ROBOGENE_CAN_PERIOD_MS_POSITION)) {
    uint8_t d[ROBOGENE_CAN_LEN_POSITION_BROADCAST];
    rg_put_i32(d + ROBOGENE_CAN_POSITION_BROADCAST_POSITION0_BYTE, b->axes[0].measured);
    rg_put_i32(d + ROBOGENE_CAN_POSITION_BROADCAST_POSITION1_BYTE, b->axes[1].measured);
    send(b, ROBOGENE_CAN_BCAST_POSITION, d, sizeof d);
  }
  if ((policy & ROBOGENE_CAN_BROADCAST_MASK_PID_OUTPUT) && due(b, SLOT_PID_OUTPUT, ROBOGENE_CAN_PERIOD_MS_PID_OUTPUT)) {
    uint8_t d[ROBOGENE_CAN_LEN_PID_OUTPUT_BROADCAST];
    rg_put_i16(d + ROBOGENE_CAN_PID_OUTPUT_BROADCAST_OUTPUT0_BYTE, b->axes[0].output);
    rg_put_i16(d + ROBOGENE_CAN_PID_OUTPUT_BROADCAST_OUTPUT1_BYTE, b->axes[1].output);
    send(b, ROBOGENE_CAN_BCAST_PID_OUTPUT, d, sizeof d);
  }
  if (policy & ROBOGENE_CAN_BROADCAST_MASK_STATUS) status(b);
  if ((policy & ROBOGENE_CAN_BROADCAST_MASK_CURRENT) && due(b, SLOT_CURRENT, ROBOGENE_CAN_PERIOD_MS_CURRENT)) {
    uint8_t d[ROBOGENE_CAN_LEN_CURRENT_BROADCAST];
    rg_put_i16(d + ROBOGENE_CAN_CURRENT_BROADCAST_CURRENT0_BYTE, milliamps(b->motors[0].last_current_ma));
    rg_put_i16(d + ROBOGENE_CAN_CURRENT_BROADCAST_CURRENT1_BYTE, milliamps(b->motors[1].last_current_ma));
    send(b, ROBOGENE_CAN_BCAST_CURRENT, d, sizeof d);
  }
  if ((policy & ROBOGENE_CAN_BROADCAST_MASK_VELOCITY) && due(b, SLOT_VELOCITY, ROBOGENE_CAN_PERIOD_MS_VELOCITY)) {
    uint8_t d[ROBOGENE_CAN_LEN_VELOCITY_BROADCAST];
    rg_put_i16(d + ROBOGENE_CAN_VELOCITY_BROADCAST_SPEED0_BYTE, rg_scaled_i16(b->axes[0].speed, 10.0f));
    rg_put_i16(d + ROBOGENE_CAN_VELOCITY_BROADCAST_ACCELERATION0_BYTE, rg_scaled_i16(b->axes[0].accel, 1000.0f));
    rg_put_i16(d + ROBOGENE_CAN_VELOCITY_BROADCAST_SPEED1_BYTE, rg_scaled_i16(b->axes[1].speed, 10.0f));
    rg_put_i16(d + ROBOGENE_CAN_VELOCITY_BROADCAST_ACCELERATION1_BYTE, rg_scaled_i16(b->axes[1].accel, 1000.0f));
    send(b, ROBOGENE_CAN_BCAST_VELOCITY, d, sizeof d);
  }
  if ((policy & ROBOGENE_CAN_BROADCAST_MASK_SUPPLY) && due(b, SLOT_SUPPLY, ROBOGENE_CAN_PERIOD_MS_SUPPLY)) {
    uint8_t d[ROBOGENE_CAN_LEN_SUPPLY_BROADCAST];
    const uint32_t mv = b->hal->supply_mv(b->hal->ctx);
    rg_put_u16(d + ROBOGENE_CAN_SUPPLY_BROADCAST_VOLTAGE_BYTE, (uint16_t)(mv > 65535u ? 65535u : mv));
    send(b, ROBOGENE_CAN_BCAST_SUPPLY, d, sizeof d);
  }
}
