// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// Whether a browser's request to write to a port was sent by a page of another site (private
// to src/carrier). With ROBOGENE_HTTP_WRITES=1 an allowed machine's browser may write; the page
// it shows may not make it write for that page: a cross-site form or <img> (CSRF), or a page
// whose own host name has been pointed at the robot (DNS rebinding, which makes the page
// same-origin with the port). docs/security.md gives the rules.
#pragma once

#include <string>
#include <vector>

#include "http_request.hpp"

namespace robogene::carrier::detail {

// Why `r` must not write, or "" when nothing says it comes from another site. `machine_names`:
// the host names this machine answers to (besides addresses and "localhost").
std::string cross_site_reason(const HttpRequest& r, const std::vector<std::string>& machine_names);

// This machine's names: its host name, the same without the domain, and with ".local" (mDNS).
std::vector<std::string> this_machine_names();

}  // namespace robogene::carrier::detail
