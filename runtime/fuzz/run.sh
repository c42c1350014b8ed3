#!/usr/bin/env bash
# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
#
# Builds the Bottle fuzz targets with clang and runs each for SECONDS (default 60), seeded with
# the shared vectors. Needs the packages in tools/setup/apt/fuzz.txt. Exit status is non-zero when
# a target finds a crash; the reproducer is left in build/fuzz/.
# Usage: runtime/fuzz/run.sh [SECONDS]
set -euo pipefail
seconds=${1:-60}
root=$(cd "$(dirname "$0")/../.." && pwd)
out=${FUZZ_BUILD:-$root/build/fuzz}
cxx=${FUZZ_CXX:-clang++-14}

cmake -S "$root/runtime/fuzz" -B "$out" -G Ninja -DCMAKE_CXX_COMPILER="$cxx" >/dev/null
cmake --build "$out" -j "${JOBS:-2}"

# Seeds: every vector's bytes for the binary decoder, every text for the text parser.
python3 - "$root/tests/vectors/bottles.json" "$out" <<'PY'
import json, pathlib, sys
doc = json.loads(pathlib.Path(sys.argv[1]).read_text())
out = pathlib.Path(sys.argv[2])
for kind in ("binary", "text"):
    (out / ("seeds-" + kind)).mkdir(exist_ok=True)
for i, case in enumerate(doc["cases"]):
    (out / "seeds-binary" / ("case%03d" % i)).write_bytes(bytes.fromhex(case["hex"]))
    (out / "seeds-text" / ("case%03d" % i)).write_text(case["text"])
for i, case in enumerate(doc["malformed_hex"]):
    (out / "seeds-binary" / ("bad%03d" % i)).write_bytes(bytes.fromhex(case["hex"]))
for i, case in enumerate(doc["malformed_text"]):
    (out / "seeds-text" / ("bad%03d" % i)).write_text(case["text"])
PY

cd "$out"
for target in binary_decoder_fuzz text_parser_fuzz; do
  kind=binary; [ "$target" = text_parser_fuzz ] && kind=text
  mkdir -p "corpus-$kind"
  echo "== $target for ${seconds}s"
  "./$target" -max_total_time="$seconds" -max_len=4096 -timeout=10 -print_final_stats=1 \
    "corpus-$kind" "seeds-$kind"
done
