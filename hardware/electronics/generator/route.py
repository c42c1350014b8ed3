# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: CERN-OHL-S-2.0
"""Route the placed board with Freerouting and pour the planes. Run with KiCad's python:
    /usr/bin/python3 route.py BOARD.kicad_pcb WORKDIR JAVA CLASSPATH

Steps: export Specctra DSN (pcbnew), limit tracks to the chosen layers (the current-carrying classes to
F.Cu), route single-threaded (Freerouting CLI, no neck-down), import the session, connect pads to the
zones solidly, add GND pours on F.Cu, In2.Cu and B.Cu, fill every zone, save.
"""
import os
import re
import subprocess
import sys

import pcbnew

import gen_board
import gen_project


def export_dsn(board, path, layers, outer_only=gen_project.OUTER_ONLY):
    """Specctra DSN with each net class limited to its layers: `layers` for most, F.Cu alone for the
    classes that carry the motor and supply currents (their widths are sized for outer copper, and a
    single layer leaves no via in the current path)."""
    if not pcbnew.ExportSpecctraDSN(board, path):
        raise RuntimeError(f"pcbnew could not export {path}")
    with open(path, encoding="utf-8") as f:
        text = f.read()

    def restrict(m):
        name = m.group(1)
        use = ["F.Cu"] if name in outer_only else layers
        return m.group(0) + "        (use_layer " + " ".join(use) + ")\n"

    text, n = re.subn(r"\(class (\S+)[^()]*\(circuit\n", restrict, text)
    if n == 0:
        raise RuntimeError(f"{path}: no net class (circuit ...) section to restrict to the routing layers")
    missing = [c for c in outer_only if not re.search(r"\(class " + re.escape(c) + r"\s", text)]
    if missing:
        raise RuntimeError(f"{path}: net classes {missing} (gen_project.OUTER_ONLY) are not in the DSN")
    with open(path, "w", encoding="utf-8") as f:
        f.write(text)


def run_freerouting(java, classpath, dsn, ses, workdir, passes=40):
    cmd = [java, "-Djava.awt.headless=true", "-cp", classpath, "app.freerouting.Freerouting",
           "--gui.enabled=false", f"--user_data_path={workdir}/freerouting-data",
           "-de", dsn, "-do", ses, "-mp", str(passes), "-mt", "1",
           # no neck-down at pins: a track narrowed to a pad's width would undo the current sizing
           "--router.automatic_neckdown=false"]
    log = os.path.join(workdir, "freerouting.log")
    with open(log, "w") as out:
        rc = subprocess.run(cmd, stdout=out, stderr=subprocess.STDOUT, timeout=1800).returncode
    if rc != 0 or not os.path.exists(ses):
        raise RuntimeError(f"freerouting failed (rc {rc}); see {log}")
    with open(log) as f:
        summary = [line for line in f if "session completed" in line]
    left = re.search(r"\((\d+) unrouted\)", summary[-1]) if summary else None
    if left:
        # Freerouting is not fully repeatable from run to run: keep the committed board, try again.
        raise RuntimeError(f"freerouting left {left.group(1)} connection(s) unrouted; board not saved (see {log})")


def widen_necks(board, classes=gen_project.OUTER_ONLY):
    """Freerouting narrows a track to the pad's width where it leaves a pin, even with automatic neck-down
    off (0.5 mm on the DRV8872's pins). Give every track of the current-carrying classes its class width
    back; DRC (tests/electronics/test_kicad_checks.py) confirms the clearances of the result."""
    widths = {name: pcbnew.FromMM(w) for name, w, *_ in gen_project.NET_CLASSES if name in classes}
    widened = 0
    for track in board.GetTracks():
        if track.Type() != pcbnew.PCB_TRACE_T:
            continue
        want = widths.get(track.GetNetClassName())
        if want and track.GetWidth() < want and not _inside_own_pad(board, track):
            track.SetWidth(want)
            widened += 1
    return widened


def _inside_own_pad(board, track):
    """A stub that lies wholly on one of its own net's pads adds no copper there: leave it as it is (widened,
    it could reach a neighbouring pin)."""
    for fp in board.GetFootprints():
        for pad in fp.Pads():
            if (pad.GetNetCode() == track.GetNetCode() and pad.IsOnLayer(track.GetLayer())
                    and pad.HitTest(track.GetStart()) and pad.HitTest(track.GetEnd())):
                return True
    return False


def finish(board):
    for zone in board.Zones():
        zone.SetPadConnection(pcbnew.ZONE_CONNECTION_FULL)
    gnd = board.FindNet("GND")
    # GND pours on every routed layer also stitch the In1 plane wherever tracks cut it
    for layer in (pcbnew.F_Cu, pcbnew.In2_Cu, pcbnew.B_Cu):
        pour = gen_board.add_zone(board, gnd, layer)
        pour.SetPadConnection(pcbnew.ZONE_CONNECTION_FULL)  # thermal spokes get starved between fine pads
        pour.SetMinThickness(pcbnew.FromMM(0.2))
    pcbnew.ZONE_FILLER(board).Fill(board.Zones())


def main(pcb, workdir, java, classpath, layers="F.Cu,In1.Cu,In2.Cu,B.Cu"):
    """layers: where tracks may go. All four (the default, used for the committed board): the GND
    and +12V planes stay in the DSN as conduction areas the router reaches through vias, and the
    outer GND pours stitch the GND plane wherever inner tracks cut it. Fewer layers: zones on the
    routed layers are taken out for routing and poured again afterwards."""
    layers = layers.split(",")
    all_layers = len(layers) == 4  # every layer routable: planes stay in the DSN as conduction areas
    os.makedirs(workdir, exist_ok=True)
    dsn, ses = os.path.join(workdir, "board.dsn"), os.path.join(workdir, "board.ses")
    board = pcbnew.LoadBoard(pcb)
    removed = []
    for zone in list(board.Zones()):
        if not all_layers and zone.GetLayer() in [board.GetLayerID(l) for l in layers]:
            removed.append((zone.GetNet(), zone.GetLayer()))
            board.Remove(zone)
    export_dsn(board, dsn, layers)
    run_freerouting(java, classpath, dsn, ses, workdir)
    if not pcbnew.ImportSpecctraSES(board, ses):
        raise RuntimeError(f"pcbnew could not import {ses}")
    for net, layer in removed:
        gen_board.add_zone(board, net, layer)
    widen_necks(board)
    finish(board)
    check_connected(board, workdir)
    pcbnew.SaveBoard(pcb, board)


def check_connected(board, workdir):
    """Freerouting can report a complete session that lacks a net's wiring (seen once: BOOT0 had no
    wire in the session, yet the log said nothing was unrouted). Count what the imported board leaves
    unconnected, as DRC would, and keep the committed board when anything is."""
    board.BuildConnectivity()
    left = board.GetConnectivity().GetUnconnectedCount(False)
    if left:
        raise RuntimeError(f"the routed board has {left} unconnected item(s) although freerouting reported none "
                           f"unrouted; board not saved (see {os.path.join(workdir, 'freerouting.log')})")


if __name__ == "__main__":
    main(*sys.argv[1:6])
