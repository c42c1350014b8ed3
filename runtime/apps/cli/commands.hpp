// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// The sub-commands of `robogene`. Each returns the exit status; errors are thrown (UsageError
// for the command line, robogene::Error for everything else) and reported by main.
#pragma once

#include "cli_support.hpp"

namespace robogene::cli {

int cmd_server(Args& args);
int cmd_name(Args& args);
int cmd_read(Args& args);
int cmd_write(Args& args);
int cmd_rpc(Args& args);
int cmd_connect(Args& args);
int cmd_disconnect(Args& args);
int cmd_ping(Args& args);
int cmd_ls(Args& args);
int cmd_dev(Args& args);
int cmd_can_sim(Args& args);
int cmd_can_home(Args& args);
int cmd_can_zero(Args& args);
int cmd_can_flash(Args& args);
int cmd_detect(Args& args);

}  // namespace robogene::cli
