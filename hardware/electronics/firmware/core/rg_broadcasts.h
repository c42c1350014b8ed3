// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// The periodic messages (class 1) a board sends when its broadcast policy enables them, each at
// its protocol period; the status also at once whenever a mode or fault changes.
#ifndef RG_BROADCASTS_H
#define RG_BROADCASTS_H

struct rg_board;

void rg_send_broadcasts(struct rg_board *b);

#endif  // RG_BROADCASTS_H
