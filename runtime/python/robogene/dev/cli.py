# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""`python -m robogene.dev`, the Python `robogene dev` (the paper's yarpdev): builds a device
configuration from --from FILE.ini and the command line (`--key value`, later wins), opens the
device with the factory (the C++ drivers, and the Python devices of a program that calls run()
after adding them) and serves it with the C++ servers until SIGINT / SIGTERM, then closes it, unregistering its ports. A device that is
not itself a server is wrapped by the one that fits it (wrapper_for), as yarpdev does.

    python -m robogene.dev --device test_motor --name /motors
    python -m robogene.dev --device controlBoard_nws_yarp --subdevice test_motor --name /motors
    python -m robogene.dev --server 127.0.0.1:10000 --device fake_grabber --name /cam"""
from __future__ import annotations

import signal
import sys
import threading
from typing import Optional, Sequence

from .core import ConfigError, ControlboardNws, DeviceDriver, GrabberNws, INetworkWrapper, PolyDriver, Property, \
    wrapper_for

USAGE = "python -m robogene.dev [--server HOST:PORT] [--from FILE.ini] --device NAME [--key value ...]"


class UsageError(Exception):
    pass


def device_config(args: Sequence[str]) -> Property:
    given = Property.from_command_line(args)
    config = Property("robogene dev configuration")
    if given.check("from"):
        path = given.get_string("from", "")
        if not path:
            raise UsageError("--from needs the name of an .ini file")
        config = Property.from_ini_file(path)
    config.merge(given)
    if not config.get_string("device", ""):
        raise UsageError("no device given: use --device NAME (or a `device` line in the --from file)")
    return config


def _wait_for_shutdown_signal() -> None:
    """Blocks until SIGINT or SIGTERM."""
    done = threading.Event()
    previous = {s: signal.signal(s, lambda _signum, _frame: done.set()) for s in (signal.SIGINT, signal.SIGTERM)}
    try:
        while not done.wait(0.5):  # a timed wait lets the handler run on the main thread
            pass
    finally:
        for s, h in previous.items():
            signal.signal(s, h)


SERVERS = {"controlBoard_nws_yarp": ControlboardNws, "frameGrabber_nws_yarp": GrabberNws}


def run(args: Sequence[str]) -> int:
    config = device_config(args)
    name = config.get_string("device", "")
    device = PolyDriver()
    if not device.open(config):
        raise ConfigError(device.last_error)
    server = None
    try:
        wrapper = device.view(INetworkWrapper)
        if wrapper is None:
            kind = wrapper_for(device.view(DeviceDriver))
            if kind not in SERVERS:
                raise ConfigError(f"device '{name}' cannot be served: it is neither a control board nor a camera, "
                                  "and not a wrapper")
            server = SERVERS[kind]()
            server.open(device.view(DeviceDriver), config)
            ports = server.port_names()
        else:
            ports = wrapper.port_names()
        print(f"robogene dev: {name} serving on {' '.join(ports)}", file=sys.stderr, flush=True)
        _wait_for_shutdown_signal()
    finally:
        if server is not None:
            server.close()
        device.close()
    print(f"robogene dev: {name} closed", file=sys.stderr, flush=True)
    return 0


def main(argv: Optional[Sequence[str]] = None) -> int:
    args = list(sys.argv[1:] if argv is None else argv)
    if args and args[0] in ("-h", "--help", "help"):
        print(f"usage: {USAGE}\n\n{__doc__}")
        return 0
    try:
        return run(args)
    except UsageError as exc:
        print(f"robogene dev: {exc}\nusage: {USAGE}", file=sys.stderr)
        return 2
    except Exception as exc:  # a device or network failure: named, not a traceback
        print(f"robogene dev: {exc}", file=sys.stderr)
        return 1
