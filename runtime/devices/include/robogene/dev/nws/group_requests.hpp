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
//   [get] [dong] n (j...)         ->  [get] [don] j, answered with one int, the AND of the joints'
//                                     (a YARP proxy's checkMotionDone() of all its joints)
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

// The single-joint queries of a group query whose answer is one bool for all its joints, or nullopt
// when `request` is not one ([get] [dong] n (j...)); counts that disagree give an empty list.
std::optional<std::vector<Bottle>> expand_group_query(const Bottle& request);

// The group query's reply from its joints' replies ([is] [don] <0|1> [tsta] n t [ok] each):
// [is] <group vocab> <AND of the values> and the last reply's stamp, or [fail] when any failed.
Bottle combine_group_replies(const Bottle& request, const std::vector<Bottle>& replies);

}  // namespace robogene::dev
