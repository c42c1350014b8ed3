# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: CERN-OHL-S-2.0
"""Route the placed board with Freerouting and pour the planes. Run with KiCad's python:
    /usr/bin/python3 route.py BOARD.kicad_pcb WORKDIR JAVA CLASSPATH

Steps: export Specctra DSN (pcbnew), limit tracks to the chosen layers, route single-threaded
(Freerouting CLI), import the session, connect pads to the zones solidly, add GND pours on F.Cu and
B.Cu, fill every zone, save. With F.Cu/B.Cu only, Freerouting left about 25 connections open on
this placement; with all four layers it completes.
"""
import os
import re
import subprocess
import sys

import pcbnew

import gen_board


def export_dsn(board, path, layers):
    if not pcbnew.ExportSpecctraDSN(board, path):
        raise RuntimeError(f"pcbnew could not export {path}")
    with open(path, encoding="utf-8") as f:
        text = f.read()
    # Tracks only on the outer layers: the inner layers stay whole GND / +12V planes.
    text, n = re.subn(r"\(circuit\n", "(circuit\n        (use_layer " + " ".join(layers) + ")\n", text)
    if n == 0:
        raise RuntimeError(f"{path}: no net class (circuit ...) section to restrict to the outer layers")
    with open(path, "w", encoding="utf-8") as f:
        f.write(text)


def run_freerouting(java, classpath, dsn, ses, workdir, passes=40):
    cmd = [java, "-Djava.awt.headless=true", "-cp", classpath, "app.freerouting.Freerouting",
           "--gui.enabled=false", f"--user_data_path={workdir}/freerouting-data",
           "-de", dsn, "-do", ses, "-mp", str(passes), "-mt", "1"]
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


def finish(board):
    for zone in board.Zones():
        zone.SetPadConnection(pcbnew.ZONE_CONNECTION_FULL)
    gnd = board.FindNet("GND")
    for layer in (pcbnew.F_Cu, pcbnew.B_Cu):  # outer GND pours also stitch any plane the tracks cut
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
