// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// The host's commands (class 0) to a board, from the generated protocol header: each checked
// for its data length, applied to the addressed axis, and answered when the command has a reply.
#include <math.h>
#include <string.h>

#include "rg_board.h"
#include "rg_joint_homing.h"
#include "rg_joint_loop.h"
#include "rg_wire.h"
#include "generated/robogene_can_motor_control.h"

typedef struct {
  rg_board_t *b;
  const rg_can_frame_t *in;
  unsigned axis;
  rg_axis_t *a;
} command_t;

static void reply(const command_t *c, const uint8_t *payload, uint8_t len) {
  rg_can_frame_t f;
  f.id = (uint16_t)ROBOGENE_CAN_ID(ROBOGENE_CAN_CLASS_POLLING_MOTOR_CONTROL, c->b->address,
                                   (c->in->id & ROBOGENE_CAN_SOURCE_MASK) >> ROBOGENE_CAN_SOURCE_SHIFT);
  f.len = len;
  memset(f.data, 0, sizeof f.data);
  f.data[0] = c->in->data[0];  // the command byte, axis bit included
  memcpy(f.data + 1, payload, (size_t)len - 1u);
  (void)c->b->hal->can_send(c->b->hal->ctx, &f);
}

static void reply_i32(const command_t *c, int32_t v) {
  uint8_t p[4];
  rg_put_i32(p, v);
  reply(c, p, 5);
}

static void reply_i16(const command_t *c, int16_t v) {
  uint8_t p[2];
  rg_put_i16(p, v);
  reply(c, p, 3);
}

static bool known_mode(uint8_t m) {
  return m == ROBOGENE_CAN_CONTROL_MODE_IDLE || m == ROBOGENE_CAN_CONTROL_MODE_POSITION ||
         m == ROBOGENE_CAN_CONTROL_MODE_VELOCITY || m == ROBOGENE_CAN_CONTROL_MODE_FORCE_IDLE;
}

static void set_control_mode(const command_t *c, uint8_t mode) {
  rg_axis_t *a = c->a;
  // An axis whose joint encoder has not given it its position stays not_configured: no loop may run
  // on a zero that is wherever the motor encoder started.
  if (rg_joint_homing_blocks(c->b, c->axis)) {
    if (mode == ROBOGENE_CAN_CONTROL_MODE_FORCE_IDLE) a->faults = 0;
    return;
  }
  if (mode == ROBOGENE_CAN_CONTROL_MODE_FORCE_IDLE) {
    a->faults = 0;  // leave the fault; a condition still present is reported again next period
    rg_board_set_mode(c->b, c->axis, ROBOGENE_CAN_CONTROL_MODE_IDLE);
    return;
  }
  // Modes this board does not implement, and any mode but force_idle in a fault, change nothing.
  if (!known_mode(mode) || a->mode == ROBOGENE_CAN_CONTROL_MODE_HARDWARE_FAULT) return;
  if (a->mode == mode) return;  // already there: keep the move in progress
  rg_board_set_mode(c->b, c->axis, mode);
}

static void firmware_version(const command_t *c) {
  const rg_board_params_t *p = &c->b->params;
  const uint8_t major = c->in->data[ROBOGENE_CAN_GET_FIRMWARE_VERSION_PROTOCOL_MAJOR_BYTE];
  const uint8_t minor = c->in->data[ROBOGENE_CAN_GET_FIRMWARE_VERSION_PROTOCOL_MINOR_BYTE];
  uint8_t r[ROBOGENE_CAN_LEN_GET_FIRMWARE_VERSION_REPLY];
  r[ROBOGENE_CAN_GET_FIRMWARE_VERSION_REPLY_BOARD_TYPE_BYTE] = ROBOGENE_CAN_BOARD_TYPE_ROBOGENE_MOTOR_BOARD;
  r[ROBOGENE_CAN_GET_FIRMWARE_VERSION_REPLY_FIRMWARE_VERSION_BYTE] = RG_FIRMWARE_VERSION;
  r[ROBOGENE_CAN_GET_FIRMWARE_VERSION_REPLY_FIRMWARE_REVISION_BYTE] = RG_FIRMWARE_REVISION;
  r[ROBOGENE_CAN_GET_FIRMWARE_VERSION_REPLY_FIRMWARE_BUILD_BYTE] = RG_FIRMWARE_BUILD;
  r[ROBOGENE_CAN_GET_FIRMWARE_VERSION_REPLY_PROTOCOL_MAJOR_BYTE] = p->protocol_major;
  r[ROBOGENE_CAN_GET_FIRMWARE_VERSION_REPLY_PROTOCOL_MINOR_BYTE] = p->protocol_minor;
  r[ROBOGENE_CAN_GET_FIRMWARE_VERSION_REPLY_COMPATIBLE_BYTE] =
      (uint8_t)(major == p->protocol_major && minor <= p->protocol_minor);
  reply(c, r + 1, sizeof r);
}

static void joint_encoder(const command_t *c) {
  const rg_axis_params_t *p = &c->b->params.axes[c->axis];
  const rg_joint_encoder_t *e = &c->a->joint_encoder;
  const bool has = p->joint_encoder_bits > 0u;
  uint8_t r[ROBOGENE_CAN_LEN_GET_JOINT_ENCODER_REPLY] = {0};
  rg_put_u16(r + ROBOGENE_CAN_GET_JOINT_ENCODER_REPLY_RAW_ANGLE_BYTE, has ? e->angle : 0u);
  r[ROBOGENE_CAN_GET_JOINT_ENCODER_REPLY_STATE_BYTE] = has ? e->state : ROBOGENE_CAN_JOINT_ENCODER_STATE_NONE;
  rg_put_u16(r + ROBOGENE_CAN_GET_JOINT_ENCODER_REPLY_ZERO_BYTE, p->joint_zero);
  r[ROBOGENE_CAN_GET_JOINT_ENCODER_REPLY_ZERO_STORED_BYTE] = (uint8_t)p->joint_zero_stored;
  r[ROBOGENE_CAN_GET_JOINT_ENCODER_REPLY_HOMED_BYTE] = (uint8_t)(has && c->a->joint_homed);
  reply(c, r + 1, sizeof r);
}

// The request's data length for each command code; 0 for codes this board does not know.
static uint8_t request_length(unsigned code) {
  switch (code) {
#define RG_CMD(NAME) \
  case ROBOGENE_CAN_CMD_##NAME: return ROBOGENE_CAN_LEN_##NAME;
    RG_CMD(GET_CONTROL_MODE) RG_CMD(MOTION_DONE) RG_CMD(SET_CONTROL_MODE) RG_CMD(GET_ENCODER_POSITION)
    RG_CMD(GET_DESIRED_POSITION) RG_CMD(SET_DESIRED_ACCELERATION) RG_CMD(GET_DESIRED_ACCELERATION)
    RG_CMD(POSITION_MOVE) RG_CMD(VELOCITY_MOVE) RG_CMD(SET_ENCODER_POSITION) RG_CMD(STOP_TRAJECTORY)
    RG_CMD(SET_BOARD_ID) RG_CMD(GET_BOARD_ID) RG_CMD(GET_PID_OUTPUT) RG_CMD(SET_MIN_POSITION)
    RG_CMD(GET_MIN_POSITION) RG_CMD(SET_MAX_POSITION) RG_CMD(GET_MAX_POSITION) RG_CMD(SET_MAX_VELOCITY)
    RG_CMD(GET_MAX_VELOCITY) RG_CMD(SET_CURRENT_LIMIT) RG_CMD(SET_BROADCAST_POLICY) RG_CMD(SET_POSITION_PID)
    RG_CMD(GET_POSITION_PID) RG_CMD(SET_POSITION_PID_LIMITS) RG_CMD(GET_POSITION_PID_LIMITS)
    RG_CMD(SET_VELOCITY_TIMEOUT) RG_CMD(GET_FIRMWARE_VERSION) RG_CMD(CALIBRATE_ENCODER)
    RG_CMD(SET_JOINT_ENCODER_ZERO) RG_CMD(GET_JOINT_ENCODER)
#undef RG_CMD
    default:
      return 0;
  }
}

static void execute(const command_t *c, unsigned code) {
  rg_board_t *b = c->b;
  rg_axis_t *a = c->a;
  const uint8_t *d = c->in->data;
  switch (code) {
    case ROBOGENE_CAN_CMD_GET_CONTROL_MODE: {
      const uint8_t m = a->mode;
      reply(c, &m, ROBOGENE_CAN_LEN_GET_CONTROL_MODE_REPLY);
      break;
    }
    case ROBOGENE_CAN_CMD_SET_CONTROL_MODE:
      set_control_mode(c, d[ROBOGENE_CAN_SET_CONTROL_MODE_MODE_BYTE]);
      break;
    case ROBOGENE_CAN_CMD_MOTION_DONE: {
      const uint8_t done = (uint8_t)(a->traj.done && a->mode != ROBOGENE_CAN_CONTROL_MODE_CALIBRATION);
      reply(c, &done, ROBOGENE_CAN_LEN_MOTION_DONE_REPLY);
      break;
    }
    case ROBOGENE_CAN_CMD_GET_ENCODER_POSITION: {
      uint8_t p[6];
      rg_put_i32(p, a->measured);
      rg_put_i16(p + 4, rg_scaled_i16(a->speed, (float)ROBOGENE_CAN_GET_ENCODER_POSITION_REPLY_SPEED_SCALE));
      reply(c, p, ROBOGENE_CAN_LEN_GET_ENCODER_POSITION_REPLY);
      break;
    }
    case ROBOGENE_CAN_CMD_GET_DESIRED_POSITION:
      reply_i32(c, rg_counts_i32(a->traj.target));
      break;
    case ROBOGENE_CAN_CMD_SET_DESIRED_ACCELERATION: {
      const int16_t raw = rg_get_i16(d + ROBOGENE_CAN_SET_DESIRED_ACCELERATION_ACCELERATION_BYTE);
      if (raw > 0) a->traj.acceleration = (float)raw * (float)ROBOGENE_CAN_SET_DESIRED_ACCELERATION_ACCELERATION_SCALE;
      break;
    }
    case ROBOGENE_CAN_CMD_GET_DESIRED_ACCELERATION:
      reply_i16(c, rg_scaled_i16(a->traj.acceleration, 1000.0f));
      break;
    case ROBOGENE_CAN_CMD_POSITION_MOVE: {
      if (a->mode != ROBOGENE_CAN_CONTROL_MODE_POSITION) break;  // only in position mode
      const int32_t position = rg_get_i32(d + ROBOGENE_CAN_POSITION_MOVE_POSITION_BYTE);
      const float speed = (float)rg_get_i16(d + ROBOGENE_CAN_POSITION_MOVE_SPEED_BYTE) * 10.0f;
      a->traj.target = rg_clampf((float)position, a->min, a->max);
      a->traj.move_speed = rg_clampf(fabsf(speed), 10.0f, a->max_velocity);
      a->traj.done = false;
      break;
    }
    case ROBOGENE_CAN_CMD_VELOCITY_MOVE: {
      if (a->mode != ROBOGENE_CAN_CONTROL_MODE_VELOCITY) break;
      const float speed = (float)rg_get_i16(d + ROBOGENE_CAN_VELOCITY_MOVE_SPEED_BYTE) * 10.0f;
      const int16_t acc = rg_get_i16(d + ROBOGENE_CAN_VELOCITY_MOVE_ACCELERATION_BYTE);
      a->velocity_command = rg_clampf(speed, -a->max_velocity, a->max_velocity);
      if (acc > 0) a->traj.acceleration = (float)acc * 1000.0f;
      a->velocity_command_tick = b->tick;
      break;
    }
    case ROBOGENE_CAN_CMD_SET_ENCODER_POSITION:
      // An axis closed on its joint encoder has the joint's position, whose zero is the stored one
      // (set_joint_encoder_zero): shifting its motor's counts would only be taken for a mismatch.
      if (rg_joint_loop_configured(b, c->axis)) break;
      rg_board_shift_position(b, c->axis, rg_get_i32(d + ROBOGENE_CAN_SET_ENCODER_POSITION_POSITION_BYTE));
      break;
    case ROBOGENE_CAN_CMD_STOP_TRAJECTORY:
      a->traj.target = a->traj.ref;
      a->velocity_command = 0.0f;
      break;
    case ROBOGENE_CAN_CMD_SET_BOARD_ID: {
      const uint8_t address = d[ROBOGENE_CAN_SET_BOARD_ID_ADDRESS_BYTE];
      if (address >= ROBOGENE_CAN_FIRST_BOARD_ADDRESS && address <= ROBOGENE_CAN_LAST_BOARD_ADDRESS) {
        b->address = address;
        if (b->hal->save_address) b->hal->save_address(b->hal->ctx, address);
      }
      break;
    }
    case ROBOGENE_CAN_CMD_GET_BOARD_ID:
      reply(c, &b->address, ROBOGENE_CAN_LEN_GET_BOARD_ID_REPLY);
      break;
    case ROBOGENE_CAN_CMD_GET_PID_OUTPUT:
      reply_i16(c, a->output);
      break;
    case ROBOGENE_CAN_CMD_SET_MIN_POSITION:
      a->min = (float)rg_get_i32(d + ROBOGENE_CAN_SET_MIN_POSITION_POSITION_BYTE);
      break;
    case ROBOGENE_CAN_CMD_GET_MIN_POSITION:
      reply_i32(c, rg_counts_i32(a->min));
      break;
    case ROBOGENE_CAN_CMD_SET_MAX_POSITION:
      a->max = (float)rg_get_i32(d + ROBOGENE_CAN_SET_MAX_POSITION_POSITION_BYTE);
      break;
    case ROBOGENE_CAN_CMD_GET_MAX_POSITION:
      reply_i32(c, rg_counts_i32(a->max));
      break;
    case ROBOGENE_CAN_CMD_SET_MAX_VELOCITY: {
      const int16_t raw = rg_get_i16(d + ROBOGENE_CAN_SET_MAX_VELOCITY_SPEED_BYTE);
      if (raw > 0) a->max_velocity = (float)raw * 10.0f;
      break;
    }
    case ROBOGENE_CAN_CMD_GET_MAX_VELOCITY:
      reply_i16(c, rg_scaled_i16(a->max_velocity, 10.0f));
      break;
    case ROBOGENE_CAN_CMD_SET_CURRENT_LIMIT: {
      const int32_t ma = rg_get_i32(d + ROBOGENE_CAN_SET_CURRENT_LIMIT_CURRENT_BYTE);
      if (ma > 0) b->motors[c->axis].current_limit_ma = ma;
      break;
    }
    case ROBOGENE_CAN_CMD_SET_BROADCAST_POLICY:
      b->policy = rg_get_u32(d + ROBOGENE_CAN_SET_BROADCAST_POLICY_MASK_BYTE);
      break;
    case ROBOGENE_CAN_CMD_SET_POSITION_PID: {
      a->pid.kp = rg_get_i16(d + ROBOGENE_CAN_SET_POSITION_PID_KP_BYTE);
      a->pid.ki = rg_get_i16(d + ROBOGENE_CAN_SET_POSITION_PID_KI_BYTE);
      a->pid.kd = rg_get_i16(d + ROBOGENE_CAN_SET_POSITION_PID_KD_BYTE);
      const uint8_t shift = d[ROBOGENE_CAN_SET_POSITION_PID_SHIFT_BYTE];
      a->pid.shift = shift > 15u ? 15u : shift;
      break;
    }
    case ROBOGENE_CAN_CMD_GET_POSITION_PID: {
      uint8_t p[7];
      rg_put_i16(p, a->pid.kp);
      rg_put_i16(p + 2, a->pid.ki);
      rg_put_i16(p + 4, a->pid.kd);
      p[6] = a->pid.shift;
      reply(c, p, ROBOGENE_CAN_LEN_GET_POSITION_PID_REPLY);
      break;
    }
    case ROBOGENE_CAN_CMD_SET_POSITION_PID_LIMITS:
      a->pid.offset = rg_get_i16(d + ROBOGENE_CAN_SET_POSITION_PID_LIMITS_OFFSET_BYTE);
      a->pid.output_limit = rg_get_i16(d + ROBOGENE_CAN_SET_POSITION_PID_LIMITS_OUTPUT_LIMIT_BYTE);
      a->pid.integral_limit = rg_get_i16(d + ROBOGENE_CAN_SET_POSITION_PID_LIMITS_INTEGRAL_LIMIT_BYTE);
      break;
    case ROBOGENE_CAN_CMD_GET_POSITION_PID_LIMITS: {
      uint8_t p[7] = {0};
      rg_put_i16(p, a->pid.offset);
      rg_put_i16(p + 2, a->pid.output_limit);
      rg_put_i16(p + 4, a->pid.integral_limit);
      reply(c, p, ROBOGENE_CAN_LEN_GET_POSITION_PID_LIMITS_REPLY);
      break;
    }
    case ROBOGENE_CAN_CMD_SET_VELOCITY_TIMEOUT: {
      const int16_t ms = rg_get_i16(d + ROBOGENE_CAN_SET_VELOCITY_TIMEOUT_TIMEOUT_BYTE);
      if (ms > 0) b->params.velocity_timeout_ms = (uint16_t)ms;
      break;
    }
    case ROBOGENE_CAN_CMD_GET_FIRMWARE_VERSION:
      firmware_version(c);
      break;
    case ROBOGENE_CAN_CMD_SET_JOINT_ENCODER_ZERO:
      (void)rg_joint_homing_set_zero(b, c->axis, rg_get_u16(d + ROBOGENE_CAN_SET_JOINT_ENCODER_ZERO_ZERO_BYTE));
      break;
    case ROBOGENE_CAN_CMD_GET_JOINT_ENCODER:
      joint_encoder(c);
      break;
    case ROBOGENE_CAN_CMD_CALIBRATE_ENCODER: {
      if (d[ROBOGENE_CAN_CALIBRATE_ENCODER_TYPE_BYTE] != ROBOGENE_CAN_CALIBRATION_TYPE_HARD_STOP) break;
      const int16_t pwm = rg_get_i16(d + ROBOGENE_CAN_CALIBRATE_ENCODER_PWM_BYTE);
      const int16_t speed = rg_get_i16(d + ROBOGENE_CAN_CALIBRATE_ENCODER_SPEED_BYTE);
      (void)rg_homing_start(b, c->axis, pwm, fabsf((float)speed * 10.0f));
      break;
    }
    default:
      break;
  }
}

void rg_board_receive(rg_board_t *b, const rg_can_frame_t *frame) {
  const unsigned message_class = (frame->id & ROBOGENE_CAN_MESSAGE_CLASS_MASK) >> ROBOGENE_CAN_MESSAGE_CLASS_SHIFT;
  const unsigned source = (frame->id & ROBOGENE_CAN_SOURCE_MASK) >> ROBOGENE_CAN_SOURCE_SHIFT;
  const unsigned destination = (frame->id & ROBOGENE_CAN_DESTINATION_MASK) >> ROBOGENE_CAN_DESTINATION_SHIFT;
  if (message_class == ROBOGENE_CAN_CLASS_BOOTLOADER) {
    rg_board_receive_bootloader(b, frame);
    return;
  }
  // Only the host's commands: other boards' replies and broadcasts share the bus.
  if (message_class != ROBOGENE_CAN_CLASS_POLLING_MOTOR_CONTROL || source != ROBOGENE_CAN_HOST_ADDRESS) return;
  if (destination != b->address && destination != ROBOGENE_CAN_BROADCAST_ADDRESS) return;
  if (frame->len < 1u) {
    ++b->rejected_frames;
    return;
  }
  const unsigned code = frame->data[0] & ~ROBOGENE_CAN_AXIS_BIT & 0xFFu;
  const unsigned length = request_length(code);
  if (length == 0u || frame->len != length) {
    ++b->rejected_frames;
    return;
  }
  const unsigned axis = (frame->data[0] & ROBOGENE_CAN_AXIS_BIT) ? 1u : 0u;
  command_t c = {b, frame, axis, &b->axes[axis]};
  if (!c.a->present) return;
  execute(&c, code);
}
