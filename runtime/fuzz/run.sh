#!/usr/bin/env bash
# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
#
# Builds every fuzz target (runtime/fuzz/*_fuzz.cpp) with clang, ASan and UBSan into build/fuzz
# and runs each for SECONDS, starting from the committed seeds and regression inputs
# (runtime/fuzz/corpus/<target>/) plus, for the bottle decoders, the shared vectors. New inputs
# go to build/fuzz/corpus/<target>/ (kept between runs: a campaign continues where the last one
# stopped). Exit status is non-zero when any target crashes, leaks or hangs; the reproducer is
# build/fuzz/artifacts/<target>-crash-*. One summary line per target goes to
# build/fuzz/results.txt. Needs the packages in tools/setup/apt/fuzz.txt.
# Usage: runtime/fuzz/run.sh SECONDS [TARGET...]
set -euo pipefail
seconds=${1:?usage: run.sh SECONDS [TARGET...]}
shift
root=$(cd "$(dirname "$0")/../.." && pwd)
out=${FUZZ_BUILD:-$root/build/fuzz}
cxx=${FUZZ_CXX:-clang++-14}

cmake -S "$root/runtime/fuzz" -B "$out" -G Ninja -DCMAKE_CXX_COMPILER="$cxx" >/dev/null
cmake --build "$out" -j "${JOBS:-2}" >"$out/build.log" 2>&1 || { tail -40 "$out/build.log"; exit 1; }

# Seeds of the two bottle decoders: every vector's bytes and every text.
python3 - "$root/tests/vectors/bottles.json" "$out" <<'PY'
import json, pathlib, sys
doc = json.loads(pathlib.Path(sys.argv[1]).read_text())
out = pathlib.Path(sys.argv[2]) / "vector-seeds"
for target in ("binary_decoder_fuzz", "text_parser_fuzz"):
    (out / target).mkdir(parents=True, exist_ok=True)
for i, case in enumerate(doc["cases"]):
    (out / "binary_decoder_fuzz" / ("case%03d" % i)).write_bytes(bytes.fromhex(case["hex"]))
    (out / "text_parser_fuzz" / ("case%03d" % i)).write_text(case["text"])
for i, case in enumerate(doc["malformed_hex"]):
    (out / "binary_decoder_fuzz" / ("bad%03d" % i)).write_bytes(bytes.fromhex(case["hex"]))
for i, case in enumerate(doc["malformed_text"]):
    (out / "text_parser_fuzz" / ("bad%03d" % i)).write_text(case["text"])
PY

if [ $# -eq 0 ]; then
  set -- $(cd "$root/runtime/fuzz" && ls *_fuzz.cpp | sed 's/\.cpp$//')
fi
mkdir -p "$out/artifacts"
: >"$out/results.txt"
failed=()
for target in "$@"; do
  corpus="$out/corpus/$target"
  mkdir -p "$corpus"
  seeds=()
  for dir in "$root/runtime/fuzz/corpus/$target" "$out/vector-seeds/$target"; do
    [ -d "$dir" ] && seeds+=("$dir")
  done
  echo "== $target for ${seconds}s"
  log="$out/$target.log"
  status=0
  # -timeout: one input taking 10 s is a hang; -rss_limit_mb: growth with input is a finding.
  "$out/$target" -max_total_time="$seconds" -max_len=4096 -timeout=10 -rss_limit_mb=2048 \
    -print_final_stats=1 -artifact_prefix="$out/artifacts/$target-" "$corpus" "${seeds[@]}" >"$log" 2>&1 || status=$?
  execs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -1)
  cov=$(grep -o 'cov: [0-9]*' "$log" | tail -1 | cut -d' ' -f2)
  corpus_size=$(ls "$corpus" | wc -l)
  line="$target: ${execs:-0} executions in ${seconds}s, coverage ${cov:-0} edges, corpus $corpus_size inputs"
  if [ "$status" -ne 0 ]; then
    line="$line, FAILED (exit $status; see $log)"
    failed+=("$target")
    grep -E 'ERROR|SUMMARY|==[0-9]+==' "$log" | head -20 || true
  fi
  echo "$line" | tee -a "$out/results.txt"
done
if [ ${#failed[@]} -ne 0 ]; then
  echo "fuzz: ${failed[*]} failed; reproducers in $out/artifacts" >&2
  exit 1
fi
