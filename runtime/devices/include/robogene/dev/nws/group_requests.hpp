// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// YARP 3's joint-group forms, which the IDL does not describe: a YARP controlboardwrapper2
// serving a remote_controlboard turns every all-joints call into one, so a YARP proxy of our
// server sends them. The control board server expands each into the single-joint requests the
// generated dispatch knows (reference sections 5.3 and 5.5):
//   [set] [posg] n (j...) (v...)  ->  [set] [pos] j v   (also relg, velg, accg, vmog, dpog)
//   [set] [stog] n (j...)         ->  [set] [sto] j
//   ([vmog] n (j...)) (v...)      ->  [set] [vmo] j v   on the command port (also posg, dpog)
#pragma once

#include <optional>
#include <vector>

#include "robogene/bottle.hpp"

namespace robogene::dev {

// The single-joint requests of a group request, or nullopt when `request` is not one. A group
// request whose counts disagree expands to an empty list (refused by the caller).
std::optional<std::vector<Bottle>> expand_group_request(const Bottle& request);

// The same for a command-port message ((head...) (values...)).
std::optional<std::vector<Bottle>> expand_group_command(const Bottle& message);

}  // namespace robogene::dev
