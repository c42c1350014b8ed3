// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "rg_joint_homing.h"

#include <math.h>

#include "rg_board.h"
#include "generated/robogene_can_motor_control.h"

// Encoder i is the one on the connector beside motor i: axis i's on an uncoupled board; on the eye board
// the left pan's (0) and the right pan's (1), from which version and vergence are derived together.
static bool has_encoder(const rg_board_t *b, unsigned axis) {
  return b->axes[axis].present && b->params.axes[axis].joint_encoder_bits > 0u;
}

static bool coupled(const rg_board_t *b) { return b->params.coupling != RG_COUPLING_NONE; }

static void read_frame(rg_board_t *b, unsigned axis) {
  const uint16_t frame = b->hal->joint_encoder_frame ? b->hal->joint_encoder_frame(b->hal->ctx, axis) : 0u;
  (void)rg_joint_encoder_update(&b->axes[axis].joint_encoder, frame);
}

// The angle (deg) encoder i gives with its stored zero, wrapped into the turn centred on `middle`.
static float encoder_degrees(const rg_board_t *b, unsigned i, float middle) {
  const rg_axis_params_t *p = &b->params.axes[i];
  const uint32_t modulus = 1u << p->joint_encoder_bits;
  const uint32_t steps = ((uint32_t)b->axes[i].joint_encoder.angle + modulus - (p->joint_zero % modulus)) % modulus;
  const float degrees = (float)steps * 360.0f / (float)modulus;
  float delta = fmodf(degrees - middle, 360.0f);
  if (delta < -180.0f) delta += 360.0f;
  if (delta >= 180.0f) delta -= 360.0f;
  return middle + delta;
}

static float middle_degrees(const rg_axis_params_t *p) {
  return 0.5f * (float)(p->min_position + p->max_position) / p->counts_per_degree;
}

static bool ready(const rg_board_t *b, unsigned i) {
  const rg_axis_params_t *p = &b->params.axes[i];
  return b->axes[i].joint_encoder.state == RG_JOINT_ENCODER_OK && p->joint_zero_stored && p->counts_per_degree > 0.0f;
}

// Sets the axis's out-of-range flag; true when `degrees` is within its limits and the tolerance.
static bool in_range(rg_board_t *b, unsigned axis, float degrees) {
  const rg_axis_params_t *p = &b->params.axes[axis];
  const float counts = degrees * p->counts_per_degree;
  const float tolerance = RG_JOINT_HOMING_RANGE_TOLERANCE_DEG * p->counts_per_degree;
  b->axes[axis].joint_out_of_range =
      counts < (float)p->min_position - tolerance || counts > (float)p->max_position + tolerance;
  return !b->axes[axis].joint_out_of_range;
}

static void home_at(rg_board_t *b, unsigned axis, float degrees) {
  rg_axis_t *a = &b->axes[axis];
  rg_board_shift_position(b, axis, (int32_t)lroundf(degrees * b->params.axes[axis].counts_per_degree));
  a->joint_homed = true;
  rg_board_set_mode(b, axis, ROBOGENE_CAN_CONTROL_MODE_IDLE);
}

static void try_home(rg_board_t *b, unsigned axis) {
  if (b->axes[axis].joint_homed || !ready(b, axis)) return;
  const float degrees = encoder_degrees(b, axis, middle_degrees(&b->params.axes[axis]));
  if (in_range(b, axis, degrees)) home_at(b, axis, degrees);
}

// The eye board: each pan's angle from its own sensor (wrapped about 0, the pans' ranges being symmetric),
// version = (left + right) / 2 and vergence = left - right, both axes homed together or neither.
static void try_home_coupled(rg_board_t *b) {
  if (!has_encoder(b, 0) || !has_encoder(b, 1) || (b->axes[0].joint_homed && b->axes[1].joint_homed)) return;
  if (!ready(b, 0) || !ready(b, 1)) return;
  const float left = encoder_degrees(b, 0, 0.0f), right = encoder_degrees(b, 1, 0.0f);
  const float version = 0.5f * (left + right), vergence = left - right;
  const bool ok = in_range(b, 0, version);
  if (!(in_range(b, 1, vergence) && ok)) return;
  home_at(b, 0, version);
  home_at(b, 1, vergence);
}

static void try_home_board(rg_board_t *b) {
  if (coupled(b)) {
    try_home_coupled(b);
    return;
  }
  for (unsigned i = 0; i < 2u; ++i) {
    if (has_encoder(b, i)) try_home(b, i);
  }
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
  }
  try_home_board(b);
}

void rg_joint_homing_tick(rg_board_t *b) {
  for (unsigned i = 0; i < 2u; ++i) {
    if (has_encoder(b, i)) read_frame(b, i);
  }
  try_home_board(b);
}

bool rg_joint_homing_position(const rg_board_t *b, unsigned axis, float *counts) {
  const rg_axis_params_t *p = &b->params.axes[axis];
  if (coupled(b)) {
    // As homing takes them: version = (left + right) / 2, vergence = left - right, each pan's angle about 0.
    if (!has_encoder(b, 0) || !has_encoder(b, 1) || !ready(b, 0) || !ready(b, 1)) return false;
    const float left = encoder_degrees(b, 0, 0.0f), right = encoder_degrees(b, 1, 0.0f);
    *counts = (axis == 0u ? 0.5f * (left + right) : left - right) * p->counts_per_degree;
    return true;
  }
  if (!has_encoder(b, axis) || !ready(b, axis)) return false;
  *counts = encoder_degrees(b, axis, middle_degrees(p)) * p->counts_per_degree;
  return true;
}

bool rg_joint_homing_blocks(const rg_board_t *b, unsigned axis) {
  return has_encoder(b, axis) && !b->axes[axis].joint_homed;
}

static bool encoder_bad(const rg_board_t *b, unsigned i) {
  const rg_axis_t *a = &b->axes[i];
  return has_encoder(b, i) && (a->joint_encoder.state == RG_JOINT_ENCODER_ABSENT ||
                               a->joint_encoder.state == RG_JOINT_ENCODER_FAILED || a->joint_out_of_range);
}

uint8_t rg_joint_homing_faults(const rg_board_t *b, unsigned axis) {
  if (!has_encoder(b, axis)) return 0u;
  // On the eye board both joints come from both sensors: either one's fault is both axes'.
  const bool bad = coupled(b) ? (encoder_bad(b, 0) || encoder_bad(b, 1)) : encoder_bad(b, axis);
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
  if (coupled(b) && running(b->axes[1u - axis].mode)) return false;  // its partner moves with it
  p->joint_zero = zero;
  p->joint_zero_stored = true;
  if (b->hal->save_joint_zero) b->hal->save_joint_zero(b->hal->ctx, axis, zero);
  unhome(b, axis);
  if (coupled(b) && b->axes[1u - axis].mode != ROBOGENE_CAN_CONTROL_MODE_HARDWARE_FAULT) unhome(b, 1u - axis);
  try_home_board(b);
  return true;
}

// The states get_joint_encoder reports are the protocol's JointEncoderState.
_Static_assert(RG_JOINT_ENCODER_STARTING == ROBOGENE_CAN_JOINT_ENCODER_STATE_STARTING, "JointEncoderState");
_Static_assert(RG_JOINT_ENCODER_OK == ROBOGENE_CAN_JOINT_ENCODER_STATE_OK, "JointEncoderState");
_Static_assert(RG_JOINT_ENCODER_ABSENT == ROBOGENE_CAN_JOINT_ENCODER_STATE_ABSENT, "JointEncoderState");
_Static_assert(RG_JOINT_ENCODER_FAILED == ROBOGENE_CAN_JOINT_ENCODER_STATE_FAILED, "JointEncoderState");
