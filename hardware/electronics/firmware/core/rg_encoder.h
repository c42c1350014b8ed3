// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// A motor's position from its 16-bit quadrature counter: the counter wraps every 65536 counts
// (under a second at full speed), so each tick adds the signed difference to a 32-bit count. This
// holds while the motor turns less than 32768 counts per tick (about 16 000 rpm at 512 lines).
#ifndef RG_ENCODER_H
#define RG_ENCODER_H

#include <stdint.h>

typedef struct {
  uint16_t last_raw;
  int32_t counts;
} rg_encoder_t;

static inline void rg_encoder_start(rg_encoder_t *e, uint16_t raw) {
  e->last_raw = raw;
  e->counts = 0;
}

static inline int32_t rg_encoder_update(rg_encoder_t *e, uint16_t raw) {
  const int16_t delta = (int16_t)(uint16_t)(raw - e->last_raw);
  e->last_raw = raw;
  e->counts = (int32_t)((uint32_t)e->counts + (uint32_t)(int32_t)delta);
  return e->counts;
}

#endif  // RG_ENCODER_H
