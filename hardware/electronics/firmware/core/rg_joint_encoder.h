// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// An axis's absolute joint encoder, an ams AS5048A on SPI (docs/firmware.md, "Joint encoders"): its
// 16-bit read frame decoded, and whether the frames an axis has received can be trusted.
//
// A read frame is bit 15 even parity over the whole frame, bit 14 the error flag (a fault in an
// earlier command frame), bits 13..0 the angle. The board sends 0xFFFF on every frame (read the angle
// register 0x3FFF; MOSI is held high by a resistor), so each frame answers the frame before it.
//
// Two failures look like frames: a frame damaged on the cable (bad parity), and the encoder missing or
// unpowered, whose data line the board pulls low: every frame reads 0x0000, which has even parity and
// no error flag, i.e. a valid "angle 0". A live sensor's angle jitters by its noise (up to 2.7 LSB rms)
// and the joint moves, so RG_JOINT_ENCODER_ZERO_FRAMES frames in a row that read exactly 0x0000 are
// taken as no encoder; frames of exactly 0 never count towards trusting the encoder.
#ifndef RG_JOINT_ENCODER_H
#define RG_JOINT_ENCODER_H

#include <stdbool.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

#define RG_AS5048A_READ_ANGLE 0xFFFFu  // the command frame: parity 1, read, address 0x3FFF
#define RG_AS5048A_PARITY_BIT 0x8000u
#define RG_AS5048A_ERROR_FLAG 0x4000u
#define RG_AS5048A_ANGLE_MASK 0x3FFFu

typedef enum {
  RG_AS5048A_FRAME_OK = 0,
  RG_AS5048A_FRAME_BAD_PARITY,
  RG_AS5048A_FRAME_ERROR_FLAG  // parity good, the sensor reports an error in an earlier frame
} rg_as5048a_frame_status_t;

// Decodes a read frame; *angle is set only for a good frame.
rg_as5048a_frame_status_t rg_as5048a_decode(uint16_t frame, uint16_t *angle);
// The frame a sensor sends for `angle` (14 bits), with its parity: what the simulator puts on the wire.
uint16_t rg_as5048a_frame(uint16_t angle, bool error_flag);

// Whether an axis's encoder can be used (the state get_joint_encoder reports; JointEncoderState).
enum {
  RG_JOINT_ENCODER_STARTING = 0,  // too few good frames yet
  RG_JOINT_ENCODER_OK = 1,
  RG_JOINT_ENCODER_ABSENT = 2,    // only 0x0000 for RG_JOINT_ENCODER_ZERO_FRAMES frames
  RG_JOINT_ENCODER_FAILED = 3     // RG_JOINT_ENCODER_BAD_FRAMES bad frames in a row
};

#define RG_JOINT_ENCODER_GOOD_FRAMES 8u   // good non-zero frames in a row before the angle is trusted
#define RG_JOINT_ENCODER_BAD_FRAMES 3u    // bad frames in a row that fail it (one glitch is forgiven)
#define RG_JOINT_ENCODER_ZERO_FRAMES 32u  // frames of exactly 0x0000 in a row that mean no encoder
// Frames rg_board_init reads at once, so the encoder is judged before the first control period.
#define RG_JOINT_ENCODER_STARTUP_FRAMES 40u

typedef struct {
  uint8_t state;
  uint16_t angle;         // the last good angle (raw, 14 bits)
  uint16_t last_frame;    // as received
  uint16_t good_run, zero_run, bad_run;
  uint16_t bad_frames;    // since start, saturating
} rg_joint_encoder_t;

void rg_joint_encoder_start(rg_joint_encoder_t *e);
// Takes one received frame; returns the new state.
uint8_t rg_joint_encoder_update(rg_joint_encoder_t *e, uint16_t frame);

#ifdef __cplusplus
}
#endif

#endif  // RG_JOINT_ENCODER_H
