# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: CERN-OHL-S-2.0
"""The head's wiring harness: cables as data (spec), the boards' connector pinout (pinout), free spans across the
joints checked over their range of motion (spans), cable lengths and checks (plan), WireViz drawing (drawing)."""
