// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// The motor board's control core: everything a board does between its CAN frames and its two
// H-bridges, for the firmware and for `robogene can-sim` alike. Per axis: the protocol's control
// modes, a trajectory generator, the position loop, software limits, homing against a hard stop,
// and fault handling; per motor: encoder decoding and a current limiter; per board: the
// broadcasts its policy enables. No heap, no globals: one rg_board_t per board, stepped by
// rg_board_tick() once per control period and fed frames by rg_board_receive().
#ifndef RG_BOARD_H
#define RG_BOARD_H

#include <stdbool.h>
#include <stdint.h>

#include "rg_encoder.h"
#include "rg_hal.h"
#include "rg_homing.h"
#include "rg_joint_encoder.h"
#include "rg_pid.h"
#include "rg_trajectory.h"

#ifdef __cplusplus
extern "C" {
#endif

enum { RG_COUPLING_NONE = 0, RG_COUPLING_VERSION_VERGENCE = 1 };  // robogene_coupling_t

// Firmware identity in the get_firmware_version reply.
#define RG_FIRMWARE_VERSION 2u
#define RG_FIRMWARE_REVISION 2u  // 2.2: positions closed on the joint encoders, protocol 1.2
#define RG_FIRMWARE_BUILD 0u

// Supply window outside which the bridges stay off (mV): the drivers' 12 V rail.
#define RG_SUPPLY_MIN_MV 9000u
#define RG_SUPPLY_MAX_MV 16000u
// A motor current above OVERCURRENT_PERCENT of its limit for this many periods is a fault: the
// limiter failed to hold it (a shorted motor lead, a stuck bridge).
#define RG_OVERCURRENT_PERCENT 150
#define RG_OVERCURRENT_PERIODS 20u

typedef struct {
  bool present;
  int32_t min_position, max_position;  // counts
  int32_t max_speed;                   // counts/s
  int32_t current_limit_ma;            // per motor of the axis
  bool has_brake;                      // the axis's motor has a power-off holding brake (uncoupled boards only)
  float counts_per_degree;             // of the joint, on the wire
  // An absolute joint encoder (AS5048A) at the joint: its bits (0: none; the axis then homes, if at all,
  // against a hard stop) and the raw angle at which the joint is at 0 deg, measured on each built head
  // (the magnet is bonded at any angle) and kept in the board's settings flash.
  uint8_t joint_encoder_bits;
  bool joint_zero_stored;
  uint16_t joint_zero;
  // > 0: the axis's position is closed on its joint encoder (rg_joint_loop.h), the motor loop's reference corrected
  // by at most this many counts before joint_encoder_mismatch stops it; 0: the motor encoder's position is the axis's.
  int32_t joint_correction_limit;
  rg_pid_gains_t pid;
  rg_homing_config_t homing;
} rg_axis_params_t;

typedef struct {
  uint8_t address;
  uint8_t board_id;              // the head-table address the firmware was built for (bootloader_identify)
  uint8_t coupling;              // RG_COUPLING_*
  int8_t counts_m2a[2][2];       // axis counts = counts_m2a x motor counts
  rg_axis_params_t axes[2];
  uint16_t pwm_full_scale;       // PWM steps of 100 % duty
  uint32_t control_period_us;
  uint16_t velocity_timeout_ms;
  uint8_t protocol_major, protocol_minor;
  uint32_t broadcast_policy;     // after reset
} rg_board_params_t;

typedef struct {
  bool present;
  uint8_t mode;                  // ROBOGENE_CAN_CONTROL_MODE_*
  uint8_t faults;                // ROBOGENE_CAN_AXIS_FAULTS_*
  rg_trajectory_t traj;
  float velocity_command;        // counts/s
  uint32_t velocity_command_tick;
  float min, max, max_velocity;  // counts, counts/s
  rg_pid_gains_t pid;
  rg_pid_state_t pid_state;
  int16_t output;                // PWM steps, before mixing to the motors
  int32_t offset;                // counts added by set_encoder_position and homing
  int32_t motor_position;        // counts from the motor encoder(s), offset added: what the position PID runs on
  int32_t measured;              // counts, the axis's position as reported: its joint encoder's when closed on it
                                 // (rg_joint_loop.h), else motor_position
  float speed, accel;            // filtered, counts/s and counts/s^2
  rg_homing_config_t homing_config;
  rg_homing_t homing;
  // The joint encoder (axes with joint_encoder_bits only): its frames, and whether the axis has taken
  // its position from it. Until it has, the axis is not_configured and refuses every control mode.
  rg_joint_encoder_t joint_encoder;
  bool joint_homed;
  bool joint_out_of_range;       // the encoder's angle, less the zero, lies outside the joint's range
  // The joint loop (rg_joint_loop.h): closed on the joint encoder this period, the joint's position from it, the
  // correction added to the motor loop's reference, and the joint's last error (counts).
  bool joint_loop;
  float joint_position;
  float joint_correction;
  float joint_error;
} rg_axis_t;

typedef struct {
  rg_encoder_t encoder;
  int32_t current_limit_ma;      // the run limit (table, set_current_limit)
  int32_t active_limit_ma;       // what the limiter held this period: the run limit, or lower while homing
  float duty_cap;                // the current limiter's ceiling, PWM steps
  uint32_t overcurrent_periods;
  int32_t last_current_ma;
  bool has_brake;
  bool bridge_on;                // the bridge was enabled in the last control period
} rg_motor_t;

typedef struct rg_board {
  const rg_hal_t *hal;
  rg_board_params_t params;
  uint8_t address;
  uint32_t policy;
  uint32_t tick;                 // control periods since start
  rg_axis_t axes[2];
  rg_motor_t motors[2];
  uint8_t board_flags;
  uint32_t last_sent[6];         // tick of each broadcast type's last send
  bool sent_once[6];
  uint8_t last_status[8];
  uint32_t rejected_frames;      // commands with a wrong length or an unknown code
} rg_board_t;

// Starts a board at `params->address` with its axes idle where the encoders are now.
void rg_board_init(rg_board_t *b, const rg_board_params_t *params, const rg_hal_t *hal);
// Handles one received frame; frames not for this board are ignored. Replies go out through
// hal->can_send at once.
void rg_board_receive(rg_board_t *b, const rg_can_frame_t *frame);
// One control period: encoders, faults, trajectories, position loops, current limiters, PWM,
// broadcasts.
void rg_board_tick(rg_board_t *b);
// The firmware reports a control period that overran its budget (status board flag).
void rg_board_note_overrun(rg_board_t *b);

// Applies the holding brakes, then turns both bridges off (enter_bootloader and any other stop
// that cannot wait for the next control period).
void rg_board_stop_motors(rg_board_t *b);

// Seconds of one control period.
float rg_board_period_s(const rg_board_t *b);

// The application's part of the bootloader class (rg_board_boot.c): bootloader_identify and
// enter_bootloader, from the host to this board or to all.
void rg_board_receive_bootloader(rg_board_t *b, const rg_can_frame_t *frame);

// Used by the protocol and homing code.
void rg_board_set_mode(rg_board_t *b, unsigned axis, uint8_t mode);
void rg_board_shift_position(rg_board_t *b, unsigned axis, int32_t position);

#ifdef __cplusplus
}
#endif

#endif  // RG_BOARD_H
