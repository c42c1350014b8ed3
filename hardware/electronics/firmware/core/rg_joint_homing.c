// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "rg_joint_homing.h"

#include <math.h>

#include "rg_board.h"
#include "generated/robogene_can_motor_control.h"

// Only on an uncoupled board: there one encoder gives one axis. (On the eye board version and vergence
// would each need both pans' sensors; codegen gives coupled axes no encoder bits.)
static bool has_encoder(const rg_board_t *b, unsigned axis) {
  return b->params.coupling == RG_COUPLING_NONE && b->axes[axis].present && b->params.axes[axis].joint_encoder_bits > 0u;
}

static void read_frame(rg_board_t *b, unsigned axis) {
  const uint16_t frame = b->hal->joint_encoder_frame ? b->hal->joint_encoder_frame(b->hal->ctx, axis) : 0u;
  (void)rg_joint_encoder_update(&b->axes[axis].joint_encoder, frame);
}

// The joint's angle (deg) from a raw reading: wrapped into the turn centred on the joint's range.
static float joint_degrees(const rg_axis_params_t *p, uint16_t raw) {
  const uint32_t modulus = 1u << p->joint_encoder_bits;
  const uint32_t steps = ((uint32_t)raw + modulus - (p->joint_zero % modulus)) % modulus;
  const float degrees = (float)steps * 360.0f / (float)modulus;
  const float middle = 0.5f * (float)(p->min_position + p->max_position) / p->counts_per_degree;
  float delta = fmodf(degrees - middle, 360.0f);
  if (delta < -180.0f) delta += 360.0f;
  if (delta >= 180.0f) delta -= 360.0f;
  return middle + delta;
}

static void try_home(rg_board_t *b, unsigned axis) {
  rg_axis_t *a = &b->axes[axis];
  const rg_axis_params_t *p = &b->params.axes[axis];
  if (a->joint_homed || a->joint_encoder.state != RG_JOINT_ENCODER_OK || !p->joint_zero_stored ||
      p->counts_per_degree <= 0.0f) {
    return;
  }
  const float degrees = joint_degrees(p, a->joint_encoder.angle);
  const float counts = degrees * p->counts_per_degree;
  const float tolerance = RG_JOINT_HOMING_RANGE_TOLERANCE_DEG * p->counts_per_degree;
  a->joint_out_of_range = counts < (float)p->min_position - tolerance || counts > (float)p->max_position + tolerance;
  if (a->joint_out_of_range) return;
  rg_board_shift_position(b, axis, (int32_t)lroundf(counts));
  a->joint_homed = true;
  rg_board_set_mode(b, axis, ROBOGENE_CAN_CONTROL_MODE_IDLE);
}

static void unhome(rg_board_t *b, unsigned axis) {
  rg_axis_t *a = &b->axes[axis];
  rg_board_set_mode(b, axis, ROBOGENE_CAN_CONTROL_MODE_IDLE);
  a->mode = ROBOGENE_CAN_CONTROL_MODE_NOT_CONFIGURED;
  a->joint_homed = false;
  a->joint_out_of_range = false;
}

void rg_joint_homing_init(rg_board_t *b) {
  for (unsigned i = 0; i < 2u; ++i) {
    if (!has_encoder(b, i)) continue;
    rg_joint_encoder_start(&b->axes[i].joint_encoder);
    unhome(b, i);
    for (unsigned k = 0; k < RG_JOINT_ENCODER_STARTUP_FRAMES; ++k) read_frame(b, i);
    try_home(b, i);
  }
}

void rg_joint_homing_tick(rg_board_t *b) {
  for (unsigned i = 0; i < 2u; ++i) {
    if (!has_encoder(b, i)) continue;
    read_frame(b, i);
    try_home(b, i);
  }
}

bool rg_joint_homing_blocks(const rg_board_t *b, unsigned axis) {
  return has_encoder(b, axis) && !b->axes[axis].joint_homed;
}

uint8_t rg_joint_homing_faults(const rg_board_t *b, unsigned axis) {
  if (!has_encoder(b, axis)) return 0u;
  const rg_axis_t *a = &b->axes[axis];
  const bool bad = a->joint_encoder.state == RG_JOINT_ENCODER_ABSENT || a->joint_encoder.state == RG_JOINT_ENCODER_FAILED ||
                   a->joint_out_of_range;
  return bad ? (uint8_t)ROBOGENE_CAN_AXIS_FAULTS_ABSOLUTE_ENCODER_ERROR : 0u;
}

static bool running(uint8_t mode) {
  return mode == ROBOGENE_CAN_CONTROL_MODE_POSITION || mode == ROBOGENE_CAN_CONTROL_MODE_VELOCITY ||
         mode == ROBOGENE_CAN_CONTROL_MODE_CALIBRATION;
}

bool rg_joint_homing_set_zero(rg_board_t *b, unsigned axis, uint16_t zero) {
  const uint8_t mode = b->axes[axis].mode;
  if (!has_encoder(b, axis) || running(mode) || mode == ROBOGENE_CAN_CONTROL_MODE_HARDWARE_FAULT) return false;
  rg_axis_params_t *p = &b->params.axes[axis];
  if ((uint32_t)zero >= (1u << p->joint_encoder_bits)) return false;
  p->joint_zero = zero;
  p->joint_zero_stored = true;
  if (b->hal->save_joint_zero) b->hal->save_joint_zero(b->hal->ctx, axis, zero);
  unhome(b, axis);
  try_home(b, axis);
  return true;
}

// The states get_joint_encoder reports are the protocol's JointEncoderState.
_Static_assert(RG_JOINT_ENCODER_STARTING == ROBOGENE_CAN_JOINT_ENCODER_STATE_STARTING, "JointEncoderState");
_Static_assert(RG_JOINT_ENCODER_OK == ROBOGENE_CAN_JOINT_ENCODER_STATE_OK, "JointEncoderState");
_Static_assert(RG_JOINT_ENCODER_ABSENT == ROBOGENE_CAN_JOINT_ENCODER_STATE_ABSENT, "JointEncoderState");
_Static_assert(RG_JOINT_ENCODER_FAILED == ROBOGENE_CAN_JOINT_ENCODER_STATE_FAILED, "JointEncoderState");
