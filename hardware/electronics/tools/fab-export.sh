#!/usr/bin/env bash
# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: CERN-OHL-S-2.0
#
# The board's fabrication package, all from kicad-cli (KiCad 9, no display needed):
# Gerbers + job file, Excellon drill + map, pick-and-place CSV, BOM CSV (for the head BOM),
# schematic PDF, board STEP (for the head assembly) and a raytraced PNG render.
# Usage: fab-export.sh PROJECT_DIR/NAME OUT_DIR MODELS_DIR
# Runs with a throwaway HOME so no user configuration leaks in; the project's own
# sym-lib-table / fp-lib-table name the libraries.
set -euo pipefail

base=$1 out=$2 models=$3
sch=$base.kicad_sch pcb=$base.kicad_pcb
for f in "$sch" "$pcb"; do [ -f "$f" ] || { echo "fab-export: $f not found" >&2; exit 1; }; done
export HOME=$(mktemp -d) && trap 'rm -rf "$HOME"' EXIT
unset DISPLAY

rm -rf "$out" && mkdir -p "$out/gerbers"
kicad-cli pcb export gerbers -o "$out/gerbers/" \
  --layers F.Cu,In1.Cu,In2.Cu,B.Cu,F.Paste,B.Paste,F.Silkscreen,B.Silkscreen,F.Mask,B.Mask,Edge.Cuts "$pcb"
kicad-cli pcb export drill --format excellon --excellon-separate-th --generate-map --map-format pdf \
  -o "$out/gerbers/" "$pcb"
kicad-cli pcb export pos --format csv --units mm --side both --exclude-dnp -o "$out/pos.csv" "$pcb"
kicad-cli sch export bom --fields 'Reference,Value,Footprint,MPN,Manufacturer,${QUANTITY}' \
  --labels 'Reference,Value,Footprint,MPN,Manufacturer,Qty' --group-by 'Value,Footprint,MPN' \
  --exclude-dnp -o "$out/bom.csv" "$sch"
kicad-cli sch export pdf -o "$out/schematic.pdf" "$sch"
# Origin at the board centre (145, 130 mm on the page), so the head assembly can place it directly.
kicad-cli pcb export step --subst-models -f --user-origin 145x130mm -D "KICAD9_3DMODEL_DIR=$models" -o "$out/board.step" "$pcb"
kicad-cli pcb render -D "KICAD9_3DMODEL_DIR=$models" --width 1600 --height 1100 --side top \
  --quality high --rotate '-35,0,25' --perspective -o "$out/render.png" "$pcb"
echo "fab-export: package written to $out"
