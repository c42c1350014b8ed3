// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// The bootloader's protocol (class 7 of the CAN protocol): identify, erase, write in sequence,
// verify against the image header's CRC, start. The same state machine runs on the board (flash
// HAL on the STM32's FLASH registers, bootloader/) and in `robogene can-sim` (a simulated flash).
// No heap, no globals; frames in through rg_boot_receive(), replies out through the HAL.
#ifndef RG_BOOT_H
#define RG_BOOT_H

#include <stdbool.h>
#include <stdint.h>

#include "rg_hal.h"
#include "rg_image.h"

#ifdef __cplusplus
extern "C" {
#endif

#define RG_BOOT_VERSION_MAJOR 1u
#define RG_BOOT_VERSION_MINOR 0u
#define RG_BOOT_ENTER_KEY 0x544F4F42u  // enter_bootloader's key: "BOOT"
#define RG_BOOT_PROGRAM_UNIT 8u        // the STM32G4 programs 64 bits at a time

// The application region's flash and the rest of the board the bootloader uses. Offsets are
// relative to the region's start (the image's first byte).
typedef struct {
  void *ctx;
  uint32_t region_size;  // bytes of the application region
  uint32_t page_size;    // its erase unit
  // Erases page `page` of the region (offset page * page_size); false on a flash error.
  bool (*erase_page)(void *ctx, uint32_t page);
  // Programs RG_BOOT_PROGRAM_UNIT bytes at an aligned offset erased before; false on an error.
  bool (*program)(void *ctx, uint32_t offset, const uint8_t *data);
  bool (*read)(void *ctx, uint32_t offset, uint8_t *out, uint32_t len);
  bool (*can_send)(void *ctx, const rg_can_frame_t *frame);
  // Called once bootloader_start's reply is queued, for an image that checks: the board restarts
  // into the application (the simulator switches the board over).
  void (*start_application)(void *ctx);
} rg_boot_hal_t;

enum {
  RG_BOOT_IDLE = 0,     // nothing under way; the region holds whatever it held
  RG_BOOT_WRITING = 1,  // erased for `size` bytes, taking writes in sequence
  RG_BOOT_WRITTEN = 2,  // every byte written, waiting for verify
  RG_BOOT_REFUSED = 3,  // the header written names another board or revision: erase again
};

typedef struct {
  const rg_boot_hal_t *hal;
  uint8_t address;            // the CAN address it answers at
  rg_image_target_t target;   // what an image must be built for
  uint8_t state;              // RG_BOOT_*
  bool image_valid;           // the region holds an image rg_image_check accepts
  uint32_t size;              // bytes erased for
  uint16_t next_sequence;     // the write expected
  uint8_t pending[RG_BOOT_PROGRAM_UNIT];
  uint32_t pending_len;
  uint32_t rejected_frames;   // frames with a wrong length or an unknown code
} rg_boot_t;

// Starts the bootloader's protocol; checks the region once (image_valid).
void rg_boot_init(rg_boot_t *b, uint8_t address, const rg_image_target_t *target, const rg_boot_hal_t *hal);
// Handles one received frame; frames not for this board are ignored.
void rg_boot_receive(rg_boot_t *b, const rg_can_frame_t *frame);
// The image check at reset: true when the region holds an image for `target`.
bool rg_boot_image_valid(const rg_boot_hal_t *hal, const rg_image_target_t *target);

#ifdef __cplusplus
}
#endif

#endif  // RG_BOOT_H
