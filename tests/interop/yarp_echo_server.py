# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""A real YARP RpcServer (SWIG `yarp` module) that replies with the request unchanged.
Run with the peer's interpreter: python yarp_echo_server.py /port"""
import sys

import yarp

yarp.Network.init()
port = yarp.RpcServer()
if not port.open(sys.argv[1]):
    sys.exit(f"cannot open {sys.argv[1]}")
print("ready", flush=True)
while True:
    request = yarp.Bottle()
    if not port.read(request, True):
        break
    print("got", request.toString(), flush=True)
    port.reply(request)
