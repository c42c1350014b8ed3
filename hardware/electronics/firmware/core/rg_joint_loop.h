// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// The joint loop (docs/firmware.md "The joint loop"): an axis with a joint encoder that homed from it, with a
// correction limit in its table, has its position closed on the joint; on the eye board version and vergence, derived
// from both pans' encoders, are closed together or not at all. The position PID
// stays on the motor encoder, the fast inner loop; this outer loop adds a correction c to its reference,
//
//   PID error = (trajectory reference + c) - motor position,
//
// and c integrates the joint's error e = reference - joint position (the joint's sensor, in the axis's counts)
// less what the motor loop has still to take up of its own error, so that c does not wind up while the motor loop
// follows a moving reference; at rest the two are the same. c moves at most RG_JOINT_LOOP_MAX_RATE_DEG_S, and only
// while |e| exceeds one count of the joint encoder: inside that dead band it holds still, so the loop settles on
// the sensor instead of hunting back and forth across the gear's backlash. It runs in position and velocity
// modes; idle, c follows what lies between motor and joint (c = motor position - joint position), so that the
// switch to a loop does not move the motor.
//
// |c| above the axis's joint_correction_limit is joint_encoder_mismatch: the motor has had to go further from the
// joint than any backlash explains (a sensor counting the wrong way makes c run away, a hub slipping on its shaft
// makes it grow without end), and the axis stops like on every other fault.
//
// A joint encoder that fails while the axis is closed on it (absent, failed: absolute_encoder_error) leaves the
// axis on its motor encoder with c frozen: the motor holds where the correction last put it, the position
// reported continues as motor position - c, and the axis keeps working, with backlash no longer taken up, until the
// sensor is trusted again.
#ifndef RG_JOINT_LOOP_H
#define RG_JOINT_LOOP_H

#include <stdbool.h>
#include <stdint.h>

// How fast c follows the joint's error: 1/s. Near the dead band c then moves at 20 x 0.022 = 0.44 deg/s, slowly enough
// that the motor loop, which lags its reference by some tens of ms, carries the joint less than a count beyond the
// point where c stops: the joint comes to rest inside the band instead of overshooting it and turning back across the
// gap. The price: a joint left a few counts off (the motor loop's own overshoot pushed it there) takes up to a second
// or two to have the motor cross the gap back.
#define RG_JOINT_LOOP_GAIN_PER_S 20.0f
// The fastest c may move, deg/s at the joint: a gap of 1 deg is crossed in 0.1 s, and a runaway reaches a 3 deg
// limit in no less than 0.3 s of the joint's travel.
#define RG_JOINT_LOOP_MAX_RATE_DEG_S 10.0f

struct rg_board;

// The axis's position is closed on its joint encoder when its sensor can be read (else it runs on its motor encoder
// with the correction frozen): a joint encoder it homed from and a correction limit (on the eye board: both axes).
bool rg_joint_loop_configured(const struct rg_board *b, unsigned axis);
// Each period, after the encoders and the joint encoders are read: the axis's reported position (measured), its
// joint's from the sensor, or its motor's less the frozen correction when the sensor fails.
void rg_joint_loop_measure(struct rg_board *b);
// Position and velocity modes, after the trajectory's step: advances the correction.
void rg_joint_loop_step(struct rg_board *b, unsigned axis, float dt);
// Any other mode (and on every mode change): the correction is what lies between motor and joint now.
void rg_joint_loop_follow(struct rg_board *b, unsigned axis);
// ROBOGENE_CAN_AXIS_FAULTS_JOINT_ENCODER_MISMATCH when the correction is over its limit, else 0.
uint8_t rg_joint_loop_faults(const struct rg_board *b, unsigned axis);

#endif  // RG_JOINT_LOOP_H
