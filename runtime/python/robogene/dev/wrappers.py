# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""Server devices, as the C++ factory has them: controlBoard_nws_yarp and frameGrabber_nws_yarp
(and YARP 3.5's names for them, controlboardwrapper2 and grabberDual) open the device named by
`subdevice` with the same configuration and put it on the network under `name`.

`serve(device, config)` picks the server that fits a device that is not itself one, as yarpdev
and `robogene dev` do."""
from __future__ import annotations

from typing import Any, List, Optional

from .device_driver import DeviceDriver
from .generated.interfaces import IEncoders, IFrameGrabberImage
from .poly_driver import PolyDriver
from .property import ConfigError, Property

CONTROL_BOARD = "controlBoard_nws_yarp"
CAMERA = "frameGrabber_nws_yarp"
# The server devices by name, YARP 3.5's older names included, and the server each one runs.
WRAPPERS = {CONTROL_BOARD: CONTROL_BOARD, "controlboardwrapper2": CONTROL_BOARD,
            CAMERA: CAMERA, "grabberDual": CAMERA}


def wrapper_for(device: Any) -> str:
    """The server that fits `device`, or "" when it is neither a control board nor a camera."""
    if isinstance(device, IEncoders):
        return CONTROL_BOARD
    if isinstance(device, IFrameGrabberImage):
        return CAMERA
    return ""


def serve(device: Any, config: Property, kind: str = "") -> Any:
    """Opens the `kind` server (default: the one that fits) for `device`, on the port named by the
    `name` key, with the name server of the `server` key (else yarp.conf) and its `period`."""
    # Imported here: the servers need the compiled core, which the factory's users may not.
    from .grabber_network import GrabberNws
    from .network import ControlboardNws, _network, _port_name

    kind = kind or wrapper_for(device)
    if not kind:
        raise ConfigError(f"device {config.get_string('device', '?')!r} cannot be served: it is neither a control "
                          "board nor a camera, and not a wrapper")
    name = _port_name(config, "name")
    network = _network(config)
    kw = {"network": network} if network is not None else {}
    if kind == CONTROL_BOARD:
        return ControlboardNws(device, name, config.get_float("period", 0.02, 0.001, 10.0), **kw)
    return GrabberNws(device, name, config.get_float("period", 0.0, 0.0, 10.0), **kw)


class NetworkWrapper(DeviceDriver):
    """A server device: its `subdevice` on the network. `port_names()` lists what it opened."""

    def __init__(self, kind: str):
        self._kind = kind
        self._subdevice = PolyDriver()
        self._server: Optional[Any] = None

    def open(self, config: Property) -> bool:
        self.close()
        sub = config.get_string("subdevice", "")
        if not sub:
            raise ConfigError(f"{config.source()}: no 'subdevice' key naming the device to serve")
        sub_config = Property(config.source())
        sub_config.merge(config)
        sub_config.put("device", sub, f"{config.origin('subdevice') or config.source()} (subdevice)")
        if not self._subdevice.open(sub_config):
            raise ConfigError(f"subdevice: {self._subdevice.last_error}")
        try:
            self._server = serve(self._subdevice.view(DeviceDriver), config, self._kind)
        except Exception:
            self._subdevice.close()
            raise
        return True

    def close(self) -> bool:
        if self._server is not None:
            self._server.close()
            self._server = None
        return self._subdevice.close()

    def port_names(self) -> List[str]:
        return self._server.port_names() if self._server is not None else []


def add_wrapper_devices(factory) -> None:
    descriptions = {CONTROL_BOARD: "serves a control board `subdevice` on <name>/rpc:i, command:i, state:o, stateExt:o",
                    CAMERA: "serves a camera `subdevice` on <name>/rpc and <name> (the images), as YARP 3.5 does"}
    for name, kind in WRAPPERS.items():
        text = descriptions[name] if name == kind else f"YARP 3.5's name for {kind}"
        factory.add(name, text, lambda kind=kind: NetworkWrapper(kind))
