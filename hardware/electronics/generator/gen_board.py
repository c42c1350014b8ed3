# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: CERN-OHL-S-2.0
"""Build the unrouted board (.kicad_pcb) from the schematic's netlist, the way pcbnew's
"Update PCB from Schematic" does: footprints from KiCad's libraries, schematic links, nets.

Placement: connectors, ICs and mounting holes sit at fixed positions (ANCHORS); every other part is
placed by a deterministic search for the free spot nearest to the pads it connects to.
Layers (a declared 4-layer stackup, 2 oz outer and 1 oz inner copper): F.Cu parts, signals and the wide current paths, In1.Cu GND
plane, In2.Cu signals and GND pour, B.Cu signals and GND pour. Run with KiCad's python:
    /usr/bin/python3 gen_board.py NETLIST.net OUT.kicad_pcb
"""
import math
import re
import os
import sys

import pcbnew

import design

from sexpr import find, find1, parse
from kicad_lib import FOOTPRINT_DIR

W, H = 90.0, 60.0           # board size, mm
OX, OY = 100.0, 100.0       # board origin on the KiCad canvas
EDGE_MARGIN = 0.6           # courtyard to board edge
GAP = 0.3                   # courtyard to courtyard

# ref: (x, y, rotation degrees) relative to the board's top-left corner
ANCHORS = {
    "H1": (4.2, 4.2, 0), "H2": (W - 4.2, 4.2, 0), "H3": (4.2, H - 4.2, 0), "H4": (W - 4.2, H - 4.2, 0),
    # daisy-chain power in (J1) and out (J5): pin 1 of each face the other, so the pass-through is short
    "J1": (5.0, 17.0, 90), "J5": (6.0, 22.3, 270),
    "J2": (4.0, 37.0, 90), "J3": (4.0, 48.0, 90), "JP1": (12.5, 49.0, 0),
    "U4": (17.0, 40.0, 0), "Q1": (22.0, 12.0, 0), "F1": (15.0, 8.0, 0), "D1": (15.0, 17.0, 0),
    "U2": (33.0, 8.0, 0), "L1": (40.0, 8.0, 0), "U3": (45.5, 8.0, 0),
    # right-angle SWD/BOOT0 header: its pins point at the top edge, where a cable reaches it in the stack
    "J4": (50.5, 11.3, 90),
    "U1": (44.0, 31.0, 0), "Y1": (34.0, 29.5, 0),
    "U5": (68.0, 16.5, 0), "U6": (68.0, 24.5, 0), "J20": (84.0, 18.0, 90),
    "U7": (68.0, 37.0, 0), "U8": (68.0, 46.5, 0), "J30": (84.0, 40.0, 90),
    # the Kelvin shunts right of and below their driver, far enough right that the OUT1 track passes
    # between the driver's VM pin and the shunt's sense pad (placed by the search, one sat in the way)
    "R30": (76.0, 22.5, 90), "R40": (76.0, 43.0, 90),
    "J21": (20.0, 55.0, 0), "J22": (31.5, 55.0, 0), "J31": (47.0, 55.0, 0), "J32": (58.5, 55.0, 0),
    # encoder buffers between their connector and the MCU: inputs face the connector, outputs the MCU
    "U9": (31.0, 45.0, 90), "U10": (53.0, 45.0, 90),
    # the absolute encoders' data buffer and their 3.3 V -> 5 V level shifter, between the MCU and J22/J32
    "U11": (42.0, 45.0, 90), "U12": (47.5, 46.0, 90),
    # the brake connectors (rev D) at the right edge between the motor connectors, each beside its motor's:
    # the +12V track reaches them on F.Cu from the drivers' supply between the two axis blocks
    "J23": (84.5, 23.2, 0), "J33": (84.5, 29.2, 0),
    # their switches between the two axis blocks, next to the headers (placed by the search, they crowded the
    # MCU's right side, and the routing there failed)
    "Q30": (73.2, 30.0, 90), "Q40": (77.0, 30.0, 90),
}
POWER_NETS = {"GND", "+12V", "+3V3", "+5V"}
REVISION_TEXT_AT = (W / 2, 21.5)  # bottom silkscreen, clear of the through-hole pads
# Parts joined to the rest only by supply nets (decoupling, bulk) go next to the part they serve; so do
# the encoder inputs' pull-downs, which the many GND pads would otherwise pull towards the board centre.
NEAR = {"C1": "Q1", "R1": "Q1", "D2": "Q1", "C3": "U2", "C4": "U2", "C5": "L1", "C6": "L1", "C7": "U3",
        "C8": "U3", "C9": "U1", "C10": "U1", "C11": "U1", "C12": "U1", "C16": "U4", "D4": "U4",
        "C30": "U5", "C31": "U5", "C32": "U6", "C40": "U7", "C41": "U7", "C42": "U8", "R6": "JP1",
        "C33": "U9", "C43": "U10", "R31": "U9", "R32": "U9", "R41": "U10", "R42": "U10",
        "C17": "U11", "R8": "U11", "FB1": "U2", "C18": "U12", "R9": "U12", "R10": "U12", "R11": "U12",
        "D30": "J23", "D40": "J33", "R33": "Q30", "R43": "Q40"}


def mm(v):
    return pcbnew.FromMM(v)


def pt(x, y):
    return pcbnew.VECTOR2I(mm(OX + x), mm(OY + y))


def read_netlist(path):
    with open(path, encoding="utf-8") as f:
        root = parse(f.read(), path)
    comps = []
    for c in find(find1(root, "components"), "comp"):
        fields = {f[1][1]: (f[2] if len(f) > 2 else "") for f in find(find1(c, "fields") or [], "field")}
        comps.append({"ref": find1(c, "ref")[1], "value": find1(c, "value")[1],
                      "footprint": find1(c, "footprint")[1], "fields": fields,
                      "tstamp": find1(c, "tstamps")[1], "sheetfile": find1(find1(c, "sheetpath"), "names")[1],
                      "excluded": any(p[1][1] in ("exclude_from_bom", "exclude_from_board")
                                      for p in find(c, "property") if len(p) > 1 and isinstance(p[1], list))})
    nets = {}
    for n in find(find1(root, "nets"), "net"):
        name = find1(n, "name")[1]
        for node in find(n, "node"):
            nets.setdefault(name, []).append((find1(node, "ref")[1], find1(node, "pin")[1]))
    return comps, nets


def load_footprint(lib_id):
    lib, name = lib_id.split(":")
    fp = pcbnew.FootprintLoad(os.path.join(FOOTPRINT_DIR, lib + ".pretty"), name)
    if fp is None:
        raise FileNotFoundError(f"footprint {lib_id} not found under {FOOTPRINT_DIR}")
    fp.SetFPIDAsString(lib_id)
    return fp


def courtyard(fp):
    bb = fp.GetCourtyard(pcbnew.F_CrtYd).BBox()
    if bb.GetWidth() == 0:
        bb = fp.GetBoundingBox(False)
    return (bb.GetX() / 1e6 - OX, bb.GetY() / 1e6 - OY,
            (bb.GetX() + bb.GetWidth()) / 1e6 - OX, (bb.GetY() + bb.GetHeight()) / 1e6 - OY)


def _overlaps(a, b):
    return not (a[2] + GAP <= b[0] or b[2] + GAP <= a[0] or a[3] + GAP <= b[1] or b[3] + GAP <= a[1])


def _inside(a):
    return a[0] >= EDGE_MARGIN and a[1] >= EDGE_MARGIN and a[2] <= W - EDGE_MARGIN and a[3] <= H - EDGE_MARGIN


def place_free(fp, target, boxes):
    """Nearest free position to `target` on a 0.5 mm grid (ring search), rotations 0 and 90."""
    tx, ty = round(target[0] * 2) / 2, round(target[1] * 2) / 2
    for ring in range(0, 200):
        cands = []
        for i in range(-ring, ring + 1):
            for j in range(-ring, ring + 1):
                if max(abs(i), abs(j)) != ring:
                    continue
                cands.append((math.hypot(i, j), i, j))
        for _, i, j in sorted(cands):
            for rot in (0, 90):
                fp.SetOrientationDegrees(rot)
                fp.SetPosition(pt(tx + i * 0.5, ty + j * 0.5))
                box = courtyard(fp)
                if _inside(box) and not any(_overlaps(box, b) for b in boxes):
                    return box
    raise RuntimeError(f"no free spot for {fp.GetReference()} near {target}")


def add_outline(board):
    corners = [(0, 0), (W, 0), (W, H), (0, H)]
    for (x0, y0), (x1, y1) in zip(corners, corners[1:] + corners[:1]):
        seg = pcbnew.PCB_SHAPE(board, pcbnew.SHAPE_T_SEGMENT)
        seg.SetStart(pt(x0, y0))
        seg.SetEnd(pt(x1, y1))
        seg.SetLayer(pcbnew.Edge_Cuts)
        seg.SetWidth(mm(0.1))
        board.Add(seg)


def add_zone(board, net, layer, priority=0):
    zone = pcbnew.ZONE(board)
    zone.SetLayer(layer)
    zone.SetNet(net)
    zone.SetAssignedPriority(priority)
    zone.SetLocalClearance(mm(0.3))
    zone.SetMinThickness(mm(0.25))
    zone.SetThermalReliefGap(mm(0.4))
    zone.SetThermalReliefSpokeWidth(mm(0.5))
    zone.SetIslandRemovalMode(pcbnew.ISLAND_REMOVAL_MODE_ALWAYS)
    outline = zone.Outline()
    outline.NewOutline()
    for x, y in [(0.5, 0.5), (W - 0.5, 0.5), (W - 0.5, H - 0.5), (0.5, H - 0.5)]:
        outline.Append(mm(OX + x), mm(OY + y))
    board.Add(zone)
    return zone


# The declared stackup (1.6 mm, 4 layers): 2 oz (70 um) finished copper outside, where the motor and supply
# currents run, 1 oz (35 um) inside. The copper check (tests/electronics/test_copper_capacity.py) takes each
# layer's thickness from here. 2 oz lets 0.7 mm tracks carry the driver's 3.6 A, narrow enough to leave the
# DRV8872's adjacent 1.27 mm-pitch VM and OUT1 pins side by side (two 1.2 mm tracks, what 1 oz needs, cannot).
STACKUP = [("F.Cu", "copper", 0.07), ("dielectric 1", "prepreg", 0.2104), ("In1.Cu", "copper", 0.035),
           ("dielectric 2", "core", 0.9492), ("In2.Cu", "copper", 0.035), ("dielectric 3", "prepreg", 0.2104),
           ("B.Cu", "copper", 0.07)]


def declare_stackup(path):
    """Write the stackup into the saved board's setup section (pcbnew's Python API does not expose the
    stackup descriptor); pcbnew reads it back and keeps it on every later save."""
    with open(path, encoding="utf-8") as f:
        text = f.read()
    if "(stackup" in text:
        raise RuntimeError(f"{path}: already has a stackup")
    rows = ['\t\t\t(layer "F.SilkS"\n\t\t\t\t(type "Top Silk Screen")\n\t\t\t)',
            '\t\t\t(layer "F.Paste"\n\t\t\t\t(type "Top Solder Paste")\n\t\t\t)',
            '\t\t\t(layer "F.Mask"\n\t\t\t\t(type "Top Solder Mask")\n\t\t\t\t(thickness 0.01)\n\t\t\t)']
    for name, kind, thickness in STACKUP:
        if kind == "copper":
            rows.append(f'\t\t\t(layer "{name}"\n\t\t\t\t(type "copper")\n\t\t\t\t(thickness {thickness})\n\t\t\t)')
        else:
            rows.append(f'\t\t\t(layer "{name}"\n\t\t\t\t(type "{kind}")\n\t\t\t\t(thickness {thickness})\n'
                        f'\t\t\t\t(material "FR4")\n\t\t\t\t(epsilon_r 4.5)\n\t\t\t\t(loss_tangent 0.02)\n\t\t\t)')
    rows += ['\t\t\t(layer "B.Mask"\n\t\t\t\t(type "Bottom Solder Mask")\n\t\t\t\t(thickness 0.01)\n\t\t\t)',
             '\t\t\t(layer "B.Paste"\n\t\t\t\t(type "Bottom Solder Paste")\n\t\t\t)',
             '\t\t\t(layer "B.SilkS"\n\t\t\t\t(type "Bottom Silk Screen")\n\t\t\t)',
             '\t\t\t(copper_finish "ENIG")\n\t\t\t(dielectric_constraints no)']
    block = "\t\t(stackup\n" + "\n".join(rows) + "\n\t\t)\n"
    text, n = re.subn(r"(\n\t\(setup\n)", lambda m: m.group(1) + block, text, count=1)
    if n != 1:
        raise RuntimeError(f"{path}: no (setup ...) section to put the stackup in")
    with open(path, "w", encoding="utf-8") as f:
        f.write(text)


def add_revision(board, box_of):
    """The revision in the board's title block (the Gerber job file takes it from there) and on the
    silkscreen, on the bottom side, which carries no parts."""
    tb = board.GetTitleBlock()
    tb.SetTitle("Robogene head motor-control board (2 DC motors, CAN)")
    tb.SetRevision(design.REVISION)
    tb.SetDate("2026-11-26")
    tb.SetCompany("Robogene contributors")
    tb.SetComment(0, "CERN-OHL-S-2.0")
    text = pcbnew.PCB_TEXT(board)
    text.SetText(f"ROBOGENE MOTOR BOARD REV {design.REVISION}")
    text.SetLayer(pcbnew.B_SilkS)
    text.SetMirrored(True)
    text.SetTextSize(pcbnew.VECTOR2I(mm(1.2), mm(1.2)))
    text.SetTextThickness(mm(0.18))
    text.SetPosition(pt(*REVISION_TEXT_AT))
    board.Add(text)


def build(netlist, out):
    comps, nets = read_netlist(netlist)
    board = pcbnew.NewBoard(out)
    board.SetCopperLayerCount(4)
    netinfo = {}
    for name in sorted(nets):
        ni = pcbnew.NETINFO_ITEM(board, name)
        board.Add(ni)
        netinfo[name] = ni
    pad_net = {(r, p): n for n, nodes in nets.items() for r, p in nodes}

    fps = {}
    for c in comps:
        fp = load_footprint(c["footprint"])
        fp.SetReference(c["ref"])
        fp.SetValue(c["value"])
        for key in ("MPN", "Manufacturer"):
            if c["fields"].get(key):
                fp.SetField(key, c["fields"][key])
                fp.GetFieldByName(key).SetVisible(False)
        # Designators live on the fabrication layer (F.Fab) only: at this density silkscreen
        # references would overlap pads and each other.
        fp.Reference().SetVisible(False)
        fp.SetPath(pcbnew.KIID_PATH("/" + c["tstamp"]))
        fp.SetSheetname("/")
        fp.SetSheetfile(c["sheetfile"] if c["sheetfile"].endswith(".kicad_sch") else os.path.basename(out).replace(".kicad_pcb", ".kicad_sch"))
        for pad in fp.Pads():
            net = pad_net.get((c["ref"], pad.GetNumber()))
            if net:
                pad.SetNet(netinfo[net])
        board.Add(fp)
        fps[c["ref"]] = fp

    boxes, problems = [], []
    for ref, (x, y, rot) in ANCHORS.items():
        fp = fps[ref]
        fp.SetOrientationDegrees(rot)
        fp.SetPosition(pt(x, y))
        box = courtyard(fp)
        problems += [f"anchored {ref} overlaps {o} ({_fmt(box)} / {_fmt(b)})" for o, b in boxes if _overlaps(box, b)]
        if not _inside(box):
            problems.append(f"anchored {ref} leaves the board: {_fmt(box)}")
        boxes.append((ref, box))
    if problems:
        raise RuntimeError("placement:\n  " + "\n  ".join(problems))

    placed = set(ANCHORS)
    pending = sorted(r for r in fps if r not in placed)
    while pending:
        # Next: the part with most signal links to what is already placed (then the biggest), so
        # chains like MCU pin -> resistor -> LED are placed link by link, each near its neighbour.
        ref = max(pending, key=lambda r: (_links(r, fps, placed, pad_net), _area(fps[r]), _refkey(r)))
        pending.remove(ref)
        target = _target(ref, fps, placed, pad_net)
        box = place_free(fps[ref], target, [b for _, b in boxes])
        boxes.append((ref, box))
        placed.add(ref)

    add_outline(board)
    add_zone(board, netinfo["GND"], pcbnew.In1_Cu)
    add_revision(board, box_of={r: b for r, b in boxes})
    board.BuildConnectivity()
    pcbnew.SaveBoard(out, board)
    declare_stackup(out)
    return board


def _fmt(box):
    return "x %.2f..%.2f y %.2f..%.2f" % (box[0], box[2], box[1], box[3])


def _area(fp):
    b = courtyard(fp)
    return (b[2] - b[0]) * (b[3] - b[1])


def _refkey(ref):
    head = ref.rstrip("0123456789")
    return head, -int(ref[len(head):] or 0)


def _links(ref, fps, placed, pad_net):
    if NEAR.get(ref) in placed:
        return 1000  # decoupling first, right beside its host
    mine = {pad_net.get((ref, p.GetNumber())) for p in fps[ref].Pads()} - {None} - POWER_NETS
    return sum(1 for other in placed for p in fps[other].Pads() if pad_net.get((other, p.GetNumber())) in mine)


def _target(ref, fps, placed, pad_net):
    """Centre of the placed pads that share a net with this part (signal nets count 4x)."""
    pts = []
    mine = {pad_net.get((ref, p.GetNumber())) for p in fps[ref].Pads()} - {None}
    if ref in NEAR:
        host = NEAR[ref]
        placed = [host]
        shared = [p for p in fps[host].Pads() if pad_net.get((host, p.GetNumber())) in mine]
        if shared:
            pos = [(p.GetPosition().x / 1e6 - OX, p.GetPosition().y / 1e6 - OY) for p in shared]
            return (sum(p[0] for p in pos) / len(pos), sum(p[1] for p in pos) / len(pos))
    for other in placed:
        for pad in fps[other].Pads():
            net = pad_net.get((other, pad.GetNumber()))
            if net in mine and not net.startswith("unconnected"):
                weight = 1 if net in POWER_NETS else 4
                pos = pad.GetPosition()
                pts += [(pos.x / 1e6 - OX, pos.y / 1e6 - OY)] * weight
    if not pts:
        return (W / 2, H / 2)
    return (sum(p[0] for p in pts) / len(pts), sum(p[1] for p in pts) / len(pts))


if __name__ == "__main__":
    build(sys.argv[1], sys.argv[2])
