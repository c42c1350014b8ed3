# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""Robogene: YARP-3-compatible bottles, ports and devices, bound from the C++ core.

    >>> import robogene
    >>> robogene.Bottle.from_text('[set] [pos] 1 30.3').to_bytes().hex()[:16]
    '0001000004000000'

Ports talk to a name server (``robogene server``, or YARP's ``yarpserver``) found through
yarp.conf, or through an explicit ``robogene.Network("host:port")``::

    with robogene.RpcServer("/calc", lambda req, info: [req[0].as_int() * 2]):
        with robogene.RpcClient(server="/calc") as client:
            client.call([21])          # Bottle.from_text('42')

See docs/python.md.
"""
from ._core import (  # noqa: F401  (re-exported API)
    Bottle,
    BufferedPort,
    BufferPolicy,
    Contact,
    Error,
    JointData,
    MessageInfo,
    NameConfig,
    Network,
    NetworkError,
    ParseError,
    Port,
    RpcClient,
    RpcServer,
    Stamp,
    Value,
    __version__,
    decode_joint_data,
    vocab,
    vocab_to_string,
)

__all__ = [
    "Bottle",
    "BufferPolicy",
    "BufferedPort",
    "Contact",
    "Error",
    "JointData",
    "MessageInfo",
    "NameConfig",
    "Network",
    "NetworkError",
    "ParseError",
    "Port",
    "RpcClient",
    "RpcServer",
    "Stamp",
    "Value",
    "__version__",
    "decode_joint_data",
    "vocab",
    "vocab_to_string",
]
