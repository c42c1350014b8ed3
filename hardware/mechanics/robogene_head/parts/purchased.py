# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: CERN-OHL-S-2.0
"""Simplified envelopes of purchased parts, sized from the datasheet numbers in the parameter file.

Every envelope is built along +z from z = 0 in its design frame; the caller places it with a Location."""
from __future__ import annotations

import math

import cadquery as cq

from robogene_head_model.params import HeadParameters

from .. import geom
from .base import DARK, GREEN, STEEL, Part, loc


def _purchased(params: HeadParameters, name: str, key: str, link: str, shape: cq.Shape, placement: cq.Location,
               color) -> Part:
    return Part(name, key, link, "purchased", shape, placement, mass=params.purchased(key).num("mass"), color=color)


def gearhead_bolt_circle(params: HeadParameters, diameter: float) -> list[tuple[float, float]]:
    """The flange's four mounting threads as this design assumes them (geometry.gearhead_flange): on a bolt circle
    of bolt_circle_ratio x the gearhead's diameter, at 45 deg + k * 90 deg."""
    ratio = params.geometry("gearhead_flange").num("bolt_circle_ratio", positive=True, maximum=1.0)
    r = ratio / 2 * diameter
    return [(r * math.cos(math.radians(45 + 90 * k)), r * math.sin(math.radians(45 + 90 * k))) for k in range(4)]


def gearhead_shape(params: HeadParameters, p) -> cq.Shape:
    """Body z 0..length with the flange's tapped holes, output shaft z -shaft_length..0 (the flange face is z = 0)."""
    f = params.geometry("gearhead_flange")
    body = geom.union(geom.cyl("z", p.num("diameter"), 0, p.num("length")),
                      geom.cyl("z", p.num("shaft_diameter"), -p.num("shaft_length"), 0))
    return geom.cut(body, *[geom.cyl("z", f.num("thread", positive=True), -1, f.num("thread_depth", positive=True), c)
                            for c in gearhead_bolt_circle(params, p.num("diameter"))])


def drive_stack(params: HeadParameters, joint: str, link: str, placement: cq.Location) -> list[Part]:
    """Gearhead + motor (+ holding brake) + encoder of a joint's drive. In the stack frame the gearhead flange face is
    at z = 0, the output shaft points to -z and the motor, its brake on the rear shaft and the encoder follow along
    +z."""
    drive = params.drive(joint)
    gear, motor, enc = (params.purchased(drive.text(k)) for k in ("gearhead", "motor", "encoder"))
    z_motor = gear.num("length")
    z_enc = z_motor + motor.num("length")
    parts = [
        _purchased(params, f"{joint}_gearhead", drive.text("gearhead"), link, gearhead_shape(params, gear),
                   placement, DARK),
        _purchased(params, f"{joint}_motor", drive.text("motor"), link,
                   geom.cyl("z", motor.num("diameter"), 0, motor.num("length")), placement * loc(z=z_motor), STEEL),
    ]
    if drive.has("brake"):
        brake = params.purchased(drive.text("brake"))
        parts.append(_purchased(params, f"{joint}_brake", drive.text("brake"), link,
                                geom.cyl("z", brake.num("diameter", positive=True), 0, brake.num("length", positive=True)),
                                placement * loc(z=z_enc), GREEN))
        z_enc += brake.num("length")
    parts.append(_purchased(params, f"{joint}_encoder", drive.text("encoder"), link,
                            geom.cyl("z", enc.num("diameter"), 0, enc.num("length")), placement * loc(z=z_enc), DARK))
    return parts


def bearing(params: HeadParameters, name: str, key: str, link: str, placement: cq.Location) -> Part:
    """Ring z 0..width."""
    b = params.purchased(key)
    shape = geom.tube("z", b.num("outside"), b.num("bore"), 0, b.num("width"))
    return _purchased(params, name, key, link, shape, placement, STEEL)


def retaining_ring(params: HeadParameters, name: str, key: str, link: str, placement: cq.Location) -> Part:
    """Ring z 0..thickness, its outside the groove diameter it springs into."""
    r = params.purchased(key)
    shape = geom.tube("z", r.num("groove_diameter"), r.num("inner_diameter"), 0, r.num("thickness"))
    return _purchased(params, name, key, link, shape, placement, DARK)


def shim(params: HeadParameters, name: str, key: str, link: str, placement: cq.Location) -> Part:
    """Flat ring z 0..thickness."""
    r = params.purchased(key)
    shape = geom.tube("z", r.num("outside"), r.num("bore"), 0, r.num("thickness"))
    return _purchased(params, name, key, link, shape, placement, STEEL)


def joint_encoder(params: HeadParameters, name: str, link: str, placement: cq.Location, key="ams-AS5048A") -> Part:
    """Sensor board: the origin at its holes' centre on the face that carries the IC, the PCB z 0..height, the IC's
    package z -ic.height..0 (its face towards the magnet at z = -ic.height), at ic_at; one solid."""
    e = params.purchased(key)
    l, w, h = e.num("length", positive=True), e.num("width", positive=True), e.num("height", positive=True)
    ox, oy = e.vec("outline_at", 2)
    ic = e.node("ic")
    il, iw, ih = ic.num("length", positive=True), ic.num("width", positive=True), ic.num("height", positive=True)
    ix, iy = e.vec("ic_at", 2)
    shape = geom.union(geom.box(ox - w / 2, ox + w / 2, oy - l / 2, oy + l / 2, 0, h),
                       geom.box(ix - iw / 2, ix + iw / 2, iy - il / 2, iy + il / 2, -ih, 0))
    holes = e.node("holes")
    px, py = holes.vec("pitch", 2)
    shape = geom.cut(shape, *[geom.cyl("z", holes.num("diameter", positive=True), -1, h + 1, (sx * px / 2, sy * py / 2))
                              for sx in (-1, 1) for sy in (-1, 1)])
    return _purchased(params, name, key, link, geom.single_solid(shape, name), placement, GREEN)


def camera(params: HeadParameters, name: str, key: str, link: str, placement: cq.Location) -> Part:
    """Board in x = -thickness..0 facing +x, lens z-centred on the board, x 0..lens_length."""
    c = params.purchased(key)
    w, h, t = c.num("board_width"), c.num("board_height"), c.num("thickness")
    shape = geom.union(geom.box(-t, 0, -w / 2, w / 2, -h / 2, h / 2),
                       geom.cyl("x", c.num("lens_diameter"), 0, c.num("lens_length")))
    return _purchased(params, name, key, link, shape, placement, GREEN)


def screw(params: HeadParameters, name: str, key: str, link: str, placement: cq.Location) -> Part:
    """Button head z -head_height..0, shank z 0..length (the head seats on z = 0)."""
    s = params.purchased(key)
    shape = geom.union(geom.cyl("z", s.num("head_diameter"), -s.num("head_height"), 0),
                       geom.cyl("z", s.num("diameter"), 0, s.num("length")))
    return _purchased(params, name, key, link, shape, placement, DARK)


def set_screw(params: HeadParameters, name: str, key: str, link: str, placement: cq.Location) -> Part:
    """Headless set screw z 0..length: its hex socket at z = 0, its point at z = length (the cup drawn flat)."""
    s = params.purchased(key)
    return _purchased(params, name, key, link, geom.cyl("z", s.num("diameter"), 0, s.num("length")), placement, DARK)


STUD_WEB = 1.0   # mm of solid hex between a male-female standoff's stud and its female thread


def standoff(params: HeadParameters, name: str, key: str, link: str, placement: cq.Location) -> Part:
    """Hex prism z 0..length with a thread-size bore (the mating screws fill it). A male-female standoff (one with
    a stud_length) has its threaded stud below, z -stud_length..0, and a blind bore down to z = STUD_WEB."""
    s = params.purchased(key)
    corner = s.num("across_flats") / math.cos(math.radians(30))
    hexagon = cq.Workplane("XY").polygon(6, corner).extrude(s.num("length")).val()
    male = s.has("stud_length")
    shape = hexagon.cut(geom.cyl("z", s.num("thread"), STUD_WEB if male else -1, s.num("length") + 1))
    if male:
        shape = geom.union(shape, geom.cyl("z", s.num("thread"), -s.num("stud_length", positive=True), 0))
    return _purchased(params, name, key, link, geom.single_solid(shape, name), placement, STEEL)


def pin(params: HeadParameters, name: str, key: str, link: str, placement: cq.Location) -> Part:
    """Dowel pin, z 0..length."""
    p = params.purchased(key)
    return _purchased(params, name, key, link, geom.cyl("z", p.num("diameter"), 0, p.num("length")), placement, STEEL)
