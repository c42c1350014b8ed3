#!/usr/bin/env bash
# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: CERN-OHL-S-2.0
#
# Extract only the KiCad 3-D models (STEP) a board uses from Debian's kicad-packages3d package.
# Installing that package would put 4.7 GB on the machine for the ~25 models the board needs, so the
# .deb (332 MB) is downloaded once with apt-get into a cache folder and read with dpkg-deb.
# Usage: fetch-3d-models.sh BOARD.kicad_pcb CACHE_DIR OUT_DIR   (OUT_DIR serves as KICAD9_3DMODEL_DIR)
set -euo pipefail

board=$1 cache=$2 out=$3
mkdir -p "$cache" "$out"

# Model paths the footprints reference, as STEP (kicad-cli --subst-models swaps .wrl for .step).
mapfile -t wanted < <(grep -o '(model "${KICAD9_3DMODEL_DIR}/[^"]*"' "$board" \
  | sed -e 's/^(model "${KICAD9_3DMODEL_DIR}\///' -e 's/"$//' -e 's/\.wrl$/.step/' | sort -u)
[ ${#wanted[@]} -gt 0 ] || { echo "fetch-3d-models: $board references no \${KICAD9_3DMODEL_DIR} models" >&2; exit 1; }

# A stamp records the set already extracted, so models absent from the package are not retried.
stamp="$out/.extracted"
missing=()
for m in "${wanted[@]}"; do [ -s "$out/$m" ] || grep -qxF "$m" "$stamp" 2>/dev/null || missing+=("$m"); done
[ ${#missing[@]} -eq 0 ] && exit 0

deb=$(ls "$cache"/kicad-packages3d_*.deb 2>/dev/null | head -n1 || true)
if [ -z "$deb" ]; then
  echo "fetch-3d-models: downloading kicad-packages3d (332 MB, once) into $cache"
  (cd "$cache" && apt-get download -q kicad-packages3d/bookworm-backports)
  deb=$(ls "$cache"/kicad-packages3d_*.deb | head -n1)
fi

prefix=./usr/share/kicad/3dmodels
members=()
for m in "${missing[@]}"; do members+=("$prefix/$m"); done
# tar exits non-zero when a named member is absent (a few footprints have no model in the package);
# what was really extracted is checked right after.
dpkg-deb --fsys-tarfile "$deb" | tar -x -C "$out" --strip-components=5 "${members[@]}" 2>/dev/null || true
found=0
for m in "${missing[@]}"; do
  if [ -s "$out/$m" ]; then found=$((found + 1)); else echo "fetch-3d-models: warning: no model $m in $deb" >&2; fi
done
printf '%s\n' "${missing[@]}" >> "$stamp"
have=0
for m in "${wanted[@]}"; do [ -s "$out/$m" ] && have=$((have + 1)); done
[ "$have" -gt 0 ] || { echo "fetch-3d-models: could not extract any model from $deb" >&2; exit 1; }
echo "fetch-3d-models: $found model(s) extracted; $have of ${#wanted[@]} available in $out"
