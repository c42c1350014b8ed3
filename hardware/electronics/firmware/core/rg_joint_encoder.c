// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "rg_joint_encoder.h"

#include <string.h>

static bool even_parity(uint16_t frame) {
  unsigned ones = 0;
  for (uint16_t v = frame; v != 0u; v = (uint16_t)(v & (v - 1u))) ++ones;
  return (ones & 1u) == 0u;
}

rg_as5048a_frame_status_t rg_as5048a_decode(uint16_t frame, uint16_t *angle) {
  if (!even_parity(frame)) return RG_AS5048A_FRAME_BAD_PARITY;
  if (frame & RG_AS5048A_ERROR_FLAG) return RG_AS5048A_FRAME_ERROR_FLAG;
  *angle = (uint16_t)(frame & RG_AS5048A_ANGLE_MASK);
  return RG_AS5048A_FRAME_OK;
}

uint16_t rg_as5048a_frame(uint16_t angle, bool error_flag) {
  uint16_t frame = (uint16_t)((angle & RG_AS5048A_ANGLE_MASK) | (error_flag ? RG_AS5048A_ERROR_FLAG : 0u));
  if (!even_parity(frame)) frame |= RG_AS5048A_PARITY_BIT;
  return frame;
}

void rg_joint_encoder_start(rg_joint_encoder_t *e) {
  memset(e, 0, sizeof *e);
  e->state = RG_JOINT_ENCODER_STARTING;
}

static uint16_t inc(uint16_t v) { return v == UINT16_MAX ? v : (uint16_t)(v + 1u); }

uint8_t rg_joint_encoder_update(rg_joint_encoder_t *e, uint16_t frame) {
  e->last_frame = frame;
  uint16_t angle = 0;
  if (rg_as5048a_decode(frame, &angle) != RG_AS5048A_FRAME_OK) {
    e->bad_frames = inc(e->bad_frames);
    e->bad_run = inc(e->bad_run);
    e->good_run = 0;
    e->zero_run = 0;
    if (e->bad_run >= RG_JOINT_ENCODER_BAD_FRAMES) e->state = RG_JOINT_ENCODER_FAILED;
    return e->state;
  }
  e->bad_run = 0;
  if (frame == 0u) {
    // The missing encoder's pulled-down line, or a live sensor exactly at 0: trusted only once it moves.
    e->good_run = 0;
    e->zero_run = inc(e->zero_run);
    if (e->zero_run >= RG_JOINT_ENCODER_ZERO_FRAMES) {
      e->state = RG_JOINT_ENCODER_ABSENT;
    } else if (e->state == RG_JOINT_ENCODER_FAILED) {
      e->state = RG_JOINT_ENCODER_STARTING;
    }
    return e->state;
  }
  e->zero_run = 0;
  e->angle = angle;
  e->good_run = inc(e->good_run);
  if (e->good_run >= RG_JOINT_ENCODER_GOOD_FRAMES) {
    e->state = RG_JOINT_ENCODER_OK;
  } else if (e->state != RG_JOINT_ENCODER_OK) {
    e->state = RG_JOINT_ENCODER_STARTING;
  }
  return e->state;
}
