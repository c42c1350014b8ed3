# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: CERN-OHL-S-2.0
"""Checks a fabricator trusts: solid validity, interference and clearance, mass properties, mesh quality."""
