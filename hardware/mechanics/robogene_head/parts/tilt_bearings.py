# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: CERN-OHL-S-2.0
"""The eye tilt's bearings (geometry.tilt_bearings): the right one fixed, the left one floating.

The tilt frame's journals turn against the load, so the inner rings are the tight ones (fits: journal_turning_ring)
and the floating bearing floats at its outer ring. Right (fixed): in a boss on the right side plate's outer face, its
outer ring between the plate's shoulder and a DIN 472 ring on a turned steel spacer ring (neck.clamped_seat), whose
bore stays outside the outer ring's face's inner edge (the maker's D2: a DIN 988 13 x 19 shim would lie on the
shield), its inner ring between a collar of the journal and a DIN 6799 retaining washer in a groove of the journal,
which stays within the inner ring's face. Left (floating): its outer ring slides in the left plate's through-bore,
its inner ring sits against the left journal's collar. The left plate keeps its 6 mm: the tilt pulleys run just
outside it.

Frames: head frame; y across, the right plate's inner face at y = -inner; the tilt link shares y with it."""
from __future__ import annotations

from dataclasses import dataclass

import cadquery as cq

from robogene_head_model.params import HeadParameters, ParameterError

from .. import fits, geom
from ..bearing_arrangement import face_edges, general_tolerance
from . import joint_encoders, neck, purchased
from .base import DARK, STEEL, Part, loc

BOSS_NOTE = ("Tilt bearing boss: shoulder, bearing seat, spacer ring, DIN 472 groove, from the inner face out; the "
             "bearing is pressed in from outside")
SPACER_NOTE = ("Spacer ring between the fixed tilt bearing's outer ring and its DIN 472 ring, turned from steel, faces "
               "flat and parallel; faced to length at assembly so that the ring snaps into its groove with the outer "
               "ring held without play")


@dataclass(frozen=True)
class Layout:
    inner: float          # the side plates' inner faces at |y| = inner
    outer: float          # the right boss's outer face at y = -outer
    tools: list           # the right seat's cutting tools (head frame)
    bearing: float        # y of the right bearing's inner face (towards +y), its outer face, the spacer's, the ring's
    spacer_at: float
    ring: float
    spacer: tuple[float, float, float]   # the spacer ring's bore, outside and thickness
    clip: float           # y of the clip's inner face (against the bearing's inner ring)
    groove: tuple[float, float]   # the clip's groove on the journal (y, increasing)
    shaft_end: float      # y of the right journal's end (negative): beyond the boss, for the encoder's magnet holder
    collar: float         # the collars' diameter
    arm: float            # |y| of the tilt frame arms' outer faces


def _node(params: HeadParameters):
    return params.geometry("tilt_bearings")


def layout(params: HeadParameters) -> Layout:
    node = _node(params)
    path = "geometry.tilt_bearings"
    head = params.geometry("head")
    hw = head.node("floor").num("half_width", positive=True)
    inner = hw - head.node("side_plate").num("thickness", positive=True)
    boss = node.node("boss")
    outer = hw + boss.num("thickness", positive=True)
    tilt = params.joints["eyes_tilt"].origin
    key = params.drive("eyes_tilt").text("bearing")
    bearing = params.purchased(key)
    bore, outside, inner_ring = bearing.num("bore"), bearing.num("outside"), bearing.num("inner_ring_outside", positive=True)
    if boss.num("diameter", positive=True) <= params.purchased(neck.bearing_ring(params)).num("groove_diameter") + 2:
        raise ParameterError(f"{params.path}: {path}.boss.diameter: {boss.num('diameter'):g} leaves under 1 mm of wall "
                             f"round the {neck.bearing_ring(params)} groove")
    spacer = _spacer(params, key)
    tools, b0, s0, g0 = neck.clamped_seat(params, "eyes_tilt", -inner, -outer, "y", (tilt[0], tilt[2]), spacer[2])
    clip_key = node.text("clip")
    clip = params.purchased(clip_key)
    if clip.text("kind") != "shaft_ring" or abs(clip.num("shaft") - bore) > 1e-9:
        raise ParameterError(f"{params.path}: {path}.clip: {clip_key} must be a shaft ring for the {bore:g} mm journal")
    d = clip.num("lug_outer_diameter", positive=True)
    if d > inner_ring + 1e-9:
        raise ParameterError(f"{params.path}: {path}.clip: {clip_key} ({d:g} across) reaches beyond the {key}'s inner "
                             f"ring ({inner_ring:g} across), onto the shield, which stands while it turns")
    t, m = clip.num("thickness", positive=True), clip.num("groove_width", positive=True)
    lugs = params.purchased(neck.bearing_ring(params)).num("lug_inner_diameter", positive=True)
    if d >= lugs and spacer[2] < t + neck.LUG_GAP - 1e-9:
        raise ParameterError(f"{params.path}: {path}.spacer.thickness: {spacer[2]:g} leaves the "
                             f"{neck.bearing_ring(params)} ring's lugs (reaching in to {lugs:g}) beside the {clip_key} "
                             f"({d:g} across) on the turning inner ring: it must be at least {t + neck.LUG_GAP:g} thick")
    collar = node.num("collar", positive=True)
    hole = params.geometry("bearing_seats").num("shoulder_hole")
    gap = params.geometry("clearances").num("minimum", positive=True)
    if not (bore < collar <= inner_ring and collar + 2 * gap <= hole):
        raise ParameterError(f"{params.path}: {path}.collar: {collar:g} must be over the {bore:g} mm journal, within "
                             f"the inner ring's face ({inner_ring:g}) and clear of the shoulder's {hole:g} mm hole")
    groove = (s0 - m, s0)
    # the journal carries the joint encoder's magnet holder beyond the boss's face (parts/joint_encoders.py)
    end = -outer - joint_encoders.shaft_protrusion(params)
    if groove[0] - clip.num("groove_edge", positive=True) < end - 1e-9:
        raise ParameterError(f"{params.path}: {path}.boss.thickness: the journal ends at y = {end:g}, "
                             f"under {clip.num('groove_edge'):g} mm beyond the {clip_key}'s groove")
    arm = inner - max(params.geometry("clearances").num("minimum"), 1.0)
    return Layout(inner, outer, tools, b0, s0, g0, spacer, s0, groove, end, collar, arm)


def _spacer(params: HeadParameters, key: str) -> tuple[float, float, float]:
    """The spacer ring's (bore, outside, thickness), refused where it could lie on the bearing's shield or not go into
    the seat: its bore at its smallest under the drawing's general tolerance (ISO 2768-m), and pushed to one side by
    its play in the seat (the outer ring stands, so its seat is the sliding fit), must stay outside the outer ring's
    face's inner edge (outer_ring_inside, the maker's D2, else the pitch circle, as bearing_arrangement takes it); its
    outside at its largest must go into the seat, and reach over the DIN 472 ring's band, which bears on it."""
    path = "geometry.tilt_bearings.spacer"
    node = _node(params).node("spacer")
    si, so, s = (node.num(k, positive=True) for k in ("inside", "outside", "thickness"))
    bearing = params.purchased(key)
    bo, edge = bearing.num("outside"), face_edges(bearing)[1]
    seat = fits.tolerance(params, "housing", False)
    ring_key = neck.bearing_ring(params)
    band = params.purchased(ring_key).num("inner_diameter", positive=True)
    largest, smallest = so + general_tolerance(so), so - general_tolerance(so)
    if not (si < smallest and band < smallest and largest <= bo + 1e-9):
        raise ParameterError(f"{params.path}: {path}.outside: {so:g} (up to {largest:g} to ISO 2768-m) must go into the "
                             f"{bo:g} mm seat, and at its smallest ({smallest:g}) stay over the {si:g} mm bore and the "
                             f"{ring_key} ring's band ({band:g} inside)")
    play = bo + fits.deviations(bo, seat)[0] - smallest
    reach = si - general_tolerance(si) - play
    if reach < edge - 1e-9:
        raise ParameterError(f"{params.path}: {path}.inside: {si:g} reaches in to {reach:g} (ISO 2768-m, and shifted by "
                             f"its {play:.3f} mm of play in the {bo:g} {seat} seat), over the {key}'s shield: its bore "
                             f"must stay outside the outer ring's face, which starts at {edge:g}")
    return si, so, s


def right_boss(params: HeadParameters) -> cq.Shape:
    """The boss on the right plate's outer face (head frame)."""
    lay = layout(params)
    hw = params.geometry("head", "floor").num("half_width")
    tx, _, tz = params.joints["eyes_tilt"].origin
    return geom.cyl("y", _node(params).node("boss").num("diameter"), -hw + 1, -lay.outer, (tx, tz))


def right_seat_tools(params: HeadParameters) -> list[cq.Shape]:
    return layout(params).tools


def frame_features(params: HeadParameters) -> tuple[list[cq.Shape], list[cq.Shape]]:
    """(added, cut) on the tilt frame (tilt link frame): the collars against both inner rings and the longer right
    journal; the clip's groove."""
    lay = layout(params)
    bore = params.purchased(params.drive("eyes_tilt").text("bearing")).num("bore")
    clip = params.purchased(_node(params).text("clip"))
    added = [geom.cyl("y", lay.collar, lay.arm - 1, lay.inner),
             geom.cyl("y", lay.collar, -lay.arm + 1, lay.bearing),
             geom.cyl("y", bore, lay.shaft_end, -lay.arm + 1)]
    cut = [geom.tube("y", bore + 1, clip.num("groove_diameter", positive=True), lay.groove[0], lay.groove[1])]
    return added, cut


def right_parts(params: HeadParameters) -> list[Part]:
    """The fixed bearing, its spacer and DIN 472 ring (head frame) and the clip on the journal (tilt link)."""
    lay = layout(params)
    tx, _, tz = params.joints["eyes_tilt"].origin
    key = params.drive("eyes_tilt").text("bearing")
    clip_key = _node(params).text("clip")
    clip = params.purchased(clip_key)
    clip_shape = geom.tube("z", clip.num("outside_diameter", positive=True), clip.num("groove_diameter"), 0,
                           clip.num("thickness"))
    return [purchased.bearing(params, "eyes_tilt_bearing_right", key, "head_frame", loc(tx, lay.bearing, tz, rx=90)),
            Part("eyes_tilt_bearing_spacer", "eyes_tilt_bearing_spacer", "head_frame", "machined",
                 geom.tube("z", lay.spacer[1], lay.spacer[0], 0, lay.spacer[2]), loc(tx, lay.spacer_at, tz, rx=90),
                 note=SPACER_NOTE, material="steel", color=STEEL),
            purchased.retaining_ring(params, "eyes_tilt_bearing_ring", neck.bearing_ring(params), "head_frame",
                                     loc(tx, lay.ring, tz, rx=90)),
            Part("eyes_tilt_clip", clip_key, "eyes_tilt_link", "purchased", clip_shape, loc(0, lay.clip, 0, rx=90),
                 mass=clip.num("mass"), color=DARK)]


def shaft_end(params: HeadParameters) -> float:
    """The right tilt journal's end along y, head frame (what a sensor outside it faces)."""
    return layout(params).shaft_end
