# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: CERN-OHL-S-2.0
"""Write the project-local library tables and the .kicad_pro (design rules, net classes).

The tables name only the libraries this design uses, through KiCad's own ${KICAD9_*_DIR} variables,
so kicad-cli finds every symbol and footprint even with a fresh HOME (no global tables).
"""
import json
import os
import sys

import design

NET_CLASSES = [
    # name, track width, clearance, via diameter, via drill, nets. The widths carry each net's current on
    # the declared 2 oz outer copper at a 20 degC rise (IPC-2221; tests/electronics/test_copper_capacity.py
    # checks the routed board), and route.py keeps these classes on F.Cu, so no via sits in their path.
    ("Default", 0.25, 0.2, 0.6, 0.3, []),
    # local-label nets carry the root sheet's "/" prefix
    # the daisy chain's pass-through: every board's current, J1 -> J5 (7.8 A for the head; 1.9 mm: 8.5 A)
    ("Chain", 1.9, 0.25, 0.8, 0.4, ["/VIN_RAW"]),
    # fuse to the reverse-polarity FET: up to the 5 A fuse rating (1.0 mm: 5.3 A)
    ("Input", 1.0, 0.2, 0.8, 0.4, ["/VIN_FUSED"]),
    # each H-bridge's supply and motor leads: the DRV8872's 3.6 A (0.7 mm: 4.1 A); two such tracks fit
    # side by side on the driver's 1.27 mm-pitch pins
    ("Motor", 0.7, 0.2, 0.8, 0.4, ["+12V", "/M1_OUT1", "/M1_MA", "/M1_OUT2", "/M2_OUT1", "/M2_MA", "/M2_OUT2"]),
    ("Power", 0.8, 0.2, 0.8, 0.4, ["/SW_5V", "/VIN_BUCK"]),
    ("Supply", 0.4, 0.2, 0.6, 0.3, ["+5V", "+3V3"]),
]
# Net classes routed on F.Cu only (route.py): their copper is sized for outer-layer copper and no via.
OUTER_ONLY = ("Chain", "Input", "Motor")


def used_libs():
    sym = sorted({p.lib_id.split(":")[0] for p in design.parts()} | {"power"})
    fp = sorted({p.footprint.split(":")[0] for p in design.parts()})
    return sym, fp


def sym_table(libs):
    rows = [f'  (lib (name "{n}")(type "KiCad")(uri "${{KICAD9_SYMBOL_DIR}}/{n}.kicad_sym")(options "")(descr ""))'
            for n in libs]
    return "(sym_lib_table\n  (version 7)\n" + "\n".join(rows) + "\n)\n"


def fp_table(libs):
    rows = [f'  (lib (name "{n}")(type "KiCad")(uri "${{KICAD9_FOOTPRINT_DIR}}/{n}.pretty")(options "")(descr ""))'
            for n in libs]
    return "(fp_lib_table\n  (version 7)\n" + "\n".join(rows) + "\n)\n"


def project(name):
    classes = []
    for cname, track, clear, via_d, via_drill, _ in NET_CLASSES:
        classes.append({"name": cname, "track_width": track, "clearance": clear, "via_diameter": via_d,
                        "via_drill": via_drill, "microvia_diameter": 0.3, "microvia_drill": 0.1,
                        "diff_pair_gap": 0.25, "diff_pair_via_gap": 0.25, "diff_pair_width": 0.2,
                        "bus_width": 12, "wire_width": 6, "line_style": 0,
                        "pcb_color": "rgba(0, 0, 0, 0.000)", "schematic_color": "rgba(0, 0, 0, 0.000)",
                        "priority": 2147483647 if cname == "Default" else len(classes)})
    classes.sort(key=lambda c: (c["name"] != "Default", c["name"]))  # the order pcbnew writes them in
    patterns = [{"netclass": c[0], "pattern": n} for c in NET_CLASSES for n in c[5]]
    return {
        "board": {"design_settings": {
            "defaults": {"board_outline_line_width": 0.1, "copper_line_width": 0.2, "silk_line_width": 0.12},
            "rules": {"min_clearance": 0.2, "min_track_width": 0.2, "min_via_diameter": 0.5,
                      "min_through_hole_diameter": 0.3, "min_via_annular_width": 0.1,
                      "min_copper_edge_clearance": 0.3, "min_hole_to_hole": 0.25, "min_hole_clearance": 0.25,
                      "min_silk_clearance": 0.0, "min_text_height": 0.8, "min_text_thickness": 0.08,
                      "allow_blind_buried_vias": False, "allow_microvias": False, "max_error": 0.005,
                      "min_connection": 0.0, "min_resolved_spokes": 2, "solder_mask_to_copper_clearance": 0.0,
                      "use_height_for_length_calcs": True, "min_microvia_diameter": 0.2,
                      "min_microvia_drill": 0.1, "min_groove_width": 0.0},
            "track_widths": [0.0, 0.25, 0.4, 0.7, 0.8, 1.0, 1.9], "via_dimensions": [{"diameter": 0.0, "drill": 0.0}]}},
        "meta": {"filename": name + ".kicad_pro", "version": 3},
        "net_settings": {"classes": classes, "meta": {"version": 4}, "net_colors": None,
                         "netclass_assignments": None, "netclass_patterns": patterns},
        "schematic": {"legacy_lib_dir": "", "legacy_lib_list": []},
        "sheets": [],
        "text_variables": {},
    }


def main(out_dir, name):
    sym, fp = used_libs()
    with open(os.path.join(out_dir, "sym-lib-table"), "w") as f:
        f.write(sym_table(sym))
    with open(os.path.join(out_dir, "fp-lib-table"), "w") as f:
        f.write(fp_table(fp))
    path = os.path.join(out_dir, name + ".kicad_pro")
    settings = project(name)
    if os.path.exists(path):
        # pcbnew rewrites the file with every setting spelled out; keep those and update ours.
        with open(path) as f:
            existing = json.load(f)
        settings = _merge(existing, settings)
    with open(path, "w") as f:
        f.write(json.dumps(settings, indent=2, sort_keys=True) + "\n")


def _merge(base, update):
    """update's values win; dictionaries are merged key by key, everything else is replaced."""
    out = dict(base)
    for key, value in update.items():
        if isinstance(value, dict) and isinstance(base.get(key), dict):
            out[key] = _merge(base[key], value)
        else:
            out[key] = value
    return out


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2])
