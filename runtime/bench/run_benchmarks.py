#!/usr/bin/env python3
# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""Run every benchmark in runtime/bench/ and print what each one reports.

Each C++ program (*.cpp, built into <build>/bin) measures its own raw-socket baseline in the same
run; each Python one (bench_*.py, run with this interpreter, which must import robogene) measures
the C++ figure it is compared with. Every one prints a RESULT line with its ratio; this script
only runs them in turn and collects the RESULT lines.
Usage: run_benchmarks.py --build build [--quick]
"""
import argparse
import pathlib
import subprocess
import sys

QUICK_ARGS = {"bench_rpc": ["--n=5000"], "bench_stream": ["--frames=300"], "bench_fanout": ["--n=2000"],
              "bench_python_rpc": ["--n=5000", "--rounds=2"], "bench_shmem": ["--frames=300"]}


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--build", default="build", help="CMake build folder (programs in <build>/bin)")
    parser.add_argument("--quick", action="store_true", help="fewer iterations, for a smoke run")
    args = parser.parse_args()
    here = pathlib.Path(__file__).resolve().parent
    sources = sorted(here.glob("*.cpp")) + sorted(here.glob("bench_*.py"))
    results = []
    failed = False
    for src in sources:
        if src.suffix == ".py":
            cmd = [sys.executable, str(src), "--build", args.build]
        else:
            exe = pathlib.Path(args.build) / "bin" / src.stem
            if not exe.exists():
                print(f"{src.stem}: not built ({exe} missing); run `make runtime` first", file=sys.stderr)
                failed = True
                continue
            cmd = [str(exe)]
        cmd += QUICK_ARGS.get(src.stem, []) if args.quick else []
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
