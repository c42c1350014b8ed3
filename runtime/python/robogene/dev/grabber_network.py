# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""Cameras on real ports, in Python: the ports and messages of the C++ camera server and
remote_grabber, which are YARP 3.5's (docs/devices.md, "The camera server and remote_grabber").

* ``GrabberNws`` serves a camera written in Python: ``<name>/rpc`` and ``<name>`` answer the
  grabber requests through ``rpc.RpcServer``, and ``<name>`` streams every frame the device gives
  as a YARP 3 image with a Stamp envelope.
* ``RemoteGrabber`` (device ``remote_grabber``) is a served camera seen from Python: frames come
  on ``<local>`` (connected from ``<remote>``), the controls go by RPC from ``<local>/rpc_client``
  through the generated ``GrabberClient``.
"""
from __future__ import annotations

import logging
import threading
import time
from typing import Any, List, Optional

from .. import Bottle, BufferedPort, Error, Network, Port, RpcClient, RpcServer
from .device_driver import DeviceDriver
from .generated.clients import GrabberClient
from .image import ImageRgb
from .network import _call_or_empty, _network, _port_name
from .property import ConfigError, Property
from .rpc import ImageError, decode_image
from .rpc import RpcServer as Dispatch
from .server_identity import announce_service, serves_robogene

_log = logging.getLogger("robogene.dev")


class GrabberNws:
    """Serves a Python camera on ``<name>/rpc`` and ``<name>``; ``period`` (seconds, default 0) is
    a minimum time between two published frames, the device's getImage sets the pace.
    ``close()`` (or ``with``) stops the stream and unregisters the ports."""

    def __init__(self, device: Any, name: str, period: float = 0.0, network: Optional[Network] = None):
        if len(name) < 2 or not name.startswith("/") or any(c.isspace() for c in name):
            raise ValueError(f"{name!r} is not a port name (it must start with '/' and have no spaces)")
        if not 0.0 <= period <= 10.0:
            raise ValueError(f"period {period} s is outside [0, 10]")
        self._dispatch = Dispatch("grabber", device)
        if not self._dispatch.interfaces():
            raise ValueError(f"{name}: the device to serve implements none of the interfaces of the "
                             "grabber service")
        self._period = period
        self._stop = threading.Event()
        self._threads: List[threading.Thread] = []
        kw = {"network": network} if network is not None else {}
        self._ports: List[Any] = []
        try:
            self._rpc = RpcServer(f"{name}/rpc", lambda request, info: self._dispatch.respond(request), **kw)
            self._ports.append(self._rpc)
            self._image = Port(name, **kw)
            self._ports.append(self._image)
            for port in (self._rpc, self._image):  # both answer requests (server_identity)
                announce_service(port, "grabber")
        except Exception:
            self.close()
            raise
        # YARP 3.5's remote_grabber sends its requests to the image port itself.
        for target, what in ((self._answer, "requests"), (self._publish, "frames")):
            thread = threading.Thread(target=target, name=f"{name} {what}", daemon=True)
            self._threads.append(thread)
            thread.start()

    def port_names(self) -> List[str]:
        return [p.name for p in self._ports]

    def _answer(self) -> None:
        while not self._stop.is_set():
            request = self._image.read(0.1, will_reply=True)
            if request is not None:
                self._image.reply(self._dispatch.respond(request))  # ignored when nobody waits

    def _publish(self) -> None:
        sequence = 0
        last = None
        while not self._stop.is_set():
            if last is not None and self._period > 0:
                if self._stop.wait(max(0.0, last + self._period - time.monotonic())):
                    return
            image = self._dispatch.publish("image")  # waits for the device's next frame
            if image is None:
                self._stop.wait(0.01)  # a device with no frame to give: do not spin
                continue
            last = time.monotonic()
            self._image.set_envelope(f"{sequence} {time.time():.15g}")
            sequence += 1
            self._image.write(image)

    def close(self) -> None:
        self._stop.set()
        for thread in self._threads:
            thread.join()
        self._threads = []
        for port in reversed(self._ports):
            port.close()
        self._ports = []

    def __enter__(self) -> "GrabberNws":
        return self

    def __exit__(self, *exc) -> None:
        self.close()


class RemoteGrabber(GrabberClient, DeviceDriver):
    """remote_grabber: keys remote (the server's prefix), local (this client's prefix), stream
    (or carrier: the images' carrier, default tcp), timeout (seconds getImage waits for a frame,
    default 1), server (name server HOST:PORT, else yarp.conf)."""

    def __init__(self) -> None:
        super().__init__(self._call)
        self._client: Optional[RpcClient] = None
        self._images: Optional[BufferedPort] = None
        self._network: Optional[Network] = None
        self._remote = self._local = ""
        self._timeout = 1.0
        self._arrived = threading.Condition()
        self._latest: Optional[Bottle] = None
        self._frames = 0
        self._closing = False
        self._connected = False
        self.last_error = ""

    def _call(self, request: Bottle) -> Bottle:
        return _call_or_empty(self._client, request, f"{self._local}/rpc_client: request to {self._remote}/rpc")

    def _received(self, message: Bottle, info) -> None:
        with self._arrived:
            self._latest = message
            self._frames += 1
            self._arrived.notify_all()

    def open(self, config: Property) -> bool:
        self.close()
        self._remote, self._local = _port_name(config, "remote"), _port_name(config, "local")
        carrier = config.get_string("stream", config.get_string("carrier", "tcp"))
        self._timeout = config.get_float("timeout", 1.0, 0.001, 3600.0)
        self._network = _network(config)
        kw = {"network": self._network} if self._network is not None else {}
        with self._arrived:
            self._closing, self._latest, self._frames = False, None, 0
        try:
            self._client = RpcClient(f"{self._local}/rpc_client", server=f"{self._remote}/rpc", **kw)
            self._client.call(Bottle.from_text("[fgi] [get] [w]"))  # raises naming an absent server
            self.check_server(serves_robogene(self._network, f"{self._remote}/rpc", self.SERVICE))
            self._images = BufferedPort(self._local, **kw)
            self._images.on_read(self._received)
            (self._network or Network()).connect(self._remote, self._local, carrier)
            self._connected = True
        except Error as exc:
            self.close()
            raise ConfigError(f"remote_grabber {self._local} -> {self._remote}: {exc}") from None
        return True

    def close(self) -> bool:
        with self._arrived:
            self._closing = True
            self._arrived.notify_all()
        if self._connected:
            try:
                (self._network or Network()).disconnect(self._remote, self._local)
            except Error as exc:
                _log.warning("%s: could not disconnect from %s: %s", self._local, self._remote, exc)
            self._connected = False
        for port in (self._images, self._client):
            if port is not None:
                port.close()
        self._images = self._client = None
        return True

    def frames_received(self) -> int:
        with self._arrived:
            return self._frames

    def _message(self, after: int) -> Optional[Bottle]:
        """The latest frame message once more than `after` have arrived (None on timeout/close)."""
        with self._arrived:
            if not self._arrived.wait_for(lambda: self._closing or self._frames > after, self._timeout) \
                    or self._closing:
                return None
            return self._latest

    def _decoded(self, message: Optional[Bottle]) -> Optional[ImageRgb]:
        if message is None:
            return None
        try:
            return decode_image(message)
        except ImageError as exc:
            self.last_error = f"a frame from {self._remote} cannot be decoded: {exc}"
            _log.warning("%s: %s", self._local, self.last_error)
            return None

    def getImage(self) -> Optional[ImageRgb]:
        """The next frame received (waiting up to `timeout`), decoded; None when none came or it
        is not an RGB image (last_error then says why)."""
        return self._decoded(self._message(self.frames_received()))

    def _frame_size(self) -> Optional[ImageRgb]:
        return self._decoded(self._message(0))

    def width(self) -> Optional[int]:
        # Asked by RPC only before the first frame: YARP's grabberDual does not answer it.
        if self.frames_received() == 0:
            cols = GrabberClient.width(self)
            if cols is not None:
                return cols
        image = self._frame_size()
        return image.width if image is not None else None

    def height(self) -> Optional[int]:
        if self.frames_received() == 0:
            rows = GrabberClient.height(self)
            if rows is not None:
                return rows
        image = self._frame_size()
        return image.height if image is not None else None


__all__ = ["GrabberNws", "RemoteGrabber"]
