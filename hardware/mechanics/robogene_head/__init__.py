# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: CERN-OHL-S-2.0
"""Parametric CAD, kinematics and checks of the Robogene 6-DOF head.

Everything is derived from hardware/head-parameters.yaml (see params.load)."""
