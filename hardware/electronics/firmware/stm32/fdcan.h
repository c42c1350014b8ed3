// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// FDCAN1 as a classic CAN 2.0 node at 1 Mbit/s from the 8 MHz crystal, with hardware filters that
// pass only the host's commands to this board (classes 0 and 7, source 0, destination = address or 15).
#ifndef FDCAN_H
#define FDCAN_H

#include <stdbool.h>
#include <stdint.h>

#include "rg_hal.h"

void fdcan_init(uint8_t address);
bool fdcan_receive(rg_can_frame_t *frame);
bool fdcan_send(const rg_can_frame_t *frame);
// Waits until the transmit FIFO has sent everything queued, or about `max_us` microseconds at
// most (a bus with no other node never acknowledges); true when it emptied.
bool fdcan_flush(uint32_t max_us);
// Leaves bus-off (the controller stops itself there); true when it was bus-off.
bool fdcan_recover(void);
// Error counters and the protocol's CAN status bits (rx_warning: error warning, rx_error: error
// passive, hardware_overrun: a frame lost to a full receive FIFO since the last call).
void fdcan_errors(uint8_t *tx_errors, uint8_t *rx_errors, uint8_t *status);

#endif  // FDCAN_H
