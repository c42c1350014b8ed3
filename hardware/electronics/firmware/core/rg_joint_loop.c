// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "rg_joint_loop.h"

#include <math.h>

#include "rg_board.h"
#include "rg_joint_homing.h"
#include "rg_wire.h"
#include "generated/robogene_can_motor_control.h"

static bool closes(const rg_board_t *b, unsigned axis) {
  const rg_axis_params_t *p = &b->params.axes[axis];
  return b->axes[axis].present && p->joint_encoder_bits > 0u && p->joint_correction_limit > 0 && b->axes[axis].joint_homed;
}

bool rg_joint_loop_configured(const rg_board_t *b, unsigned axis) {
  // On the eye board version and vergence both come from both pans' sensors: both closed, or neither.
  if (b->params.coupling != RG_COUPLING_NONE) return closes(b, 0) && closes(b, 1);
  return closes(b, axis);
}

void rg_joint_loop_measure(rg_board_t *b) {
  for (unsigned i = 0; i < 2u; ++i) {
    rg_axis_t *a = &b->axes[i];
    a->joint_loop = false;
    if (!rg_joint_loop_configured(b, i)) continue;
    float joint = 0.0f;
    if (rg_joint_homing_position(b, i, &joint)) {
      a->joint_loop = true;
      a->joint_position = joint;
      a->measured = (int32_t)lroundf(joint);
    } else {
      a->measured = a->motor_position - (int32_t)lroundf(a->joint_correction);
    }
  }
}

// One count of the joint encoder, in the axis's counts: the dead band.
static float encoder_count(const rg_board_t *b, unsigned axis) {
  const rg_axis_params_t *p = &b->params.axes[axis];
  return p->counts_per_degree * 360.0f / (float)(1u << p->joint_encoder_bits);
}

void rg_joint_loop_step(rg_board_t *b, unsigned axis, float dt) {
  rg_axis_t *a = &b->axes[axis];
  if (!a->joint_loop) return;  // not closed on the joint, or its sensor failed: c holds
  const float error = a->traj.ref - a->joint_position;
  a->joint_error = error;
  if (fabsf(error) <= encoder_count(b, axis)) return;
  // What the motor loop has yet to take up is its own to correct, not the joint loop's.
  const float motor_error = a->traj.ref + a->joint_correction - (float)a->motor_position;
  const float most = RG_JOINT_LOOP_MAX_RATE_DEG_S * b->params.axes[axis].counts_per_degree * dt;
  a->joint_correction += rg_clampf(RG_JOINT_LOOP_GAIN_PER_S * (error - motor_error) * dt, -most, most);
}

void rg_joint_loop_follow(rg_board_t *b, unsigned axis) {
  rg_axis_t *a = &b->axes[axis];
  a->joint_error = 0.0f;
  if (!rg_joint_loop_configured(b, axis)) {
    a->joint_correction = 0.0f;
  } else if (a->joint_loop) {
    a->joint_correction = (float)(a->motor_position - a->measured);
  }  // else the sensor failed: the correction keeps what the joint last needed
}

static bool over_limit(const rg_board_t *b, unsigned axis) {
  return fabsf(b->axes[axis].joint_correction) > (float)b->params.axes[axis].joint_correction_limit;
}

uint8_t rg_joint_loop_faults(const rg_board_t *b, unsigned axis) {
  if (!rg_joint_loop_configured(b, axis)) return 0u;
  // On the eye board both motors serve both axes: either axis's mismatch stops both.
  const bool over = b->params.coupling != RG_COUPLING_NONE ? (over_limit(b, 0) || over_limit(b, 1)) : over_limit(b, axis);
  return over ? (uint8_t)ROBOGENE_CAN_AXIS_FAULTS_JOINT_ENCODER_MISMATCH : 0u;
}
