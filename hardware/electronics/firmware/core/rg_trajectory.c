// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "rg_trajectory.h"

#include <math.h>

#include "rg_wire.h"

void rg_trajectory_hold(rg_trajectory_t *t, float position) {
  t->ref = t->target = position;
  t->ref_velocity = 0.0f;
  t->done = true;
}

static void approach(rg_trajectory_t *t, float wanted, float dt) {
  const float acc = fmaxf(t->acceleration, 1.0f);
  t->ref_velocity += rg_clampf(wanted - t->ref_velocity, -acc * dt, acc * dt);
}

void rg_trajectory_position_step(rg_trajectory_t *t, float dt) {
  const float acc = fmaxf(t->acceleration, 1.0f);
  const float distance = t->target - t->ref;
  if (fabsf(distance) < 0.5f && fabsf(t->ref_velocity) <= acc * dt) {
    t->ref = t->target;
    t->ref_velocity = 0.0f;
    t->done = true;
    return;
  }
  const float braking = sqrtf(2.0f * acc * fabsf(distance));
  approach(t, copysignf(fminf(t->move_speed, braking), distance), dt);
  const float step = t->ref_velocity * dt;
  const bool overshoots = fabsf(step) >= fabsf(distance) && (step > 0.0f) == (distance > 0.0f);
  t->ref = overshoots ? t->target : t->ref + step;
}

void rg_trajectory_velocity_step(rg_trajectory_t *t, float speed, float min, float max, float dt) {
  approach(t, speed, dt);
  t->ref += t->ref_velocity * dt;
  if (t->ref < min || t->ref > max) {
    t->ref = rg_clampf(t->ref, min, max);
    t->ref_velocity = 0.0f;
  }
  t->target = t->ref;
}
