// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// The reference an axis's position loop follows, advanced once per control period: in position
// mode a trapezoidal profile to the target (cruise at the move's speed, brake in time to stop on
// it), in velocity mode the commanded speed reached with the set acceleration and held within the
// axis's limits. Counts and counts/s, as on the wire.
#ifndef RG_TRAJECTORY_H
#define RG_TRAJECTORY_H

#include <stdbool.h>

typedef struct {
  float ref, ref_velocity;  // where the axis should be now, and how fast that moves
  float target, move_speed;  // position moves
  float acceleration;
  bool done;                 // the position reference has reached the target
} rg_trajectory_t;

// Holds the reference where the axis is.
void rg_trajectory_hold(rg_trajectory_t *t, float position);
// One period of a position move towards t->target.
void rg_trajectory_position_step(rg_trajectory_t *t, float dt);
// One period towards `speed`, the reference kept within [min, max].
void rg_trajectory_velocity_step(rg_trajectory_t *t, float speed, float min, float max, float dt);

#endif  // RG_TRAJECTORY_H
