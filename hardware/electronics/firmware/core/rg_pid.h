// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// The position controller in the reference boards' units: output = (kp e + ki sum(e) + kd de)
// >> shift + offset, e in counts, output in PWM steps, the integral held within integral_limit
// (in output units) and the output within output_limit.
#ifndef RG_PID_H
#define RG_PID_H

#include <stdint.h>

typedef struct {
  int16_t kp, ki, kd;
  uint8_t shift;  // at most 15
  int16_t offset, output_limit, integral_limit;
} rg_pid_gains_t;

typedef struct {
  float integral, last_error;
} rg_pid_state_t;

static inline void rg_pid_reset(rg_pid_state_t *s) {
  s->integral = 0.0f;
  s->last_error = 0.0f;
}

// One step on `error` (counts); `limit` is the output limit in force (the gains' or lower).
int16_t rg_pid_step(const rg_pid_gains_t *g, rg_pid_state_t *s, float error, int16_t limit);

#endif  // RG_PID_H
