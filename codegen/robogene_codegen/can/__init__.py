# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""CAN protocols and board configurations described in the IDL (`can_protocol:`, `board_config:`)."""
