# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""Control boards on real ports, in Python: the same ports and messages as the C++ network
devices (docs/devices.md, "On the network").

* ``ControlboardNws`` serves a device written in Python: ``<name>/rpc:i`` answers through
  ``rpc.RpcServer``, ``<name>/command:i`` takes streamed commands, ``<name>/state:o`` and
  ``<name>/stateExt:o`` publish the encoders (a YARP Vector, and jointData) every ``period`` with
  a Stamp envelope. YARP's remote_controlboard and the C++ one can use it.
* ``RemoteControlboard`` (device ``remote_controlboard``, in remote_controlboard.py) is a served
  control board seen from Python, with the C++ client's ports: encoders from ``stateExt:o``,
  velocity moves on ``command:i``, the rest by RPC.
"""
from __future__ import annotations

import logging
import threading
import time
from typing import Any, List, Optional

from .. import Bottle, BufferedPort, Error, Network, Port, RpcServer, Value
from .property import ConfigError, Property
from .rpc import RpcServer as Dispatch
from .server_identity import announce_service


def _network(config: Property) -> Optional[Network]:
    """The name server named by the `server` key (HOST:PORT), else None (yarp.conf)."""
    return Network(config.get_string("server", "")) if config.check("server") else None


def _port_name(config: Property, key: str) -> str:
    name = config.get_string(key, "")
    if len(name) < 2 or not name.startswith("/") or any(c.isspace() for c in name):
        raise ConfigError(f"{config.origin(key) or config.source()}: key '{key}': {name!r} is not a port "
                          "name (it must start with '/' and have no spaces)")
    return name


def _call_or_empty(client: Any, request: Bottle, what: str) -> Bottle:
    """One request of a remote device's generated client. A failed exchange is an empty reply (the
    method then returns None/False, as in C++), logged with `what` (ports and peer)."""
    if client is None:
        return Bottle()
    try:
        return client.call(request)
    except Error as exc:
        logging.getLogger("robogene.dev").warning("%s failed: %s", what, exc)
        return Bottle()


def encode_joint_data(device: Any) -> Optional[Bottle]:
    """YARP 3's jointData for `device` (the stateExt:o message), as the C++ encode_joint_data:
    11 (values) [ok|fail] pairs; what the device cannot report is zeros flagged [fail]."""
    axes = device.getAxes() if hasattr(device, "getAxes") else None
    if axes is None or axes < 0:
        return None

    def reading(method: str) -> Optional[List[Any]]:
        values = getattr(device, method)() if hasattr(device, method) else None
        return values if values is not None and len(values) == axes else None

    out = Bottle()

    def add(values: Optional[List[Any]], make) -> None:
        out.add(Value.list([make(v) for v in values] if values is not None else [make(0)] * axes))
        out.add(Value.vocab("ok" if values is not None else "fail"))

    for method in ("getEncoders", "getEncoderSpeeds", "getEncoderAccelerations"):
        add(reading(method), lambda v: Value.float64(float(v)))
    for _ in range(3):  # motor position, velocity, acceleration: no IMotorEncoders
        add(None, lambda v: Value.float64(0.0))
    add(reading("getTorques"), lambda v: Value.float64(float(v)))
    for _ in range(2):  # PWM duty cycle, current
        add(None, lambda v: Value.float64(0.0))
    add(reading("getControlModes"), lambda v: Value.int32(int(v)))
    add(None, lambda v: Value.int32(0))  # interaction mode
    return out


class ControlboardNws:
    """Serves a Python control board on ``<name>/rpc:i``, ``command:i``, ``state:o`` and
    ``stateExt:o``; ``close()`` (or ``with``) stops the stream and unregisters the ports."""

    def __init__(self, device: Any, name: str, period: float = 0.02, network: Optional[Network] = None):
        if not name.startswith("/"):
            raise ValueError(f"{name!r} is not a port name (it must start with '/')")
        if not 0.001 <= period <= 10.0:
            raise ValueError(f"period {period} s is outside [0.001, 10]")
        self._device, self._period = device, period
        self._dispatch = Dispatch("controlboard", device)
        kw = {"network": network} if network is not None else {}
        self._ports: List[Any] = []
        try:
            self._rpc = RpcServer(f"{name}/rpc:i", lambda request, info: self._dispatch.respond(request), **kw)
            self._ports.append(self._rpc)
            announce_service(self._rpc, "controlboard")  # so our clients may ask [get] [rgif]
            self._command = BufferedPort(f"{name}/command:i", **kw)
            self._ports.append(self._command)
            self._command.on_read(lambda message, info: self._dispatch.command(message))
            self._state = Port(f"{name}/state:o", **kw)
            self._ports.append(self._state)
            self._state_ext = Port(f"{name}/stateExt:o", **kw)
            self._ports.append(self._state_ext)
        except Exception:
            self.close()
            raise
        self._stop = threading.Event()
        self._thread = threading.Thread(target=self._publish, name=f"{name} state", daemon=True)
        self._thread.start()

    def port_names(self) -> List[str]:
        return [p.name for p in self._ports]

    def _publish(self) -> None:
        sequence = 0
        next_tick = time.monotonic()
        while not self._stop.wait(max(0.0, next_tick - time.monotonic())):
            envelope = f"{sequence} {time.time():.15g}"
            sequence += 1
            state = self._dispatch.publish("state")
            if state is not None:
                self._state.set_envelope(envelope)
                self._state.write(state)
            joints = encode_joint_data(self._device)
            if joints is not None:
                self._state_ext.set_envelope(envelope)
                self._state_ext.write(joints)
            next_tick += self._period
            if next_tick < time.monotonic():  # skip the ticks a slow step missed
                next_tick = time.monotonic() + self._period

    def close(self) -> None:
        stop = getattr(self, "_stop", None)
        if stop is not None:
            stop.set()
            self._thread.join()
        for port in reversed(self._ports):
            port.close()
        self._ports = []

    def __enter__(self) -> "ControlboardNws":
        return self

    def __exit__(self, *exc) -> None:
        self.close()


__all__ = ["ControlboardNws", "encode_joint_data"]
