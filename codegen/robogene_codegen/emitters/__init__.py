# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""One emitter per target; each turns the checked model into {relative path: text}."""
from . import board_config, cpp_can, cpp_dispatch, dbc, markdown_can, cpp_interfaces, markdown, pybind, python_can, python_interfaces, svd_c

# The order only decides the order of error messages; outputs never overlap.
EMITTERS = (cpp_interfaces, cpp_dispatch, pybind, python_interfaces, markdown, cpp_can, python_can, board_config, dbc, markdown_can,
            svd_c)

__all__ = ["EMITTERS"]
