# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: CERN-OHL-S-2.0
"""Write the board's schematic (.kicad_sch) from design.py.

Every symbol comes from KiCad's own libraries. Each connected pin gets a short wire stub ending in a
net label (or a power symbol for the supply nets); open pins get a no-connect flag. Parts are laid
out block by block (power, MCU, CAN, one block per motor axis). Output is deterministic.
"""
import sys
import uuid

import design
from kicad_lib import flattened_symbol, pins, units
from sexpr import Sym, dump

PROJECT = "robogene-motor-board"
GRID = 2.54
STUB = 2.54
CHAR_W = 1.05  # width of one 1.27 mm label character, for spacing estimates
S = Sym


def uid(*key):
    return str(uuid.uuid5(uuid.NAMESPACE_URL, "robogene/" + PROJECT + "/" + "/".join(key)))


ROOT_UUID = uid("root")


def snap(v):
    return round(round(v / GRID) * GRID, 4)


def _effects(size=1.27, justify=None, hide=False):
    e = [S("effects"), [S("font"), [S("size"), size, size]]]
    if justify:
        e.append([S("justify")] + [S(j) for j in justify.split()])
    if hide:
        e.append([S("hide"), S("yes")])
    return e


def _prop(name, value, x, y, hide=False, justify=None, angle=0):
    return [S("property"), name, value, [S("at"), x, y, angle], _effects(justify=justify, hide=hide)]


# outward direction of a pin (screen coordinates, y down) from its angle in the library (y up)
_OUT = {0: (-1, 0), 180: (1, 0), 90: (0, 1), 270: (0, -1)}


def _label_angle(dx, dy):
    return {(1, 0): 0, (-1, 0): 180, (0, -1): 90, (0, 1): 270}[(dx, dy)]


def _label_justify(angle):
    return {0: "left bottom", 180: "right bottom", 90: "left bottom", 270: "right bottom"}[angle]


def _power_rotation(net, dx, dy):
    if net == "GND":  # body below the pin
        return {(0, 1): 0, (0, -1): 180, (1, 0): 90, (-1, 0): 270}[(dx, dy)]
    return {(0, -1): 0, (0, 1): 180, (-1, 0): 90, (1, 0): 270}[(dx, dy)]


class Sheet:
    def __init__(self):
        self.items = []
        self.lib_ids = []
        self.pwr_count = 0

    def lib(self, lib_id):
        if lib_id not in self.lib_ids:
            self.lib_ids.append(lib_id)

    def wire(self, a, b, key):
        self.items.append([S("wire"), [S("pts"), [S("xy"), a[0], a[1]], [S("xy"), b[0], b[1]]],
                           [S("stroke"), [S("width"), 0], [S("type"), S("default")]], [S("uuid"), uid("wire", key)]])

    def label(self, net, x, y, angle, key):
        self.items.append([S("label"), net, [S("at"), x, y, angle], [S("fields_autoplaced"), S("yes")],
                           _effects(justify=_label_justify(angle)), [S("uuid"), uid("label", key)]])

    def no_connect(self, x, y, key):
        self.items.append([S("no_connect"), [S("at"), x, y], [S("uuid"), uid("nc", key)]])

    def text(self, s, x, y, size=2.54, key=None):
        self.items.append([S("text"), s, [S("exclude_from_sim"), S("no")], [S("at"), x, y, 0],
                           _effects(size=size, justify="left bottom"), [S("uuid"), uid("text", key or s)]])

    def symbol(self, lib_id, ref, value, x, y, props, pin_numbers, key, in_bom=True, angle=0, hide_ref=False,
               ref_at=None, value_at=None, unit=1):
        self.lib(lib_id)
        ref_at = ref_at or (x, y - 5)
        value_at = value_at or (x, y + 5)
        node = [S("symbol"), [S("lib_id"), lib_id], [S("at"), x, y, angle], [S("unit"), unit],
                [S("exclude_from_sim"), S("no")], [S("in_bom"), S("yes" if in_bom else "no")],
                [S("on_board"), S("yes")], [S("dnp"), S("no")], [S("uuid"), uid("sym", key)],
                _prop("Reference", ref, ref_at[0], ref_at[1], hide=hide_ref, justify="left"),
                _prop("Value", value, value_at[0], value_at[1], justify="left")]
        for name, val in props:
            node.append(_prop(name, val, x, y, hide=True))
        for num in sorted(set(pin_numbers), key=lambda s: (len(s), s)):
            node.append([S("pin"), num, [S("uuid"), uid("pin", key, num)]])
        node.append([S("instances"), [S("project"), PROJECT, [S("path"), "/" + ROOT_UUID, [S("reference"), ref],
                                                             [S("unit"), unit]]]])
        self.items.append(node)

    def power(self, net, x, y, dx, dy):
        self.pwr_count += 1
        ref = f"#PWR{self.pwr_count:03d}"
        rot = _power_rotation(net, dx, dy)
        self.symbol("power:" + net, ref, net, x, y, [("Footprint", ""), ("Datasheet", ""), ("Description", "")],
                    ["1"], ref, angle=rot, hide_ref=True, ref_at=(x, y), value_at=(x + 2 * dx, y + 2 * dy + (2 if dy == 0 else 0)))


def _extent(part, unit=1):
    """Bounding box of a placed unit (pins + stubs + labels), relative to its origin, screen coords."""
    xs, ys = [0.0], [0.0]
    for num, name, etype, px, py, ang in units(part.lib_id)[unit]:
        dx, dy = _OUT[ang]
        net = part.pins.get(num)
        length = STUB + (0 if net in design.POWER_NETS or net is None else len(net) * CHAR_W + 1)
        if net in design.POWER_NETS:
            length += 5
        xs += [px, px + dx * length]
        ys += [-py, -py + dy * length]
    return min(xs) - 2, max(xs) + 2, min(ys) - 7, max(ys) + 7


def place(sheet, part, ox, oy, unit=1):
    """Place one unit of the part (single-unit symbols have unit 1 only) with its stubs and labels."""
    ox, oy = snap(ox), snap(oy)
    lib_pins = units(part.lib_id)[unit]
    declared = set(part.pins)
    known = {p[0] for p in pins(part.lib_id)}
    if declared - known:
        raise ValueError(f"{part.ref}: pins {sorted(declared - known)} not in symbol {part.lib_id}")
    by_pos = {}
    for num, name, etype, px, py, ang in lib_pins:
        if num not in part.pins and etype != "no_connect":
            raise ValueError(f"{part.ref}: pin {num} ({name}) of {part.lib_id} has no net in design.py")
        by_pos.setdefault((px, py, ang), []).append(num)
    for (px, py, ang), nums in sorted(by_pos.items()):
        nets = {part.pins.get(n) for n in nums if n in part.pins}
        if len(nets) > 1:
            raise ValueError(f"{part.ref}: stacked pins {nums} are given different nets {sorted(map(str, nets))}")
        if not nets:
            continue
        net = nets.pop()
        x, y = round(ox + px, 4), round(oy - py, 4)
        key = f"{part.ref}/{nums[0]}"
        if net is None:
            sheet.no_connect(x, y, key)
            continue
        dx, dy = _OUT[ang]
        ex, ey = round(x + dx * STUB, 4), round(y + dy * STUB, 4)
        sheet.wire((x, y), (ex, ey), key)
        if net in design.POWER_NETS:
            sheet.power(net, ex, ey, dx, dy)
        else:
            sheet.label(net, ex, ey, _label_angle(dx, dy), key)
    x0, x1, y0, y1 = _extent(part, unit)
    props = [("Footprint", part.footprint), ("Datasheet", "~"), ("Description", part.description or part.value),
             ("MPN", part.mpn), ("Manufacturer", part.manufacturer)]
    sheet.symbol(part.lib_id, part.ref, part.value, ox, oy, props, [p[0] for p in lib_pins],
                 part.ref if unit == 1 else f"{part.ref}/unit{unit}", in_bom=part.in_bom,
                 ref_at=(snap(ox + x0 + 2), snap(oy + y0 + 4)), value_at=(snap(ox + x0 + 2), snap(oy + y1 - 2)),
                 unit=unit)


# Block frames on an A2 sheet (594 x 420 mm; A3 became too small with the encoder buffers):
# (title, x, y, width)
PAPER = ("A2", 594, 420)
BLOCKS = {
    "power": ("Supply: daisy-chain in/out, fuse, reverse polarity, TVS, 12 V -> 5 V buck, 5 V -> 3.3 V LDO, bus sense", 15, 20, 280),
    "mcu": ("Microcontroller STM32G431 (FDCAN), crystal, edge SWD/BOOT0 header, status LED", 310, 20, 270),
    "can": ("CAN bus: transceiver, ESD, daisy-chain connectors, jumper-selectable 120 ohm termination", 15, 125, 280),
    "axis1": ("Motor 1: H-bridge, inline current sense, motor and encoder connectors, encoder buffer, brake switch", 15, 195, 280),
    "axis2": ("Motor 2: H-bridge, inline current sense, motor and encoder connectors, encoder buffer, brake switch", 310, 250, 270),
    "mech": ("Mounting holes (M3)", 15, 315, 75),
    "aea": ("Absolute encoders: data buffer to PB4 (5 V in, 3.3 V out), CLK/CS/MOSI level shifter (3.3 V in, 5 V out)", 310, 125, 270),
}
# KiCad's default drawing sheet: a border 10 mm in with a 2 mm ruler strip inside it, and the title
# block within 110 x 34 mm of the border's bottom-right corner.
BORDER = 12
TITLE_BLOCK = (110, 34)


def _check_layout(boxes):
    """Every unit stays on the drawing, clear of the title block and of the other blocks' units."""
    _, width, height = PAPER
    tb = (width - 10 - TITLE_BLOCK[0], height - 10 - TITLE_BLOCK[1], width - 10, height - 10)
    problems = []
    for name, block, box in boxes:
        if box[0] < BORDER or box[1] < BORDER or box[2] > width - BORDER or box[3] > height - BORDER:
            problems.append(f"{name} ({block}) leaves the drawing: {_fmt_box(box)}")
        if _boxes_overlap(box, tb):
            problems.append(f"{name} ({block}) runs into the title block: {_fmt_box(box)}")
    for i, (name, block, box) in enumerate(boxes):
        for other, other_block, other_box in boxes[i + 1:]:
            if block != other_block and _boxes_overlap(box, other_box):
                problems.append(f"{name} ({block}) overlaps {other} ({other_block}): {_fmt_box(box)} / {_fmt_box(other_box)}")
    if problems:
        raise ValueError("schematic layout (gen_schematic.BLOCKS):\n  " + "\n  ".join(problems))


def _boxes_overlap(a, b):
    return a[0] < b[2] and b[0] < a[2] and a[1] < b[3] and b[1] < a[3]


def _fmt_box(box):
    return "x %.1f..%.1f y %.1f..%.1f" % (box[0], box[2], box[1], box[3])


def build():
    sheet = Sheet()
    by_block = {}
    for p in design.parts():
        by_block.setdefault(p.block, []).append(p)
    boxes = []
    for block, plist in by_block.items():
        title, bx, by, bw = BLOCKS[block]
        sheet.text(title, bx, by, key=block)
        x, y, row_h = bx, by + 6, 0
        for p, unit in ((p, u) for p in plist for u in units(p.lib_id)):
            x0, x1, y0, y1 = _extent(p, unit)
            w, h = x1 - x0, y1 - y0
            if x + w > bx + bw and x > bx:
                x, y, row_h = bx, y + row_h + 4, 0
            place(sheet, p, x - x0, y - y0, unit)
            boxes.append((p.ref if len(units(p.lib_id)) == 1 else f"{p.ref} unit {unit}", block, (x, y, x + w, y + h)))
            x += w + 4
            row_h = max(row_h, h)
    _check_layout(boxes)
    # supplies driven through passive parts (the FET, the buck's ferrite bead) need a flag
    for i, net in enumerate(("+12V", "GND", "+5V", "VIN_BUCK")):
        fx, fy = snap(200 + 20 * i), snap(150)
        sheet.symbol("power:PWR_FLAG", f"#FLG0{i + 1}", "PWR_FLAG", fx, fy,
                     [("Footprint", ""), ("Datasheet", "~"), ("Description", "")], ["1"], f"flag{i}",
                     hide_ref=True, ref_at=(fx, fy - 5), value_at=(fx, fy - 6))
        sheet.wire((fx, fy), (fx, fy + STUB), f"flag{i}")
        if net in design.POWER_NETS:
            sheet.power(net, fx, fy + STUB, 0, 1)
        else:
            sheet.label(net, fx, fy + STUB, 270, f"flag{i}")
    return sheet


def render(sheet):
    libs = [S("lib_symbols")] + [flattened_symbol(l) for l in sorted(sheet.lib_ids)]
    root = [S("kicad_sch"), [S("version"), 20250114], [S("generator"), "robogene_gen_schematic"],
            [S("generator_version"), "9.0"], [S("uuid"), ROOT_UUID], [S("paper"), PAPER[0]],
            [S("title_block"), [S("title"), "Robogene head motor-control board (2 DC motors, CAN)"],
             [S("date"), "2026-11-26"], [S("rev"), design.REVISION], [S("company"), "Robogene contributors"],
             [S("comment"), 1, "CERN-OHL-S-2.0"],
             [S("comment"), 2, "Generated by hardware/electronics/generator/gen_schematic.py from design.py"],
             # Split: only generated files may hold the phrase (tests/codegen/test_manifest.py).
             [S("comment"), 3, "Do not" " edit: change design.py and run make generate"]],
            libs] + sheet.items + [[S("sheet_instances"), [S("path"), "/", [S("page"), "1"]]],
                                   [S("embedded_fonts"), S("no")]]
    return dump(root) + "\n"


def main(out):
    text = render(build())
    with open(out, "w", encoding="utf-8") as f:
        f.write(text)


if __name__ == "__main__":
    main(sys.argv[1])
