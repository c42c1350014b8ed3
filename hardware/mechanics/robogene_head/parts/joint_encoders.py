# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: CERN-OHL-S-2.0
"""The joint encoders (geometry.joint_encoders): per joint an AS5048A board on a machined bracket, facing a diametric
magnet held in the end of the joint's shaft.

Everything of one joint is drawn in its end frame: origin on the joint's axis at the end of the shaft, w (z) along
the axis away from the shaft, u and v (x and y) in the face the bracket stands on. The frame is given in the link the
bracket is fixed to (`mount`); the magnet turns with the shaft's link (`shaft`). Where the magnet sits on a fixed
shaft (yaw: the head turns round the roll stage's shaft) the board turns with the head instead: either way one of the
two turns about the axis relative to the other, which is all the sensor needs.

Why machined: the board's IC must stay within the datasheet's displacement (0.25 mm) of the axis and its air gap
(0.5 to 2 mm) over the head's life. A printed bracket's positional error is of that size and PETG creeps under the
screws' preload; an aluminium bracket holds both, and, like the magnet's pockets and holder, is not ferromagnetic
(the adapter board manual asks for a non-ferromagnetic magnet holder)."""
from __future__ import annotations

import math
from dataclasses import dataclass

import cadquery as cq

from robogene_head_model.params import HeadParameters, Node, ParameterError

from .. import geom
from . import purchased, tilt_bearings, yaw_bearings
from .base import ALUMINIUM, Part, loc

JOINTS = ("neck_pitch", "neck_roll", "neck_yaw", "eyes_tilt")


@dataclass(frozen=True)
class End:
    """A joint's shaft end and the face round it, where the bracket stands."""
    joint: str
    mount: str             # link of the bracket and the board
    shaft: str             # link of the shaft and the magnet
    frame: cq.Location     # end frame in the mount link
    shaft_frame: cq.Location   # the same frame in the shaft link, at the zero pose
    shaft_diameter: float
    face: float            # w of the face the feet stand on (0: flush with the shaft's end)
    holder: bool           # magnet in a holder on the shaft (True) or in a pocket bored in it
    exit: float            # w of the face the shaft comes out of (what a holder on it stands off)
    keep_out: float        # radius round the axis the feet stay clear of: a boss standing on the face (0: none)


def node(params: HeadParameters) -> Node:
    return params.geometry("joint_encoders")


def _translate(origin, sign: float) -> cq.Location:
    return loc(*(sign * c for c in origin))


def ends(params: HeadParameters) -> dict[str, End]:
    """The four joints' shaft ends, from the same parameters the shafts are built from (parts/neck.py, eyes.py,
    yaw_bearings.py, tilt_bearings.py)."""
    up = params.geometry("neck_base", "upright")
    y_out = up.num("gap") / 2 + up.num("thickness")                       # right upright's outer face, at -y
    hp = params.joints["neck_pitch"].origin[2]
    stage = params.geometry("neck_pitch_stage")
    x_front = stage.node("lug").num("span") / 2 + stage.node("front_lug").num("thickness")   # front lug's outer face
    zr = params.joints["neck_roll"].origin[2]
    hw = params.geometry("head", "floor").num("half_width")
    tx, _, tz = params.joints["eyes_tilt"].origin
    bore = {j: params.purchased(params.drive(j).text("bearing")).num("bore", positive=True) for j in JOINTS}
    # yaw: the fixed shaft stands through the bearings' boss, its ring and spacer, to yaw_bearings.shaft_end
    ze = yaw_bearings.shaft_end(params)
    yaw_boss = yaw_bearings.layout(params).boss / 2
    # tilt: the right journal stands `protrusion` out of the fixed bearing's boss (tilt_bearings.shaft_end)
    tilt = tilt_bearings.layout(params)
    ye = tilt.shaft_end
    tilt_boss = params.geometry("tilt_bearings", "boss").num("diameter", positive=True) / 2
    frames = {
        # pitch: the pitch stage's right journal ends in the right upright's outer face (u = x, v = z, w = -y)
        "neck_pitch": ("neck_base", "neck_pitch_link", loc(0, -y_out, hp, rx=90), 0.0, False, 0.0, 0.0),
        # roll: the roll stage's front journal ends in the front lug's outer face (u = -z, v = y, w = x)
        "neck_roll": ("neck_pitch_link", "neck_roll_link", loc(x_front, 0, zr, ry=90), 0.0, False, 0.0, 0.0),
        # yaw: the roll stage's fixed shaft ends ze above the head floor's top face, the yaw joint's origin (u = x,
        # v = y); the bracket stands on the floor round the bearings' boss
        "neck_yaw": ("head_frame", "neck_roll_link", loc(0, 0, ze), -ze, False, -ze + yaw_bearings.layout(params).top,
                     yaw_boss),
        # tilt: the right journal ends beyond the boss on the right side plate (u = x, v = z, w = -y); the bracket
        # stands on the plate's outer face round the boss, the holder off the boss's face
        "eyes_tilt": ("head_frame", "eyes_tilt_link", loc(tx, ye, tz, rx=90), ye + hw, True, ye + tilt.outer,
                      tilt_boss),
    }
    out = {}
    for joint, (mount, shaft, frame, face, holder, exit_, keep_out) in frames.items():
        j = params.joints[joint]
        if j.parent == mount and j.child == shaft:
            shaft_frame = _translate(j.origin, -1) * frame
        elif j.child == mount and j.parent == shaft:
            shaft_frame = _translate(j.origin, 1) * frame
        else:
            raise ParameterError(f"{params.path}: joints.{joint}: the joint encoder expects it between {mount} and "
                                 f"{shaft}")
        # the yaw shaft is the yaw bearing's bore; the others are their bearings' journals
        out[joint] = End(joint, mount, shaft, frame, shaft_frame, bore[joint], face, holder, exit_, keep_out)
    return out


def holder_node(params: HeadParameters) -> Node:
    return node(params).node("holder")


def magnet_key(params: HeadParameters) -> str:
    return node(params).text("magnet")


def _magnet(params: HeadParameters) -> tuple[float, float]:
    m = params.purchased(magnet_key(params))
    return m.num("diameter", positive=True), m.num("thickness", positive=True)


def magnet_face(params: HeadParameters, end: End) -> float:
    """w of the magnet's face towards the board: flush with the shaft's end, or with the holder's outer face."""
    _, mt = _magnet(params)
    if end.holder:
        return holder_node(params).num("web", positive=True) + mt
    return 0.0


def board_key(params: HeadParameters, joint: str) -> str:
    return params.drive(joint).text("joint_encoder")


@dataclass(frozen=True)
class Levels:
    """w of the stack from the magnet's face out: where the IC's face, the board's faces and the plate are."""
    magnet: float
    ic: float          # the IC's face towards the magnet
    component: float   # the board's face carrying the IC
    back: float        # the board's other face, on the bracket's plate
    top: float         # the plate's outer face


def levels(params: HeadParameters, end: End) -> Levels:
    b = params.purchased(board_key(params, end.joint))
    n = node(params)
    m = magnet_face(params, end)
    ic = m + n.num("gap", positive=True)
    component = ic + b.node("ic").num("height", positive=True)
    back = component + b.num("height", positive=True)
    return Levels(m, ic, component, back, back + n.num("plate", positive=True))


def _turned(u: float, v: float, turn: float) -> tuple[float, float]:
    c, s = math.cos(math.radians(turn)), math.sin(math.radians(turn))
    return c * u - s * v, s * u + c * v


def board_holes(params: HeadParameters, joint: str) -> list[tuple[float, float]]:
    """The board's four holes in the end frame's (u, v): the holes' centre on the axis, turned by `turn`."""
    b = params.purchased(board_key(params, joint))
    px, py = b.node("holes").vec("pitch", 2)
    turn = node(params).node("joints").node(joint).num("turn")
    return [_turned(sx * px / 2, sy * py / 2, turn) for sx in (-1, 1) for sy in (-1, 1)]


def _outline(params: HeadParameters, joint: str) -> list[tuple[float, float]]:
    """The board outline's corners in the end frame's (u, v)."""
    b = params.purchased(board_key(params, joint))
    ox, oy = b.vec("outline_at", 2)
    w, l = b.num("width", positive=True), b.num("length", positive=True)
    turn = node(params).node("joints").node(joint).num("turn")
    return [_turned(ox + sx * w / 2, oy + sy * l / 2, turn) for sx in (-1, 1) for sy in (-1, 1)]


def feet(params: HeadParameters, joint: str) -> list[tuple[float, float]]:
    return node(params).node("joints").node(joint).points("feet")


def _check_feet(params: HeadParameters, end: End) -> None:
    """A foot stands beside the board, never under it (the board lies between the feet's tops and the plate), and
    off the boss round the shaft by the fabricator's minimum (a foot merged into the boss cannot be machined as
    drawn, and the boss's seat would take the screw's tapped hole)."""
    joint = end.joint
    r = node(params).num("foot", positive=True) / 2
    gap = params.geometry("clearances").num("minimum", positive=True)
    for i, (u, v) in enumerate(feet(params, joint)):
        if end.keep_out and math.hypot(u, v) - r < end.keep_out + gap - 1e-9:
            raise ParameterError(f"{params.path}: geometry.joint_encoders.joints.{joint}.feet[{i}]: the foot at "
                                 f"({u:g}, {v:g}) reaches within {gap:g} of the {2 * end.keep_out:g} mm boss round the "
                                 f"shaft: its centre must be at least {end.keep_out + gap + r:g} from the axis")
    corners = _outline(params, joint)
    u0, u1 = min(c[0] for c in corners), max(c[0] for c in corners)
    v0, v1 = min(c[1] for c in corners), max(c[1] for c in corners)
    for i, (u, v) in enumerate(feet(params, joint)):
        du = max(u0 - u, 0.0, u - u1)
        dv = max(v0 - v, 0.0, v - v1)
        if math.hypot(du, dv) < r:
            raise ParameterError(f"{params.path}: geometry.joint_encoders.joints.{joint}.feet[{i}]: the foot at "
                                 f"({u:g}, {v:g}) stands under the board (its outline u {u0:g}..{u1:g}, v {v0:g}..{v1:g})")


def _screw_seat(params: HeadParameters, end: End, top: float) -> float:
    """w of the mount screws' heads: the screw reaches `engagement` into its hole below the face."""
    n = node(params)
    key = n.text("mount_screw")
    length = params.purchased(key).num("length", positive=True)
    seat = end.face - n.num("engagement", positive=True) + length
    if seat > top:
        raise ParameterError(f"{params.path}: geometry.joint_encoders.mount_screw: {key} is too long for the "
                             f"{end.joint} bracket ({top - end.face:g} mm tall): it would reach more than the "
                             f"{n.num('engagement'):g} mm engagement into the face")
    under = n.num("under_head", positive=True)
    if seat < end.face + under:
        raise ParameterError(f"{params.path}: geometry.joint_encoders.mount_screw: {key} is too short for the "
                             f"{end.joint} bracket: it leaves less than {under:g} mm of the foot under its head")
    return seat


def bracket(params: HeadParameters, end: End) -> cq.Solid:
    """The bracket in the end frame: a plate on the board's back face over its holes, with feet down to the face."""
    n = node(params)
    _check_feet(params, end)
    lv = levels(params, end)
    holes = board_holes(params, end.joint)
    margin, r = n.num("margin", positive=True), n.num("foot", positive=True) / 2
    pts = [(u, v) for u, v in holes]
    u0 = min(min(u for u, _ in pts) - margin, min(u - r for u, _ in feet(params, end.joint)))
    u1 = max(max(u for u, _ in pts) + margin, max(u + r for u, _ in feet(params, end.joint)))
    v0 = min(min(v for _, v in pts) - margin, min(v - r for _, v in feet(params, end.joint)))
    v1 = max(max(v for _, v in pts) + margin, max(v + r for _, v in feet(params, end.joint)))
    body = geom.union(geom.box(u0, u1, v0, v1, lv.back, lv.top),
                      *[geom.cyl("z", 2 * r, end.face, lv.back + 0.5, f) for f in feet(params, end.joint)])
    screw = params.purchased(n.text("board_screw"))
    seat = _screw_seat(params, end, lv.top)
    hole, counterbore = n.num("screw_hole", positive=True), n.num("counterbore", positive=True)
    mount = params.purchased(n.text("mount_screw"))
    if hole <= mount.num("diameter") or counterbore <= mount.num("head_diameter"):
        raise ParameterError(f"{params.path}: geometry.joint_encoders: screw_hole {hole:g} / counterbore "
                             f"{counterbore:g} do not take {n.text('mount_screw')}")
    if counterbore > 2 * r - 2:
        raise ParameterError(f"{params.path}: geometry.joint_encoders.foot: {2 * r:g} leaves under 1 mm of wall round "
                             f"the {counterbore:g} mm counterbores")
    spots = feet(params, end.joint)
    for i in range(len(spots)):
        for k in range(i):
            d = math.dist(spots[i], spots[k])
            # heads that touch cannot both be turned; counterbores that just touch leave a knife edge
            if d < mount.num("head_diameter") + 0.2 or abs(d - counterbore) < 0.2:
                raise ParameterError(f"{params.path}: geometry.joint_encoders.joints.{end.joint}.feet: feet {k} and "
                                     f"{i} are {d:g} apart: their screws' heads ({mount.num('head_diameter'):g}) need "
                                     f"room and their {counterbore:g} mm counterbores must overlap or stand apart")
    tools = [geom.cyl("z", screw.num("diameter", positive=True), lv.back - 1, lv.top + 1, h) for h in holes]
    for f in feet(params, end.joint):
        tools += [geom.cyl("z", hole, end.face - 1, lv.top + 1, f), geom.cyl("z", counterbore, seat, lv.top + 1, f)]
    return geom.single_solid(geom.cut(body, *tools), f"{end.joint} encoder bracket")


def face_holes(params: HeadParameters, end: End) -> list[cq.Shape]:
    """The mount screws' tapped holes in the face, drawn at the thread, in the mount link's frame."""
    n = node(params)
    d = params.purchased(n.text("mount_screw")).num("diameter", positive=True)
    depth = n.num("engagement", positive=True) + 1.0
    return [geom.cyl("z", d, end.face - depth, end.face + 1, f).moved(end.frame) for f in feet(params, end.joint)]


def shaft_cuts(params: HeadParameters, end: End) -> list[cq.Shape]:
    """The magnet's pocket in the shaft's end, in the shaft link's frame (none where a holder carries it)."""
    if end.holder:
        return []
    md, mt = _magnet(params)
    pocket = md + node(params).num("pocket_clearance", positive=True)
    if pocket > end.shaft_diameter - 2.0:
        raise ParameterError(f"{params.path}: geometry.joint_encoders.magnet: a {pocket:g} mm pocket leaves under 1 mm "
                             f"of wall in the {end.joint} shaft ({end.shaft_diameter:g})")
    return [geom.cyl("z", pocket, -mt, 1.0).moved(end.shaft_frame)]


def shaft_protrusion(params: HeadParameters) -> float:
    """How far the tilt frame's right journal stands out of its bearing's boss for the magnet holder."""
    return holder_node(params).num("protrusion", positive=True)


def _holder(params: HeadParameters, end: End) -> cq.Solid:
    """Turned aluminium cap bonded on the shaft's end, in the end frame: a bore for the shaft, the magnet's pocket
    in its outer face (both turned in one setting: the magnet's axis is the shaft's)."""
    h = holder_node(params)
    md, mt = _magnet(params)
    outside, gap, web = h.num("outside", positive=True), h.num("gap", positive=True), h.num("web", positive=True)
    if outside < end.shaft_diameter + 2 or outside < md + 2:
        raise ParameterError(f"{params.path}: geometry.joint_encoders.holder.outside: {outside:g} leaves under 1 mm of "
                             f"wall round the {end.shaft_diameter:g} mm shaft or the {md:g} mm magnet")
    if end.exit + gap >= -1.0:
        raise ParameterError(f"{params.path}: geometry.joint_encoders.holder: the shaft stands "
                             f"{-end.exit:g} mm out, under the {gap:g} mm gap and 1 mm of bore")
    pocket = md + node(params).num("pocket_clearance", positive=True)
    top = web + mt
    body = geom.cyl("z", outside, end.exit + gap, top)
    return geom.single_solid(geom.cut(body, geom.cyl("z", end.shaft_diameter, end.exit + gap - 1, 0.0),
                                      geom.cyl("z", pocket, web, top + 1)), "magnet holder")


def parts(params: HeadParameters, joint: str) -> list[Part]:
    """The joint's magnet (and holder), bracket, board and their screws, each on its link."""
    end = ends(params)[joint]
    n = node(params)
    lv = levels(params, end)
    md, mt = _magnet(params)
    out = []
    if end.holder:
        out.append(Part(f"{joint}_magnet_holder", "magnet_holder", end.shaft, "machined", _holder(params, end),
                        end.shaft_frame, material="aluminium-6082", color=ALUMINIUM,
                        note=(f"Bore {end.shaft_diameter:g} for the shaft's end and the magnet's pocket turned in one "
                              f"setting (coaxial 0.02). Bonded on the shaft (retaining compound), the magnet bonded "
                              f"in its pocket")))
    magnet = geom.cyl("z", md, lv.magnet - mt, lv.magnet)
    out.append(Part(f"{joint}_encoder_magnet", magnet_key(params), end.shaft, "purchased", magnet, end.shaft_frame,
                    mass=params.purchased(magnet_key(params)).num("mass"), color=(0.5, 0.5, 0.55)))
    out.append(Part(f"{joint}_encoder_bracket", f"encoder_bracket_{joint}", end.mount, "machined",
                    bracket(params, end), end.frame, material="aluminium-6082", color=ALUMINIUM,
                    note=(f"M{params.purchased(n.text('board_screw')).num('diameter'):g} tapped through the plate for the "
                          f"board (drawn at the thread). Feet: {n.num('screw_hole'):g} through, counterbored, for "
                          f"the {n.text('mount_screw')} into the face round the shaft")))
    turn = n.node("joints").node(joint).num("turn")
    out.append(purchased.joint_encoder(params, f"{joint}_joint_encoder", end.mount,
                                       end.frame * loc(z=lv.component, rz=turn), key=board_key(params, joint)))
    for i, (u, v) in enumerate(board_holes(params, joint)):   # heads on the board's IC face, into the plate
        out.append(purchased.screw(params, f"{joint}_encoder_board_screw_{i}", n.text("board_screw"), end.mount,
                                   end.frame * loc(u, v, lv.component)))
    seat = _screw_seat(params, end, lv.top)
    for i, (u, v) in enumerate(feet(params, joint)):          # heads in the counterbores, into the face
        out.append(purchased.screw(params, f"{joint}_encoder_bracket_screw_{i}", n.text("mount_screw"), end.mount,
                                   end.frame * loc(u, v, seat, rx=180)))
    return out


def build(params: HeadParameters) -> list[Part]:
    return [p for joint in JOINTS for p in parts(params, joint)]
