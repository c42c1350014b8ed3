# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""Every screw in the assembly holds parts together: its head bears on one part and its shank sits in a hole
of another (it touches at least two parts of its link), and it overlaps none, so each one has its holes.
The parts the fabrication guide says to bolt are bolted."""
import numpy as np
import pytest

from robogene_head.checks import interference
from robogene_head.geom import distance

from least_distance import Bounds, box_gap, least_distance


def _kind(params, part):
    """The purchased kind of a part; belts are cut from a stock section and are not listed by their key."""
    return params.purchased(part.design).text("kind") if params.root.node("purchased").has(part.design) else None


def _screws(params, assembly):
    return [p for p in assembly.parts
            if p.kind == "purchased" and _kind(params, p) == "screw"]


def _near(a, b, margin=1.0):
    ba, bb = a.shape.BoundingBox(), b.shape.BoundingBox()
    lo = np.maximum([ba.xmin, ba.ymin, ba.zmin], [bb.xmin, bb.ymin, bb.zmin])
    hi = np.minimum([ba.xmax, ba.ymax, ba.zmax], [bb.xmax, bb.ymax, bb.zmax])
    return np.all(lo - hi <= margin)


def _contact(params, external):
    """part -> how far apart counts as touching it. KiCad's STEP draws a board's PCB body without its copper and
    mask, so what bears on the finished board stands that much above the body."""
    fit = params.geometry("clearances").num("fit_tolerance")
    mask = params.root.node("boards").num("thickness") - external.board.pcb.BoundingBox().zlen
    return lambda part: fit + (mask if part.kind == "board" else 0.0)


@pytest.fixture(scope="module")
def held(params, assembly, external):
    """screw name -> names of the parts it touches; fails on any overlap."""
    contact = _contact(params, external)
    out = {}
    for screw in _screws(params, assembly):
        touched = []
        for other in assembly.parts:
            if other is screw or other.link != screw.link or not _near(screw, other):
                continue
            if distance(screw.shape, other.shape) < contact(other):
                overlap = screw.shape.intersect(other.shape).Volume()
                assert overlap < interference.VOLUME_TOLERANCE, f"{screw.name} cuts into {other.name}: {overlap:.2f} mm^3"
                touched.append(other.name)
        out[screw.name] = touched
    return out


# The whole assembly's screws and boards against their neighbours in OpenCASCADE: about 30 s each on an idle
# 2-core machine, several times that when the machine is shared, so these carry a longer timeout.
HEAVY = pytest.mark.timeout(600)


# Screws that close the split of one part round what it clamps: each jackshaft stage's gearhead clamp in its housing,
# its coupling's two halves (robogene_head/parts/jackshaft.py).
CLAMPS = {f"{j}_{name}": f"{j}_{part}" for j in ("eyes_tilt", "neck_yaw")
          for name, part in (("clamp_screw", "jackshaft_housing"), ("coupling_screw_0", "coupling"),
                             ("coupling_screw_1", "coupling"))}


@HEAVY
def test_every_screw_joins_two_parts(held):
    loose = {name: parts for name, parts in held.items() if len(parts) < 2 and name not in CLAMPS}
    assert loose == {}
    # a clamp screw bears on its split part alone, on both sides of the split
    assert {name: held[name] for name in CLAMPS} == {name: [part] for name, part in CLAMPS.items()}


@pytest.mark.parametrize("a, b", [
    ("head_floor", "head_side_plate_left"), ("head_floor", "head_side_plate_right"),
    ("head_floor", "head_back_plate"),
    ("head_side_plate_left", "head_back_plate"), ("head_side_plate_right", "head_back_plate"),
    ("head_side_plate_left", "head_top_bar"), ("head_side_plate_right", "head_top_bar"),
    ("face_plate", "head_side_plate_left"), ("face_plate", "head_side_plate_right"),
    ("neck_pitch_motor_mount", "neck_upright_left"), ("neck_roll_motor_mount", "neck_pitch_stage"),
    ("neck_yaw_jackshaft_housing", "head_floor"), ("eyes_tilt_jackshaft_housing", "head_side_plate_left"),
    # every gearhead not clamped in a jackshaft housing hangs on four M2 through the plate its flange bears on
    ("neck_pitch_motor_mount", "neck_pitch_gearhead"), ("neck_roll_motor_mount", "neck_roll_gearhead"),
    ("eyes_tilt_frame", "left_eye_pan_gearhead"), ("eyes_tilt_frame", "right_eye_pan_gearhead"),
    # each joint encoder's board on its bracket, the bracket on the face round its shaft's end
    *[(f"{j}_encoder_bracket", f"{j}_joint_encoder") for j in ("neck_pitch", "neck_roll", "neck_yaw", "eyes_tilt")],
    ("neck_pitch_encoder_bracket", "neck_upright_right"), ("neck_roll_encoder_bracket", "neck_pitch_front_lug"),
    ("neck_yaw_encoder_bracket", "head_floor"), ("eyes_tilt_encoder_bracket", "head_side_plate_right"),
])
def test_the_parts_the_guide_bolts_are_bolted(held, a, b):
    screws = [name for name, parts in held.items() if a in parts and b in parts]
    assert len(screws) >= 2, f"{a} and {b} share {screws}"


def test_a_screw_too_long_for_the_gearhead_threads_is_named(params, external, tmp_path):
    import yaml
    from robogene_head_model.params import ParameterError, load
    from robogene_head.parts import build_all
    data = yaml.safe_load(params.path.read_text())
    data["purchased"]["iso4762-M2x6"]["length"] = 12
    path = tmp_path / "long-screws.yaml"
    path.write_text(yaml.safe_dump(data))
    with pytest.raises(ParameterError, match=r"purchased\.iso4762-M2x6: reaches 10.2 mm into neck_pitch's gearhead"):
        build_all(load(path), external)


def _standoffs(params, assembly):
    return [p for p in assembly.parts
            if p.kind == "purchased" and _kind(params, p) == "standoff"]


@HEAVY
def test_every_board_is_clamped_at_its_four_holes(params, assembly, external):
    """Each board bears on four standoffs below it and is clamped by four standoffs or screws above it, the
    lowest standoffs stand on the flange, and nothing in the stack cuts into anything."""
    contact = _contact(params, external)
    stack = [p for p in _standoffs(params, assembly) + _screws(params, assembly) if p.name.startswith("board_")]
    assert len(stack) == 4 * (int(params.root.node("boards").num("count")) + 1)
    flange = next(p for p in assembly.parts if p.name == "neck_base_flange")
    for board in [p for p in assembly.parts if p.kind == "board"]:
        bottom = board.shape.BoundingBox().zmin   # the pins reach below the PCB; its bottom face is the origin
        z = board.placement.toTuple()[0][2]
        # The board is its PCB and some eighty component solids: measured solid by solid, only those near the part
        # count (the same distance as the whole board's; a common volume at least the whole board's).
        pieces, bounds = board.shape.Solids(), Bounds()
        below, above = [], []
        for part in stack:
            shape = part.shape
            if _near(board, part) and least_distance([(s, shape) for s in pieces], bounds) < contact(board):
                near = [s for s in pieces if box_gap(bounds(s), bounds(shape)) == 0]
                assert sum(s.intersect(shape).Volume() for s in near) < interference.VOLUME_TOLERANCE, part.name
                (below if part.placement.toTuple()[0][2] < z else above).append(part)
        assert len(below) == 4 and len(above) == 4, (board.name, [p.name for p in below], [p.name for p in above])
        assert bottom < z
        centres = {tuple(np.round(p.placement.toTuple()[0][:2], 3)) for p in below + above}
        assert len(centres) == 4, (board.name, centres)
    on_flange = [p for p in stack if distance(flange.shape, p.shape) < contact(flange)]
    assert sorted(p.name for p in on_flange) == [f"board_standoff_0_{i}" for i in range(4)]
    for part in on_flange:
        assert flange.shape.intersect(part.shape).Volume() < interference.VOLUME_TOLERANCE, part.name


def test_a_stack_pitch_no_standoff_gives_is_named(params, external, tmp_path):
    import yaml
    from robogene_head_model.params import ParameterError, load
    from robogene_head.parts import build_all
    data = yaml.safe_load(params.path.read_text())
    data["boards"]["stack_pitch"] = 14
    path = tmp_path / "pitch.yaml"
    path.write_text(yaml.safe_dump(data))
    with pytest.raises(ParameterError, match=r"boards\.stack_pitch: 14.0 must be a standoff length plus the board "
                                             r"thickness: standoff-M3x30-MF gives 31.6"):
        build_all(load(path), external)


def test_a_top_screw_too_long_for_the_standoff_is_named(params, external, tmp_path):
    import yaml
    from robogene_head_model.params import ParameterError, load
    from robogene_head.parts import build_all
    data = yaml.safe_load(params.path.read_text())
    data["purchased"]["iso7380-M3x35"] = dict(data["purchased"]["iso7380-M3x12"], length=35)
    data["boards"]["standoffs"]["screw"] = "iso7380-M3x35"   # 33.4 mm past the board, the thread is 29 deep
    path = tmp_path / "screw.yaml"
    path.write_text(yaml.safe_dump(data))
    with pytest.raises(ParameterError, match=r"boards\.standoffs\.screw: reaches 33.4 mm past the board into a "
                                             r"29 mm deep female thread"):
        build_all(load(path), external)
