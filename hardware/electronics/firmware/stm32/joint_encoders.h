// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// The two AS5048A joint encoders on SPI1 (J22 and J32 of the board, level-shifted): SCK on PB3, the shared
// data line on PB4 (pulled low by R8: a missing encoder reads 0x0000), each encoder's chip select a
// GPIO (axis 0: PA15, axis 1: PA5; 10 k pull-ups). MOSI is not wired to a pin since revision D: R11
// holds the encoders' input high, so every frame they receive is 0xFFFF, read angle.
#ifndef JOINT_ENCODERS_H
#define JOINT_ENCODERS_H

#include <stdint.h>

// SPI1 as master, 16-bit frames, mode 1 (CPOL 0, CPHA 1), PCLK2 / 16 = 9.4 MHz (the AS5048A takes
// at most 10 MHz); both chip selects driven high (deselected).
void joint_encoders_init(void);
// One frame from axis 0's or 1's encoder: select, clock 16 bits out of it, deselect. The answer is to
// the frame before (the sensor answers each command in the next one). 0x8000 (bad parity) if the
// peripheral did not complete the frame.
uint16_t joint_encoders_frame(unsigned axis);

#endif  // JOINT_ENCODERS_H
