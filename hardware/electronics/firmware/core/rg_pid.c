// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "rg_pid.h"

#include <math.h>

#include "rg_wire.h"

int16_t rg_pid_step(const rg_pid_gains_t *g, rg_pid_state_t *s, float error, int16_t limit) {
  const float scale = ldexpf(1.0f, g->shift);
  const float integral_cap = (float)g->integral_limit * scale;
  s->integral = rg_clampf(s->integral + (float)g->ki * error, -integral_cap, integral_cap);
  const float derivative = error - s->last_error;
  s->last_error = error;
  const float out = ((float)g->kp * error + s->integral + (float)g->kd * derivative) / scale + (float)g->offset;
  const float cap = (float)(limit < 0 ? 0 : limit);
  return (int16_t)lroundf(rg_clampf(out, -cap, cap));
}
