// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// How the name server tells a live registration from a stale one (its owner crashed without
// unregistering). The network probe lives in tcp_liveness_probe.hpp; tests inject their own.
#pragma once

#include "robogene/name/registration.hpp"

namespace robogene::name {

enum class Liveness {
  Alive,    // something answered as a port
  Dead,     // refused, or answered but not as a port: the entry is stale
  Unknown,  // could not tell (timeout, unreachable network): keep the entry
};

class LivenessProbe {
 public:
  virtual ~LivenessProbe() = default;
  virtual Liveness probe(const Registration& r) = 0;
};

}  // namespace robogene::name
