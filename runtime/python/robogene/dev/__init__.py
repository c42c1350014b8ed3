# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""Devices (paper section 3): the C++ device layer, bound in robogene._core and gathered in
robogene.dev.core. Property, DriverFactory, PolyDriver, the generated interfaces (IEncoders,
IPositionControl...), the network servers (ControlboardNws, GrabberNws), the RPC halves of each
service (ControlboardServer, ControlboardClient...) and the image and jointData codecs are the C++
ones; the drivers (test_motor, fake_grabber, remote_controlboard...) are opened by name through
PolyDriver. A device written in Python derives from DeviceDriver and the interfaces it
implements, and is added to the same factory (docs/devices.md, "Devices written in Python")."""
from .core import *  # noqa: F401,F403
from .core import __all__  # noqa: F401
