// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// The head's generated board configuration, as the tests read it.
#pragma once

#include <string>

#include "robogene/can/head_config.hpp"
#include "robogene/dev/property.hpp"

namespace robogene::can::testing {

inline std::string head_ini_path() { return std::string(ROBOGENE_SOURCE_DIR) + "/drivers/can/generated/head.ini"; }

inline HeadConfig head_config() { return read_head_config(dev::Property::from_ini_file(head_ini_path())); }

}  // namespace robogene::can::testing
