// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// One function per binding file; module.cpp calls them in dependency order.
#pragma once

#include <pybind11/pybind11.h>

#include "robogene/bottle.hpp"

namespace robogene::python {

void bind_bottle(pybind11::module_& m);
void bind_float_buffers(pybind11::class_<Bottle>& bottle);
void bind_contact(pybind11::module_& m);
void bind_network(pybind11::module_& m);
void bind_port(pybind11::module_& m);
void bind_buffered_port(pybind11::module_& m);
void bind_rpc(pybind11::module_& m);
void bind_joint_data(pybind11::module_& m);
// The device layer (bind_devices.cpp, with the generated generated/bind_interfaces.cpp).
void bind_devices(pybind11::module_& m);
// The generated RPC dispatch and clients of each device service, without ports (bind_device_rpc.cpp).
void bind_device_rpc(pybind11::module_& m);

// A Bottle from a Python sequence, converting each item the way Bottle.add does.
Bottle bottle_from_sequence(const pybind11::handle& seq);

}  // namespace robogene::python
