// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// Homing against a hard stop, for axes with no absolute encoder (the eyes' pan): the axis runs
// slowly towards its stop with its drive limited to a low PWM and its motors to a current limit of
// their own, takes the stop as reached when it stalls there (pushing at that limit and no longer
// moving), declares its position to be the stop's, backs off and holds in position mode. The
// current limit sets the torque the stop is pressed with, and so how far the stop and the gear
// wind up when the position is taken (the eyes' accuracy budget); it applies only while the axis
// seeks the stop: backing off, and whatever follows, runs at the motors' run limit. While it
// homes the axis reports the control mode `calibration`; an axis that finds no stop within the
// time allowed goes `not_configured` with its bridge off. On the coupled eye board axis 0
// (version) homes both eyes against their stops with axis 1 (vergence) left free; at the stops
// both axes take their stop positions, so one run calibrates both, and both then hold in
// position mode.
#ifndef RG_HOMING_H
#define RG_HOMING_H

#include <stdbool.h>
#include <stdint.h>

typedef struct {
  int8_t direction;        // -1 towards the lower stop, +1 the upper; 0: the axis does not home
                           // itself (stop_position still applies to a coupled partner)
  float speed;             // counts/s towards the stop
  int16_t pwm_limit;       // PWM steps the drive may push with
  int32_t stop_position;   // counts the axis reads pressed against the stop
  int32_t backoff;         // counts to move away from the stop afterwards
  uint32_t timeout_ms;     // to find the stop
  int32_t current_limit_ma;  // per motor while seeking the stop (at most the run limit); 0: the run limit
} rg_homing_config_t;

enum {
  RG_HOMING_IDLE = 0,  // never homed, or interrupted
  RG_HOMING_SEEK,
  RG_HOMING_BACKOFF,
  RG_HOMING_DONE,
  RG_HOMING_FAILED
};

// A stall is this many periods of pushing at the PWM limit while slower than a fifth of the
// homing speed, after the first STALL_GRACE periods (the start from rest looks alike).
#define RG_HOMING_STALL_PERIODS 50u
#define RG_HOMING_STALL_GRACE 100u

typedef struct {
  uint8_t phase;
  rg_homing_config_t run;  // the parameters of this run
  uint32_t start_tick;
  uint32_t stall_periods;
} rg_homing_t;

struct rg_board;

// Starts homing `axis`; pwm_limit and speed override the axis's configuration when not zero.
// False (nothing changes) when the axis has no homing configured or is in a fault.
bool rg_homing_start(struct rg_board *b, unsigned axis, int16_t pwm_limit, float speed);
// One control period of a homing axis; returns its controller output (PWM steps).
int16_t rg_homing_step(struct rg_board *b, unsigned axis, float dt);
// The homing current limit (mA) in force on `axis` now: its run's while it seeks its stop, else 0 (none).
int32_t rg_homing_current_limit(const struct rg_board *b, unsigned axis);

#endif  // RG_HOMING_H
