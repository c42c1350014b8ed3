// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "rg_board.h"

#include <math.h>
#include <string.h>

#include "rg_broadcasts.h"
#include "rg_joint_homing.h"
#include "rg_joint_loop.h"
#include "rg_wire.h"
#include "generated/robogene_can_motor_control.h"

float rg_board_period_s(const rg_board_t *b) { return (float)b->params.control_period_us * 1e-6f; }

static void read_encoders(rg_board_t *b, bool first) {
  int32_t motor_counts[2];
  for (unsigned m = 0; m < 2u; ++m) {
    const uint16_t raw = b->hal->encoder_raw(b->hal->ctx, m);
    if (first) rg_encoder_start(&b->motors[m].encoder, raw);
    motor_counts[m] = rg_encoder_update(&b->motors[m].encoder, raw);
  }
  const float dt = rg_board_period_s(b);
  for (unsigned i = 0; i < 2u; ++i) {
    rg_axis_t *a = &b->axes[i];
    const int8_t *row = b->params.counts_m2a[i];
    const int32_t counts = row[0] * motor_counts[0] + row[1] * motor_counts[1] + a->offset;
    if (!first) {
      // Low-pass filtered differences (10 ms), the speed a board can estimate from counts.
      const float alpha = 0.1f;
      const float previous = a->speed;
      a->speed += alpha * ((float)(counts - a->motor_position) / dt - a->speed);
      a->accel += alpha * ((a->speed - previous) / dt - a->accel);
    }
    a->motor_position = counts;
    a->measured = counts;  // an axis closed on its joint encoder takes the joint's (rg_joint_loop_measure)
  }
}

void rg_board_init(rg_board_t *b, const rg_board_params_t *params, const rg_hal_t *hal) {
  memset(b, 0, sizeof *b);
  b->hal = hal;
  b->params = *params;
  b->address = params->address;
  b->policy = params->broadcast_policy;
  for (unsigned i = 0; i < 2u; ++i) {
    const rg_axis_params_t *p = &params->axes[i];
    rg_axis_t *a = &b->axes[i];
    a->present = p->present;
    a->mode = ROBOGENE_CAN_CONTROL_MODE_IDLE;
    a->min = (float)p->min_position;
    a->max = (float)p->max_position;
    a->max_velocity = (float)p->max_speed;
    a->traj.acceleration = 4.0f * a->max_velocity;
    a->pid = p->pid;
    a->homing_config = p->homing;
    b->motors[i].current_limit_ma = p->current_limit_ma;
    b->motors[i].duty_cap = (float)params->pwm_full_scale;
  }
  // Brakes only where motor i drives axis i alone: on a coupled board a motor serves both axes, and the
  // board configuration has no brakes there (the codegen refuses them).
  for (unsigned i = 0; i < 2u; ++i) {
    b->motors[i].has_brake = params->coupling == RG_COUPLING_NONE && params->axes[i].present &&
                             params->axes[i].has_brake && hal->set_brake != NULL;
    // Applied from the start, as the gate's pull-down already holds it through reset.
    if (b->motors[i].has_brake) hal->set_brake(hal->ctx, i, false);
  }
  // On a coupled board both motors serve both axes: each takes the lower of the two limits.
  if (params->coupling != RG_COUPLING_NONE) {
    const int32_t l0 = params->axes[0].current_limit_ma, l1 = params->axes[1].current_limit_ma;
    b->motors[0].current_limit_ma = b->motors[1].current_limit_ma = l0 < l1 ? l0 : l1;
  }
  for (unsigned m = 0; m < 2u; ++m) b->motors[m].active_limit_ma = b->motors[m].current_limit_ma;
  read_encoders(b, true);
  rg_joint_homing_init(b);
  rg_joint_loop_measure(b);
  for (unsigned i = 0; i < 2u; ++i) {
    rg_trajectory_hold(&b->axes[i].traj, (float)b->axes[i].measured);
    rg_joint_loop_follow(b, i);
  }
}

void rg_board_set_mode(rg_board_t *b, unsigned axis, uint8_t mode) {
  rg_axis_t *a = &b->axes[axis];
  rg_trajectory_hold(&a->traj, (float)a->measured);
  rg_joint_loop_follow(b, axis);
  a->velocity_command = 0.0f;
  rg_pid_reset(&a->pid_state);
  a->output = 0;
  a->homing.phase = a->homing.phase == RG_HOMING_DONE ? RG_HOMING_DONE : RG_HOMING_IDLE;
  a->mode = mode;
}

void rg_board_shift_position(rg_board_t *b, unsigned axis, int32_t position) {
  rg_axis_t *a = &b->axes[axis];
  const int32_t shift = position - a->measured;
  a->offset += shift;
  a->motor_position += shift;
  a->measured += shift;
  a->traj.ref += (float)shift;
  a->traj.target += (float)shift;
}

void rg_board_note_overrun(rg_board_t *b) { b->board_flags |= ROBOGENE_CAN_BOARD_FLAGS_CONTROL_LOOP_OVERRUN; }

static bool running(uint8_t mode) {
  return mode == ROBOGENE_CAN_CONTROL_MODE_POSITION || mode == ROBOGENE_CAN_CONTROL_MODE_VELOCITY ||
         mode == ROBOGENE_CAN_CONTROL_MODE_CALIBRATION;
}

// Supply, bridge and current faults. A fault on a running axis stops it (hardware_fault, bridge
// off) until the host sends force_idle; on an idle axis the bits only report the condition.
static void check_faults(rg_board_t *b) {
  const uint32_t mv = b->hal->supply_mv(b->hal->ctx);
  uint8_t board_faults = 0;
  if (mv < RG_SUPPLY_MIN_MV) board_faults |= ROBOGENE_CAN_AXIS_FAULTS_UNDERVOLTAGE;
  if (mv > RG_SUPPLY_MAX_MV) board_faults |= ROBOGENE_CAN_AXIS_FAULTS_OVERVOLTAGE;
  if (b->hal->bridge_fault(b->hal->ctx)) board_faults |= ROBOGENE_CAN_AXIS_FAULTS_EXTERNAL;
  uint8_t motor_faults = 0;
  for (unsigned m = 0; m < 2u; ++m) {
    rg_motor_t *mo = &b->motors[m];
    mo->last_current_ma = b->hal->current_ma(b->hal->ctx, m);
    const int64_t magnitude = mo->last_current_ma < 0 ? -(int64_t)mo->last_current_ma : mo->last_current_ma;
    const bool over = magnitude * 100 > (int64_t)mo->current_limit_ma * RG_OVERCURRENT_PERCENT;
    mo->overcurrent_periods = over ? mo->overcurrent_periods + 1u : 0u;
    if (mo->overcurrent_periods >= RG_OVERCURRENT_PERIODS) motor_faults |= ROBOGENE_CAN_AXIS_FAULTS_OVERCURRENT;
  }
  for (unsigned i = 0; i < 2u; ++i) {
    rg_axis_t *a = &b->axes[i];
    if (!a->present) continue;
    // Motor i drives axis i, or both axes on a coupled board.
    const bool coupled = b->params.coupling != RG_COUPLING_NONE;
    const uint8_t over = coupled ? motor_faults : (b->motors[i].overcurrent_periods >= RG_OVERCURRENT_PERIODS
                                                       ? ROBOGENE_CAN_AXIS_FAULTS_OVERCURRENT : 0u);
    const uint8_t now = (uint8_t)(board_faults | over | rg_joint_loop_faults(b, i));
    // The joint encoder's own faults are reported, but stop nothing: the axis goes on on its motor encoder.
    const uint8_t reported = (uint8_t)(now | rg_joint_homing_faults(b, i));
    if (a->mode == ROBOGENE_CAN_CONTROL_MODE_HARDWARE_FAULT) {
      a->faults |= reported;  // latched until force_idle
    } else if (now != 0u && running(a->mode)) {
      rg_board_set_mode(b, i, ROBOGENE_CAN_CONTROL_MODE_HARDWARE_FAULT);
      a->faults = reported;
    } else {
      a->faults = reported;
    }
  }
}

static int16_t control(rg_board_t *b, unsigned axis, float dt) {
  rg_axis_t *a = &b->axes[axis];
  switch (a->mode) {
    case ROBOGENE_CAN_CONTROL_MODE_POSITION:
      rg_trajectory_position_step(&a->traj, dt);
      break;
    case ROBOGENE_CAN_CONTROL_MODE_VELOCITY: {
      const uint32_t timeout_ticks = (uint32_t)b->params.velocity_timeout_ms * 1000u / b->params.control_period_us;
      if (a->velocity_command != 0.0f && b->tick - a->velocity_command_tick > timeout_ticks) {
        a->velocity_command = 0.0f;  // the host went quiet: stop
      }
      rg_trajectory_velocity_step(&a->traj, a->velocity_command, a->min, a->max, dt);
      break;
    }
    case ROBOGENE_CAN_CONTROL_MODE_CALIBRATION:
      return rg_homing_step(b, axis, dt);
    default:  // idle, faults, not configured: follow the axis so that a switch to a loop is smooth
      rg_trajectory_hold(&a->traj, (float)a->measured);
      rg_joint_loop_follow(b, axis);
      rg_pid_reset(&a->pid_state);
      return 0;
  }
  // The motor loop, its reference shifted by the joint loop's correction (0 on an axis not closed on its joint).
  rg_joint_loop_step(b, axis, dt);
  const float error = a->traj.ref + a->joint_correction - (float)a->motor_position;
  return rg_pid_step(&a->pid, &a->pid_state, error, a->pid.output_limit);
}

// The limit a motor's current is held to this period: its run limit, or while an axis it drives seeks
// its hard stop that run's homing limit, if lower (it sets how hard the stop is pressed). Computed each
// period from the homing phase, so that every way out of the seek (the stop found, a timeout, a fault,
// a mode change) is back at the run limit.
static int32_t active_limit(const rg_board_t *b, unsigned m) {
  int32_t limit = b->motors[m].current_limit_ma;
  for (unsigned i = 0; i < 2u; ++i) {
    if (b->params.coupling == RG_COUPLING_NONE && i != m) continue;  // motor m drives axis m alone
    const int32_t homing = rg_homing_current_limit(b, i);
    if (homing > 0 && homing < limit) limit = homing;
  }
  return limit;
}

// Keeps a motor's current within its limit: over the limit the duty ceiling drops in proportion
// (current follows duty at stall, where the limit matters); below it the ceiling rises again,
// within 50 periods when far below, more slowly the closer the current is to the limit, so that
// a motor pushing against something settles at the limit instead of ringing about it.
static float limit_current(rg_board_t *b, unsigned m, float duty) {
  rg_motor_t *mo = &b->motors[m];
  const float full = (float)b->params.pwm_full_scale;
  const float current = fabsf((float)mo->last_current_ma);
  const float limit = (float)mo->active_limit_ma;
  if (current > limit && current > 0.0f) {
    mo->duty_cap = fminf(mo->duty_cap, fabsf(duty)) * limit / current;
  } else {
    const float headroom = limit > 0.0f ? (limit - current) / limit : 1.0f;
    mo->duty_cap = fminf(full, mo->duty_cap + full / 50.0f * headroom);
  }
  return rg_clampf(duty, -mo->duty_cap, mo->duty_cap);
}

// Only a motor with a brake output ever drives it; the call is repeated every period (the output is a
// level, so a lost write cannot leave a brake released).
static void set_brake(rg_board_t *b, unsigned m, bool released) {
  if (!b->motors[m].has_brake) return;
  b->hal->set_brake(b->hal->ctx, m, released);
}

static void drive(rg_board_t *b) {
  float duty[2];
  const float u0 = b->axes[0].output, u1 = b->axes[1].output;
  if (b->params.coupling == RG_COUPLING_VERSION_VERGENCE) {
    duty[0] = u0 + 0.5f * u1;  // left = version + vergence / 2
    duty[1] = u0 - 0.5f * u1;  // right = version - vergence / 2
  } else {
    duty[0] = u0;
    duty[1] = u1;
  }
  for (unsigned m = 0; m < 2u; ++m) {
    rg_motor_t *mo = &b->motors[m];
    const bool enabled = b->params.coupling == RG_COUPLING_NONE
                             ? running(b->axes[m].mode)
                             : (running(b->axes[0].mode) || running(b->axes[1].mode));
    const float full = (float)b->params.pwm_full_scale;
    mo->active_limit_ma = active_limit(b, m);
    const float d = rg_clampf(limit_current(b, m, duty[m]), -full, full);
    // The brake holds whenever the bridge does not: applied before the bridge turns off (a disable, a
    // fault), released only once the bridge has been on and its loop holding for a whole period.
    if (!enabled) set_brake(b, m, false);
    b->hal->set_pwm(b->hal->ctx, m, enabled ? (int32_t)lroundf(d) : 0, enabled);
    if (enabled && mo->bridge_on) set_brake(b, m, true);
    mo->bridge_on = enabled;
  }
}

void rg_board_stop_motors(rg_board_t *b) {
  for (unsigned m = 0; m < 2u; ++m) {
    set_brake(b, m, false);
    b->hal->set_pwm(b->hal->ctx, m, 0, false);
    b->motors[m].bridge_on = false;
  }
}

void rg_board_tick(rg_board_t *b) {
  ++b->tick;
  const float dt = rg_board_period_s(b);
  read_encoders(b, false);
  rg_joint_homing_tick(b);
  rg_joint_loop_measure(b);
  check_faults(b);
  for (unsigned i = 0; i < 2u; ++i) {
    rg_axis_t *a = &b->axes[i];
    a->output = a->present ? control(b, i, dt) : 0;
  }
  drive(b);
  rg_send_broadcasts(b);
}
