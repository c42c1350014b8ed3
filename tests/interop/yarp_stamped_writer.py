# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""A real YARP output port (SWIG `yarp` module) that writes each stdin line as a bottle with an
envelope Stamp(sequence = line number, time = 1000.25 + line number), as sensor/state ports do.
Run with the peer's interpreter: python yarp_stamped_writer.py /port"""
import sys

import yarp

yarp.Network.init()
port = yarp.Port()
if not port.open(sys.argv[1]):
    sys.exit(f"cannot open {sys.argv[1]}")
print("ready", flush=True)
for count, line in enumerate(sys.stdin):
    bottle = yarp.Bottle()
    bottle.fromString(line.rstrip("\n"))
    port.setEnvelope(yarp.Stamp(count, 1000.25 + count))
    port.write(bottle)
    print("wrote", count, flush=True)
port.close()
