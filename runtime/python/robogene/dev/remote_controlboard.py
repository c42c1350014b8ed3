# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""remote_controlboard in Python: a served control board seen from Python, with the C++ client's
ports and rules (runtime/src/dev/nws/remote_controlboard.cpp, docs/devices.md):

* ``<local>/rpc:o`` -> ``<remote>/rpc:i``: every method by RPC through the generated
  ``ControlboardClient``, except
* the encoders (positions, speeds, accelerations), read from the last jointData that
  ``<remote>/stateExt:o`` sent to ``<local>/stateExt:i`` (decoded by the C++ core's
  ``decode_joint_data``); by RPC only when that message is older than 0.5 s or the server
  flagged the field [fail], and
* single-axis velocity moves, sent on ``<local>/command:o`` -> ``<remote>/command:i`` as
  ``([vmo] j) (v)`` (by RPC only when no command connection takes it).
"""
from __future__ import annotations

import logging
import math
import threading
import time
from typing import List, Optional

from .. import Bottle, BufferedPort, Error, JointData, Network, Port, RpcClient, Value, decode_joint_data
from .device_driver import DeviceDriver
from .generated.clients import ControlboardClient
from .property import ConfigError, Property
from .network import _call_or_empty, _network, _port_name
from .server_identity import serves_robogene

_log = logging.getLogger("robogene.dev")

# As the C++ client (and YARP's): jointData older than this is stale, and the encoders go by RPC.
STATE_TIMEOUT = 0.5
_BY_RPC = object()  # no fresh streamed value: ask the server


def _axis(j, axes: int) -> bool:
    return isinstance(j, int) and not isinstance(j, bool) and 0 <= j < axes


class RemoteControlboard(ControlboardClient, DeviceDriver):
    """remote_controlboard: keys remote (the server's prefix), local (this client's prefix),
    carrier (of the two streams, default udp as YARP's), server (name server HOST:PORT, else
    yarp.conf)."""

    def __init__(self) -> None:
        super().__init__(self._call)
        self._client: Optional[RpcClient] = None
        self._command_port: Optional[Port] = None
        self._state_port: Optional[BufferedPort] = None
        self._network: Optional[Network] = None
        self._remote = self._local = ""
        self._axes = 0
        self._connected = False
        self._lock = threading.Lock()
        self._latest: Optional[JointData] = None
        self._latest_at = 0.0
        self._warned = False

    def _call(self, request: Bottle) -> Bottle:
        return _call_or_empty(self._client, request, f"{self._local}/rpc:o: request to {self._remote}/rpc:i")

    def open(self, config: Property) -> bool:
        self.close()
        self._remote, self._local = _port_name(config, "remote"), _port_name(config, "local")
        remote, local = self._remote, self._local
        carrier = config.get_string("carrier", "udp")
        self._network = _network(config)
        kw = {"network": self._network} if self._network is not None else {}
        try:
            self._client = RpcClient(f"{local}/rpc:o", server=f"{remote}/rpc:i", **kw)
            self._client.call(Bottle.from_text("[get] [prot]"))  # raises naming an absent server
            # Only a server that says it is Robogene's is asked for its fingerprints (server_identity).
            self.check_server(serves_robogene(self._network, f"{remote}/rpc:i", self.SERVICE))
            axes = self.getAxes()
            if axes is None:
                raise Error(f"{remote}/rpc:i does not answer [get] [axes]")
            self._axes = axes
            self._command_port = Port(f"{local}/command:o", **kw)
            self._command_port.add_output(f"{remote}/command:i", carrier)
            self._state_port = BufferedPort(f"{local}/stateExt:i", **kw)
            self._state_port.on_read(self._received)
            (self._network or Network()).connect(f"{remote}/stateExt:o", f"{local}/stateExt:i", carrier)
            self._connected = True
        except Error as exc:
            self.close()
            raise ConfigError(f"remote_controlboard {local} -> {remote}: {exc}") from None
        return True

    def close(self) -> bool:
        if self._connected:
            # As YARP's client does: the server would otherwise keep sending (udp never notices).
            try:
                (self._network or Network()).disconnect(f"{self._remote}/stateExt:o", f"{self._local}/stateExt:i")
            except Error as exc:
                _log.warning("%s/stateExt:i: could not disconnect: %s", self._local, exc)
            self._connected = False
        for port in (self._state_port, self._command_port, self._client):
            if port is not None:
                port.close()
        self._state_port = self._command_port = self._client = None
        with self._lock:
            self._latest, self._warned = None, False
        return True

    # ---- the stream ----------------------------------------------------------------------------

    def _received(self, message: Bottle, info) -> None:
        try:
            data = decode_joint_data(message)
        except Error as exc:
            with self._lock:
                if not self._warned:
                    _log.warning("%s/stateExt:i: ignoring jointData: %s", self._local, exc)
                self._warned = True
            return
        if data.axes != self._axes:
            return  # another board's
        with self._lock:
            self._latest, self._latest_at = data, time.monotonic()

    def _fresh(self, field: str) -> Optional[List[float]]:
        """One field of the latest jointData if it is fresh and valid, else None."""
        with self._lock:
            if self._latest is None or time.monotonic() - self._latest_at > STATE_TIMEOUT:
                return None
            return getattr(self._latest, field)

    def _fresh_one(self, field: str, j):
        values = self._fresh(field)
        if values is None:
            return _BY_RPC
        return values[j] if _axis(j, len(values)) else None

    def getEncoders(self) -> Optional[List[float]]:
        values = self._fresh("position")
        return values if values is not None else ControlboardClient.getEncoders(self)

    def getEncoder(self, j: int) -> Optional[float]:
        v = self._fresh_one("position", j)
        return ControlboardClient.getEncoder(self, j) if v is _BY_RPC else v

    def getEncoderSpeeds(self) -> Optional[List[float]]:
        values = self._fresh("velocity")
        return values if values is not None else ControlboardClient.getEncoderSpeeds(self)

    def getEncoderSpeed(self, j: int) -> Optional[float]:
        v = self._fresh_one("velocity", j)
        return ControlboardClient.getEncoderSpeed(self, j) if v is _BY_RPC else v

    def getEncoderAccelerations(self) -> Optional[List[float]]:
        values = self._fresh("acceleration")
        return values if values is not None else ControlboardClient.getEncoderAccelerations(self)

    def getEncoderAcceleration(self, j: int) -> Optional[float]:
        v = self._fresh_one("acceleration", j)
        return ControlboardClient.getEncoderAcceleration(self, j) if v is _BY_RPC else v

    # ---- the command port ----------------------------------------------------------------------

    def velocityMove(self, j: int, sp: float) -> bool:
        if not _axis(j, self._axes) or not isinstance(sp, (int, float)) or isinstance(sp, bool) \
                or not math.isfinite(sp):
            return False
        # CommandMessage: a (head) list and a (values) list, sent without waiting (reference 5.5).
        message = Bottle([Value.list([Value.vocab("vmo"), Value.int32(j)]), Value.list([Value.float64(sp)])])
        if self._command_port is not None and self._command_port.write(message):
            return True
        return ControlboardClient.velocityMove(self, j, sp)  # no command connection: ask by RPC


__all__ = ["STATE_TIMEOUT", "RemoteControlboard"]
