# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""The dimensions a lab may change live in the parameter file's geometry section, not in the part modules: a
changed value reaches the solids, a bad one is refused by its key, and no part module grows numeric constants
again."""
import ast
import copy
import math
from pathlib import Path

import pytest
import yaml

from robogene_head_model import params as P
from robogene_head import parts
from robogene_head.parts import covers, head_frame, neck

PARTS_DIR = Path(parts.__file__).resolve().parent
# Module-level numbers that stay in code, and why.
ALLOWED_CONSTANTS = {
    ("base.py", "ALUMINIUM"), ("base.py", "PRINTED"), ("base.py", "DARK"), ("base.py", "STEEL"),
    ("base.py", "GREEN"), ("face.py", "COLOR"),                  # display colours
    ("board_stack.py", "MASK_AND_COPPER"),                      # what KiCad's STEP leaves out of a PCB
    ("purchased.py", "STUD_WEB"),                               # envelope of a purchased standoff
    ("neck.py", "LUG_GAP"),                                     # a design rule (over a bearing's axial play), no part's size
    ("neck.py", "BORE_RUNOUT"),                                 # a design rule (a bore runs past its shaft's end)
    ("drive_hubs.py", "LAND_DEPTH"),                            # a machining rule (the land a set screw's drill starts on)
    ("drive_hubs.py", "_AXES"),                                 # unit vectors, no dimension
    ("board_plugs.py", "OUTLINE_MARGIN"),                       # a matching tolerance between two drawings of one part
}


@pytest.fixture(scope="module")
def raw():
    return yaml.safe_load(P.DEFAULT_PATH.read_text())


def _load(raw, tmp_path, path: str, value):
    data = copy.deepcopy(raw)
    node = data
    *keys, last = path.split(".")
    for key in keys:
        node = node[key]
    if value is None:
        del node[last]
    else:
        node[last] = value
    out = tmp_path / "p.yaml"
    out.write_text(yaml.safe_dump(data))
    return P.load(out)


def _parts(params, family) -> dict:
    return {p.name: p for p in family.build(params)}


def _size(part) -> tuple[float, float, float]:
    box = part.local.BoundingBox()
    return box.xlen, box.ylen, box.zlen


@pytest.mark.parametrize("path, value, family, part, measure, expected", [
    ("geometry.covers.back_depth", 20, covers, "head_back_cover", lambda p: _size(p)[0], 20),
    ("geometry.motor_mounts.neck_pitch.outline", [-22, 22, -18, 18], neck, "neck_pitch_motor_mount",
     lambda p: _size(p)[0], 44),
    ("geometry.yaw_jackshaft.housing.flange_half", 23, head_frame, "neck_yaw_jackshaft_housing",
     lambda p: _size(p)[2], 46),
    ("geometry.tilt_jackshaft.housing.front", 24, head_frame, "eyes_tilt_jackshaft_housing", lambda p: _size(p)[0], 35),
    ("geometry.yaw_jackshaft.axis", [-16, -42], head_frame, "neck_yaw_jackshaft",
     lambda p: p.shape.BoundingBox().center.x, -16),
    ("geometry.yaw_jackshaft.fixings", [[8, -18], [8, 18]], head_frame, "yaw_housing_screw_1",
     lambda p: math.dist(p.shape.Center().toTuple()[:2], (-15, -42)),
     math.hypot(8, 18)),
    ("geometry.head.joins.side_floor_x", [-38, 20], head_frame, "side_floor_screw_left_0",
     lambda p: p.placement.toTuple()[0][0], -38),
    ("geometry.gearhead_flange.bolt_circle_ratio", 0.6, neck, "neck_pitch_gearhead_screw_0",
     lambda p: math.hypot(p.placement.toTuple()[0][0], p.placement.toTuple()[0][2] - 48), 0.3 * 32),  # 32/3: 32 across
    ("geometry.pulleys.yaw.rim", 2, head_frame, "neck_yaw_motor_pulley",
     lambda p: _size(p)[0], 14 * 5.08 / math.pi - 0.508 + 4),
])
def test_a_changed_dimension_reaches_the_solids(raw, tmp_path, params, path, value, family, part, measure, expected):
    before = measure(_parts(params, family)[part])
    after = measure(_parts(_load(raw, tmp_path, path, value), family)[part])
    assert after == pytest.approx(expected, abs=1e-6)
    assert before != pytest.approx(after, abs=1e-6)


def test_wider_mount_holes_take_material_from_the_flange(raw, tmp_path, params):
    flange = _parts(params, neck)["neck_base_flange"].local.Volume()
    wider = _parts(_load(raw, tmp_path, "geometry.neck_base.flange.mount_holes.diameter", 8), neck)
    assert flange - wider["neck_base_flange"].local.Volume() == pytest.approx(4 * math.pi * (4 ** 2 - 3.25 ** 2) * 6)


@pytest.mark.parametrize("path, value, message", [
    ("geometry.covers.wall", -1, r"geometry\.covers\.wall: must be > 0, got -1"),
    ("geometry.covers", None, r"geometry\.covers: missing"),
    ("geometry.motor_mounts.neck_pitch.outline", [-20, 20, -18],
     r"geometry\.motor_mounts\.neck_pitch\.outline: expected a list of 4 numbers"),
    ("geometry.motor_mounts.neck_pitch.outline", [5, 20, -18, 18],
     r"geometry\.motor_mounts\.neck_pitch\.outline: expected x0 < 0 < x1"),
    ("geometry.motor_mounts.neck_roll.fixings", [[-14.5, -6, 1]],
     r"geometry\.motor_mounts\.neck_roll\.fixings\[0\]: expected a list of 2 numbers"),
    ("geometry.yaw_jackshaft.housing.flange_back", 14, r"geometry\.yaw_jackshaft\.housing\.flange_back: 14 reaches "
                                                      r"behind the body's back"),
    ("geometry.yaw_jackshaft.axis", [0, 0], r"geometry\.yaw_jackshaft\.axis: lies on the yaw axis"),
    ("geometry.yaw_jackshaft.axis", [-15, -70], r"geometry\.yaw_jackshaft\.axis: \(-15, -70\) is not on the head floor"),
    ("geometry.clearance_holes.M3", 2.9, r"geometry\.clearance_holes\.M3: 2\.9 does not clear an M3"),
    ("geometry.clearance_holes.M2", None, r"geometry\.clearance_holes\.M2: missing"),
    ("geometry.gearhead_flange.bolt_circle_ratio", 1.2, r"geometry\.gearhead_flange\.bolt_circle_ratio: must be <= 1"),
    ("geometry.gearhead_flange.counterbore", [2, 2.2], r"geometry\.gearhead_flange\.counterbore: expected a diameter "
                                                        r"above the clearance"),
    ("geometry.tilt_jackshaft.housing.cavity", 16, r"geometry\.tilt_jackshaft\.housing\.cavity: 16 does not take "
                                                   r"the 16 mm coupling"),
    ("geometry.covers.skirt_cable_exit.height", 96, r"geometry\.covers\.skirt_cable_exit\.height: 96 leaves nothing"),
    ("geometry.neck_base.cable_pass.from_edge", [40, 20], r"geometry\.neck_base\.cable_pass\.from_edge"),
    ("geometry.head.joins.back_side_z", [15], r"geometry\.head\.joins\.back_side_z: expected a list of 2 numbers"),
])
def test_a_bad_dimension_is_named(raw, tmp_path, path, value, message):
    params = _load(raw, tmp_path, path, value)
    with pytest.raises(P.ParameterError, match=message):
        for family in (neck, head_frame, covers):
            family.build(params)


def test_part_modules_keep_no_dimension_constants():
    """A module-level number in a part module is a dimension the parameter file cannot reach."""
    found = []
    modules = sorted(PARTS_DIR.glob("*.py"))
    assert "neck.py" in [m.name for m in modules], f"no part modules under {PARTS_DIR}"   # an empty glob passes nothing
    for path in modules:
        for node in ast.parse(path.read_text()).body:
            if isinstance(node, (ast.Assign, ast.AnnAssign)):
                targets = node.targets if isinstance(node, ast.Assign) else [node.target]
                numbers = [n for n in ast.walk(node.value) if isinstance(n, ast.Constant)
                           and isinstance(n.value, (int, float)) and not isinstance(n.value, bool)]
                for target in targets:
                    if numbers and isinstance(target, ast.Name) and (path.name, target.id) not in ALLOWED_CONSTANTS:
                        found.append(f"{path.name}: {target.id}")
    assert found == []
