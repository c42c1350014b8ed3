# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: CERN-OHL-S-2.0
"""Bill of materials of the Robogene head: catalog, quantities from the CAD and the boards, CSV/Markdown/HTML."""
