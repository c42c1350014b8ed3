// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// The firmware core's parameters of one board, from head.ini: what the generated firmware table
// (robogene_head_board_config.h) gives the board's image, derived here from the same parameter
// file's other output, so the simulated board runs with the real board's numbers.
#pragma once

#include <cstddef>

#include "rg_board.h"
#include "robogene/can/head_config.hpp"

namespace robogene::can::sim {

// Throws robogene::Error when the board cannot run on the firmware (a coupling it does not
// implement, a value that does not fit the firmware's field).
rg_board_params_t core_params(const HeadConfig& head, const BoardConfig& board);
// Motor encoder counts per degree of the joint for motor m (4 x lines x reduction / 360).
double motor_counts_per_degree(const HeadConfig& head, const BoardConfig& board, std::size_t m);

}  // namespace robogene::can::sim
