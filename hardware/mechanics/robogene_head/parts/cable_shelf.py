# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: CERN-OHL-S-2.0
"""The camera cables' shelf on the tilt frame (docs/fabricate.md, "Wire the head"): a printed angle screwed onto the
tilt plate's back edge, between the eyes, its foot reaching back behind them to a wall that stands up there. Each
camera cable is taped to the wall's front face, where its loop about the pan axis ends, and, folded over the wall's
top, to its back face, where its loop about the tilt axis begins (harness clamps pan_feed_*, cam_arm_*).

A part of its own, not a part of the frame: it stands above the yaw axis, where the yaw shaft's upper spacer, its ring
and the yaw encoder go on from above after the head is on the neck; it goes on after them (assembly-sequence.yaml).
Printed, not machined: it rides at the top of the neck, where every gram is pitch torque (drive sizing). Two screws
from above through the foot into the plate, tapped. Between the eyes the plate's back edge is clear: the eye-pan
stops' lugs sweep it only further out (eye_stops), their pins stand further forward."""
from __future__ import annotations

from dataclasses import dataclass

from robogene_head_model.params import HeadParameters

from .. import geom
from . import purchased
from .base import PRINTED, Part, loc


@dataclass(frozen=True)
class Shelf:
    back: float          # x of the tilt plate's back edge (the tilt frame's frame)
    bottom: float        # z of the plate's underside
    top: float           # z of the plate's top face
    overlap: float       # how far the foot reaches over the plate
    depth: float         # how far behind the plate's back edge the wall's back face stands
    width: float
    foot: float          # the foot's thickness
    wall: float
    height: float        # of the wall's top over the plate's top
    screw: str
    screw_y: float       # the screws at +-screw_y, midway along the overlap


def shelf(params: HeadParameters, back: float, bottom: float, top: float, arm_in: float) -> Shelf:
    s = params.geometry("eyes", "tilt_frame").node("cable_shelf")
    out = Shelf(back, bottom, top, s.num("overlap", positive=True), s.num("depth", positive=True),
                s.num("width", positive=True), s.num("foot", positive=True), s.num("wall", positive=True),
                s.num("wall_height", positive=True), s.text("screw"), s.num("screw_y", positive=True))
    if out.width / 2 > arm_in:
        raise s.fail("width", f"{out.width:g} reaches the tilt frame's arms (they stand {arm_in:.1f} mm either side)")
    if out.wall >= out.depth:
        raise s.fail("wall", f"{out.wall:g} leaves no foot behind the plate ({out.depth:g} deep)")
    if out.screw_y + 2 > out.width / 2:
        raise s.fail("screw_y", f"{out.screw_y:g} puts the screws off the {out.width:g} mm foot")
    length = params.purchased(out.screw).num("length", positive=True)
    if length > (top - bottom) + out.foot:
        raise s.fail("screw", f"{out.screw} ({length:g} long) would stand out under the plate (foot {out.foot:g} "
                              f"+ plate {top - bottom:g} mm)")
    return out


def _screw_points(s: Shelf) -> list[tuple[float, float]]:
    return [(s.back + s.overlap / 2, sign * s.screw_y) for sign in (1, -1)]


def plate_holes(params: HeadParameters, s: Shelf) -> list:
    """The screws' tapped holes through the tilt plate (drawn at the thread)."""
    d = params.purchased(s.screw).num("diameter", positive=True)
    return [geom.cyl("z", d, s.bottom - 1, s.top + 1, (x, y)) for x, y in _screw_points(s)]


def _body(params: HeadParameters, s: Shelf):
    w0 = s.back - s.depth
    body = geom.union(geom.box(w0, s.back + s.overlap, -s.width / 2, s.width / 2, s.top, s.top + s.foot),
                      geom.box(w0, w0 + s.wall, -s.width / 2, s.width / 2, s.top, s.top + s.height))
    d = params.purchased(s.screw).num("diameter", positive=True) + 0.4     # clearance over the thread
    return geom.single_solid(geom.cut(body, *[geom.cyl("z", d, s.top - 1, s.top + s.foot + 1, (x, y))
                                             for x, y in _screw_points(s)]), "cable shelf")


def parts(params: HeadParameters, s: Shelf) -> list[Part]:
    """The shelf and its screws, heads on the foot, into the plate's tapped holes."""
    out = [Part("eyes_cable_shelf", "eyes_cable_shelf", "eyes_tilt_link", "printed", _body(params, s),
                material="petg-printed", color=PRINTED)]
    out += [purchased.screw(params, f"eyes_cable_shelf_screw_{i}", s.screw, "eyes_tilt_link",
                            loc(x, y, s.top + s.foot, rx=180)) for i, (x, y) in enumerate(_screw_points(s))]
    return out
