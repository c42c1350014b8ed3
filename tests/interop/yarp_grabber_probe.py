# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""Run by the YARP peer's interpreter: reads frames from a grabber's image port with YARP's own
BufferedPortImageRgb and sends requests to its RPC port with a yarp.RpcClient.

usage: yarp_grabber_probe.py <image port> <local prefix> <rpc port> [request ...]
Prints `frame <w> <h> <x-step> <y-step> <nonzero>` for two frames (x-step: red of (x+1, y) minus
red of (x, y) mod 256 if constant over row 1, else -1; likewise y-step on green down column 1;
nonzero: bytes > 0 in row 240 and in column 1, so that a horizontal line anywhere counts), then `reply <text>` for each request, then `done`."""
import sys

import yarp


def steps(img):
    w, h = img.width(), img.height()
    xs = {(img.pixel(x + 1, 1).r - img.pixel(x, 1).r) % 256 for x in range(w - 1)}
    ys = {(img.pixel(1, y + 1).g - img.pixel(1, y).g) % 256 for y in range(h - 1)}
    row = min(240, h - 1)
    nonzero = sum(1 for x in range(w) for c in (img.pixel(x, row).r, img.pixel(x, row).g, img.pixel(x, row).b) if c)
    nonzero += sum(1 for y in range(h) for c in (img.pixel(1, y).r, img.pixel(1, y).g, img.pixel(1, y).b) if c)
    return (xs.pop() if len(xs) == 1 else -1), (ys.pop() if len(ys) == 1 else -1), nonzero


def main():
    image_port, local, rpc_port, *requests = sys.argv[1:]
    yarp.Network.init()
    reader = yarp.BufferedPortImageRgb()
    reader.open(local + "/img")
    if not yarp.Network.connect(image_port, local + "/img"):
        print(f"cannot connect {image_port}", flush=True)
        return 1
    for _ in range(2):
        img = reader.read(True)
        print("frame", img.width(), img.height(), *steps(img), flush=True)
    client = yarp.RpcClient()
    client.open(local + "/rpc")
    if not yarp.Network.connect(local + "/rpc", rpc_port):
        print(f"cannot connect {rpc_port}", flush=True)
        return 1
    for text in requests:
        request, reply = yarp.Bottle(), yarp.Bottle()
        request.fromString(text)
        client.write(request, reply)
        print("reply", reply.toString(), flush=True)
    print("done", flush=True)
    reader.close()
    client.close()
    return 0


if __name__ == "__main__":
    sys.exit(main())
