# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""The head's CAN protocol in Python: message dataclasses, encode()/decode() between an Envelope
and a Frame, and the text form shared with the C++ codec. Generated from
interfaces/idl/can_motor_control.yaml (see docs/can-protocol.md).

    >>> from robogene import can
    >>> str(can.encode(can.command(1, 0, can.PositionMove(position=1000, speed=250.0))))
    '001#1BE80300001900'
"""
from .generated.motor_control import *  # noqa: F401,F403  (the protocol's whole API)
