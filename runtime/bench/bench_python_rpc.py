#!/usr/bin/env python3
# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""Python binding RPC round trip against the C++ one, measured in the same run.

Python: robogene.RpcClient.call of the 46-byte Bottle `1 2.5 "hi" [set]` to a robogene.RpcServer
in the same process whose handler (a Python function, run on the connection's thread with the
GIL) returns the request; tcp carrier on loopback, no name server. C++: the `robogene tcp` line
of the bench_rpc program (the same exchange between RpcClient and RpcServer in C++). The two are
run in alternating rounds so that both see the same machine load; each side keeps its best
median. Target: Python <= 1.5 x C++.
Usage: bench_python_rpc.py --build build [--n=20000] [--rounds=3]
"""
from __future__ import annotations

import argparse
import pathlib
import re
import statistics
import subprocess
import sys
import time

import robogene

REQUEST = robogene.Bottle.from_text('1 2.5 "hi" [set]')


def python_round_trips(n: int) -> list[float]:
    """Microseconds per call for n calls after n/10 uncounted warm-up calls."""
    with robogene.RpcServer("/bench/py/rpc:i", lambda request, info: request, at=("127.0.0.1", 0)) as server:
        with robogene.RpcClient("/bench/py/rpc:o", at=("127.0.0.1", 0)) as client:
            client.connect(server.contact)
            clock = time.perf_counter
            call = client.call
            times = []
            for i in range(n + n // 10):
                start = clock()
                reply = call(REQUEST)
                if i >= n // 10:
                    times.append((clock() - start) * 1e6)
            if reply != REQUEST:
                raise SystemExit(f"the server echoed {reply} instead of {REQUEST}")
    return times


def cpp_median(exe: pathlib.Path, n: int) -> float:
    out = subprocess.run([str(exe), f"--n={n}"], capture_output=True, text=True, timeout=600, check=True).stdout
    m = re.search(r"robogene tcp\s+([\d.]+)", out)
    if not m:
        raise SystemExit(f"{exe} printed no 'robogene tcp' line:\n{out}")
    return float(m.group(1))


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--build", default="build", help="CMake build folder (bench_rpc in <build>/bin)")
    parser.add_argument("--n", type=int, default=20000, help="calls per round")
    parser.add_argument("--rounds", type=int, default=3)
    args = parser.parse_args()
    exe = pathlib.Path(args.build) / "bin" / "bench_rpc"
    if not exe.exists():
        print(f"bench_python_rpc: {exe} missing; run `make runtime` first", file=sys.stderr)
        return 1
    cpp, py, py_p99 = [], [], []
    for _ in range(args.rounds):
        cpp.append(cpp_median(exe, args.n))
        times = sorted(python_round_trips(args.n))
        py.append(statistics.median(times))
        py_p99.append(times[len(times) * 99 // 100])
    best_cpp, best_py = min(cpp), min(py)
    print(f"rpc round trip, {args.n} calls x {args.rounds} rounds, tcp, median us per round")
    print("  C++    RpcClient -> RpcServer  " + " ".join(f"{v:7.1f}" for v in cpp))
    print("  Python RpcClient -> RpcServer  " + " ".join(f"{v:7.1f}" for v in py)
          + f"   (p99 {min(py_p99):.1f})")
    print(f"  best: C++ {best_cpp:.1f} us, Python {best_py:.1f} us, ratio {best_py / best_cpp:.2f}")
    print(f"RESULT python_rpc_ratio={best_py / best_cpp:.2f} target<=1.5")
    return 0


if __name__ == "__main__":
    sys.exit(main())
