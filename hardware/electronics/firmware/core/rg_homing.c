// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "rg_homing.h"

#include <math.h>

#include "rg_board.h"
#include "generated/robogene_can_motor_control.h"

bool rg_homing_start(struct rg_board *b, unsigned axis, int16_t pwm_limit, float speed) {
  rg_axis_t *a = &b->axes[axis];
  // An axis with a joint encoder is homed from it (rg_joint_homing.c), never against a stop: a stop run would
  // let it move before its encoder gave it a position.
  if (!a->present || a->homing_config.direction == 0 || a->mode == ROBOGENE_CAN_CONTROL_MODE_HARDWARE_FAULT ||
      b->params.axes[axis].joint_encoder_bits > 0u) {
    return false;
  }
  rg_board_set_mode(b, axis, ROBOGENE_CAN_CONTROL_MODE_IDLE);  // a fresh start: reference where the axis is
  a->mode = ROBOGENE_CAN_CONTROL_MODE_CALIBRATION;
  a->traj.done = false;
  rg_homing_t *h = &a->homing;
  h->run = a->homing_config;
  if (pwm_limit > 0) h->run.pwm_limit = pwm_limit;
  if (speed > 0.0f) h->run.speed = speed;
  h->phase = RG_HOMING_SEEK;
  h->start_tick = b->tick;
  h->stall_periods = 0;
  // On the eye board the partner axis (vergence) must let each eye run into its own stop.
  if (b->params.coupling != RG_COUPLING_NONE) {
    rg_axis_t *partner = &b->axes[1u - axis];
    if (partner->mode != ROBOGENE_CAN_CONTROL_MODE_HARDWARE_FAULT) {
      rg_board_set_mode(b, 1u - axis, ROBOGENE_CAN_CONTROL_MODE_IDLE);
    }
  }
  return true;
}

static void fail(struct rg_board *b, unsigned axis) {
  rg_axis_t *a = &b->axes[axis];
  rg_board_set_mode(b, axis, ROBOGENE_CAN_CONTROL_MODE_IDLE);
  a->mode = ROBOGENE_CAN_CONTROL_MODE_NOT_CONFIGURED;
  a->homing.phase = RG_HOMING_FAILED;
}

static int16_t seek(struct rg_board *b, unsigned axis, float dt) {
  rg_axis_t *a = &b->axes[axis];
  rg_homing_t *h = &a->homing;
  const uint32_t elapsed = b->tick - h->start_tick;
  if ((float)elapsed * dt * 1000.0f > (float)h->run.timeout_ms) {
    fail(b, axis);
    return 0;
  }
  // The stop's position is unknown until it is found: no software limits while seeking.
  rg_trajectory_velocity_step(&a->traj, (float)h->run.direction * h->run.speed, -3.0e9f, 3.0e9f, dt);
  // The reference may lead the axis by a few PWM-limited errors only, so that leaving the stop
  // (someone lifts the eye off it) does not fling the axis.
  const float lead = 4.0f * (float)h->run.pwm_limit * ldexpf(1.0f, a->pid.shift) / (float)(a->pid.kp > 0 ? a->pid.kp : 1);
  const float measured = (float)a->measured;
  if (fabsf(a->traj.ref - measured) > lead) a->traj.ref = measured + copysignf(lead, a->traj.ref - measured);
  const int16_t out = rg_pid_step(&a->pid, &a->pid_state, a->traj.ref - measured, h->run.pwm_limit);
  const bool pushing = out == (int16_t)(h->run.direction * h->run.pwm_limit);
  const bool still = fabsf(a->speed) < 0.2f * h->run.speed;
  h->stall_periods = (elapsed > RG_HOMING_STALL_GRACE && pushing && still) ? h->stall_periods + 1u : 0u;
  if (h->stall_periods < RG_HOMING_STALL_PERIODS) return out;
  // At the stop: this is where the axis is, by definition of the stop's position; on the coupled
  // board the partner's too, and it holds there.
  rg_board_shift_position(b, axis, h->run.stop_position);
  if (b->params.coupling != RG_COUPLING_NONE) {
    const unsigned other = 1u - axis;
    rg_axis_t *partner = &b->axes[other];
    if (partner->present && partner->mode == ROBOGENE_CAN_CONTROL_MODE_IDLE) {
      rg_board_shift_position(b, other, partner->homing_config.stop_position);
      rg_board_set_mode(b, other, ROBOGENE_CAN_CONTROL_MODE_POSITION);
    }
  }
  rg_pid_reset(&a->pid_state);
  rg_trajectory_hold(&a->traj, (float)a->measured);
  a->traj.target = (float)(h->run.stop_position - h->run.direction * h->run.backoff);
  a->traj.move_speed = h->run.speed;
  a->traj.done = false;
  h->phase = RG_HOMING_BACKOFF;
  return 0;
}

int32_t rg_homing_current_limit(const struct rg_board *b, unsigned axis) {
  const rg_axis_t *a = &b->axes[axis];
  const bool seeking = a->mode == ROBOGENE_CAN_CONTROL_MODE_CALIBRATION && a->homing.phase == RG_HOMING_SEEK;
  return seeking ? a->homing.run.current_limit_ma : 0;
}

int16_t rg_homing_step(struct rg_board *b, unsigned axis, float dt) {
  rg_axis_t *a = &b->axes[axis];
  switch (a->homing.phase) {
    case RG_HOMING_SEEK:
      return seek(b, axis, dt);
    case RG_HOMING_BACKOFF: {
      rg_trajectory_position_step(&a->traj, dt);
      const int16_t out = rg_pid_step(&a->pid, &a->pid_state, a->traj.ref - (float)a->measured, a->pid.output_limit);
      if (a->traj.done) {
        a->mode = ROBOGENE_CAN_CONTROL_MODE_POSITION;  // holds where it backed off to
        a->homing.phase = RG_HOMING_DONE;
      }
      return out;
    }
    default:
      return 0;
  }
}
