# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""How a client learns that a device server is Robogene's before it asks for the interfaces'
fingerprints ([get] [rgif]): YARP 3's servers log every request they do not know as an error, so
that request goes only to a server that says it can answer it. The C++ twin is
robogene/dev/nws/server_identity.hpp: a Robogene server's request port carries the user-defined
port property ``robogene_service`` = the service's name, which a client reads with the admin
message [prop] [get] robogene_service; any YARP 3 port answers that itself, without its device."""
from __future__ import annotations

from typing import Any, Optional

from .. import Bottle, Network, Value, vocab

SERVICE_PROPERTY = "robogene_service"


def announce_service(port: Any, service: str) -> None:
    """Marks `port` (a Port, BufferedPort or RpcServer) as answering `service` as Robogene's do."""
    port.set_property(SERVICE_PROPERTY, service)


def serves_robogene(network: Optional[Network], name: str, service: str) -> bool:
    """Whether the port `name` says it serves `service` as Robogene's servers do; False for one
    that does not say so, cannot be found or does not answer."""
    request = Bottle()
    request.add(Value.vocab(vocab("prop")))
    request.add(Value.vocab(vocab("get")))
    request.add(Value.string(SERVICE_PROPERTY))
    try:
        reply = (network or Network()).admin(name, request)
    except Exception:  # a port that cannot be asked is not known to be Robogene's
        return False
    return len(reply) == 1 and reply[0].is_string() and reply[0].as_string() == service
