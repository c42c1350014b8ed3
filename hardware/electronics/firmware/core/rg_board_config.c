// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "rg_board_config.h"

#include <string.h>

#include "generated/robogene_head_board_config.h"

static void axis_from_config(const robogene_axis_config_t *c, rg_axis_params_t *p) {
  memset(p, 0, sizeof *p);
  p->present = c->joint != NULL;
  p->min_position = c->min_position;
  p->max_position = c->max_position;
  p->max_speed = c->max_speed;
  p->current_limit_ma = c->current_limit;
  p->has_brake = c->has_brake != 0u;
  p->counts_per_degree = c->counts_per_degree;
  p->joint_encoder_bits = c->joint_encoder_bits;
  p->joint_correction_limit = c->joint_correction_limit;
  p->pid.kp = c->kp;
  p->pid.ki = c->ki;
  p->pid.kd = c->kd;
  p->pid.shift = c->shift;
  p->pid.offset = c->offset;
  p->pid.output_limit = c->output_limit;
  p->pid.integral_limit = c->integral_limit;
  p->homing.direction = c->homing_direction;
  p->homing.speed = (float)c->homing_speed;
  p->homing.pwm_limit = c->homing_pwm;
  p->homing.stop_position = c->homing_stop;
  p->homing.backoff = c->homing_backoff;
  p->homing.timeout_ms = c->homing_timeout_ms;
  p->homing.current_limit_ma = c->homing_current_limit;
}

bool rg_board_params_for_address(uint8_t can_address, rg_board_params_t *out) {
  const robogene_board_config_t *c = robogene_board_config(can_address);
  if (c == NULL) return false;
  memset(out, 0, sizeof *out);
  out->address = c->can_address;
  out->board_id = c->can_address;
  out->coupling = (uint8_t)c->coupling;
  memcpy(out->counts_m2a, c->counts_m2a, sizeof out->counts_m2a);
  for (unsigned i = 0; i < 2u; ++i) axis_from_config(&c->axes[i], &out->axes[i]);
  out->pwm_full_scale = ROBOGENE_PWM_FULL_SCALE;
  out->control_period_us = ROBOGENE_CONTROL_PERIOD_US;
  out->velocity_timeout_ms = ROBOGENE_VELOCITY_TIMEOUT_MS;
  out->protocol_major = ROBOGENE_CAN_PROTOCOL_MAJOR;
  out->protocol_minor = ROBOGENE_CAN_PROTOCOL_MINOR;
  out->broadcast_policy = ROBOGENE_BROADCAST_POLICY;
  return true;
}
