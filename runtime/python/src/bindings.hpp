// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// One function per binding file; module.cpp calls them in dependency order.
#pragma once

#include <pybind11/pybind11.h>

namespace robogene::python {

void bind_bottle(pybind11::module_& m);

}  // namespace robogene::python
