# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""Robogene's interface compiler: reads interfaces/idl/*.yaml and writes the generated sources."""
