// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// The core's parameters of one board from the generated head table
// (robogene_head_board_config.h), as the firmware starts them.
#ifndef RG_BOARD_CONFIG_H
#define RG_BOARD_CONFIG_H

#include <stdbool.h>
#include <stdint.h>

#include "rg_board.h"

#ifdef __cplusplus
extern "C" {
#endif

// Fills `out` for the board at `can_address`; false when the head has no such board.
bool rg_board_params_for_address(uint8_t can_address, rg_board_params_t *out);

#ifdef __cplusplus
}
#endif

#endif  // RG_BOARD_CONFIG_H
