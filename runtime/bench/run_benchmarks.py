#!/usr/bin/env python3
# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""Run every C++ benchmark built from runtime/bench/*.cpp and print what each one reports.

Each program measures its own raw-socket baseline in the same run and prints a RESULT line with
the ratio against it; this script only runs them in turn and collects the RESULT lines.
Usage: run_benchmarks.py --build build [--quick]
"""
import argparse
import pathlib
import subprocess
import sys

QUICK_ARGS = {"bench_rpc": ["--n=5000"], "bench_stream": ["--frames=300"], "bench_fanout": ["--n=2000"]}


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--build", default="build", help="CMake build folder (programs in <build>/bin)")
    parser.add_argument("--quick", action="store_true", help="fewer iterations, for a smoke run")
    args = parser.parse_args()
    sources = sorted(pathlib.Path(__file__).resolve().parent.glob("*.cpp"))
    results = []
    failed = False
    for src in sources:
        exe = pathlib.Path(args.build) / "bin" / src.stem
        if not exe.exists():
            print(f"{src.stem}: not built ({exe} missing); run `make runtime` first", file=sys.stderr)
            failed = True
            continue
        cmd = [str(exe)] + (QUICK_ARGS.get(src.stem, []) if args.quick else [])
        print(f"== {' '.join(cmd)}", flush=True)
        proc = subprocess.run(cmd, capture_output=True, text=True, timeout=1800)
        sys.stdout.write(proc.stdout)
        sys.stderr.write(proc.stderr)
        if proc.returncode != 0:
            print(f"{src.stem}: exited with status {proc.returncode}", file=sys.stderr)
            failed = True
        results += [line for line in proc.stdout.splitlines() if line.startswith("RESULT ")]
    print("== summary")
    for line in results:
        print(line)
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
