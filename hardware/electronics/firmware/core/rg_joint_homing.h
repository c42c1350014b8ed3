// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// Homing from an absolute joint encoder (homing method absolute_encoder: neck pitch, roll, yaw, eye
// tilt). An axis with a joint encoder starts not_configured and refuses every control mode; as soon as
// its encoder is trusted (rg_joint_encoder.h) and a zero is stored, its position is taken from it:
//
//   joint angle = (raw - zero) x 360 / 2^bits, wrapped into the 360 deg centred on the joint's range,
//   position   = joint angle x counts per degree (the motor encoder's counts through the reduction),
//
// and the axis goes idle, homed. On the eye board (coupled) the two encoders are the pans' (encoder 0 beside
// motor 0, the left pan): each pan's angle is taken about 0, and version = (left + right) / 2 and vergence =
// left - right home together, or neither does. rg_board_init reads RG_JOINT_ENCODER_STARTUP_FRAMES frames at once,
// so a working encoder homes its axis before the first control period. An encoder that is absent or
// failing, no stored zero, or an angle more than RG_JOINT_HOMING_RANGE_TOLERANCE_DEG outside the
// joint's limits (a wrong zero, a slipped magnet) leave the axis unhomed: never a guessed zero. The
// encoder keeps being read every period: a homed axis with a correction limit closes its position on it (rg_joint_loop.h);
// its faults are reported in the axis's status (absolute_encoder_error) but do not stop a homed axis, which goes on
// on its motor encoder.
#ifndef RG_JOINT_HOMING_H
#define RG_JOINT_HOMING_H

#include <stdbool.h>
#include <stdint.h>

#define RG_JOINT_HOMING_RANGE_TOLERANCE_DEG 10.0f

struct rg_board;

// At start: every axis with a joint encoder is read RG_JOINT_ENCODER_STARTUP_FRAMES times and homed if it can be.
void rg_joint_homing_init(struct rg_board *b);
// Each control period: one frame per joint encoder; an unhomed axis homes once it can.
void rg_joint_homing_tick(struct rg_board *b);
// The axis has a joint encoder and has not yet taken its position from it: no control mode is accepted.
bool rg_joint_homing_blocks(const struct rg_board *b, unsigned axis);
// The joint's position from its encoder now (axis counts, as homing takes it; on the eye board version or vergence
// from both pans' encoders) when the encoder(s) are trusted and have a stored zero; false otherwise.
bool rg_joint_homing_position(const struct rg_board *b, unsigned axis, float *counts);
// The fault bits (ROBOGENE_CAN_AXIS_FAULTS_*) the joint encoder adds to the axis's status now.
uint8_t rg_joint_homing_faults(const struct rg_board *b, unsigned axis);
// set_joint_encoder_zero: stores `zero` (and saves it through the HAL), then homes the axis again from
// it. False, changing nothing, for an axis without a joint encoder, a zero beyond its bits, or a running axis.
bool rg_joint_homing_set_zero(struct rg_board *b, unsigned axis, uint16_t zero);

#endif  // RG_JOINT_HOMING_H
