// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// The board revision the firmware is built for, an ASCII letter. The build passes it from the one
// place it is written, hardware/electronics/generator/design.py (REVISION), so the image header,
// bootloader_identify and the board's silkscreen cannot disagree.
#ifndef RG_REVISION_H
#define RG_REVISION_H

#ifndef ROBOGENE_BOARD_REVISION
#error "build with -DROBOGENE_BOARD_REVISION=<letter code> (REVISION of hardware/electronics/generator/design.py)"
#endif

#endif  // RG_REVISION_H
