# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""A real YARP output port (SWIG `yarp` module) that writes the typed-value bottles of
tests/vectors/yarp3_typed_values.json (int8, int16, float32, ... built with the typed add* calls)
once a line arrives on stdin. Run with the peer's interpreter: python yarp_typed_writer.py /port"""
import sys
from pathlib import Path

import yarp

sys.path.insert(0, str(Path(__file__).resolve().parent))
from gen_yarp3_vectors import typed_cases  # noqa: E402

yarp.Network.init()
port = yarp.Port()
if not port.open(sys.argv[1]):
    sys.exit(f"cannot open {sys.argv[1]}")
print("ready", flush=True)
for _ in sys.stdin:
    for name, build in typed_cases():
        bottle = yarp.Bottle()
        build(bottle)
        port.write(bottle)
    print("sent", flush=True)
port.close()
