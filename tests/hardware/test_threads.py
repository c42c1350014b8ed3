# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""Tapped holes are those a fastener of the assembly is screwed into: a shank in a hole of its own diameter.
A clearance hole, a hole no fastener reaches and a fastener on another link are not; the hole is given in its
design's frame however the part is placed."""
from robogene_head import geom, threads
from robogene_head.parts import purchased
from robogene_head.parts.base import Part, loc


def plate(params):
    """A 40 x 20 x 6 plate placed upside down 100 mm up: a Ø3 hole 5 deep from its top face (z = 6 in its own
    frame) at x = 10, a Ø3.4 through at x = 20, a Ø3 through at x = 30 that no screw reaches."""
    shape = geom.cut(geom.box(0, 40, 0, 20, 0, 6), geom.cyl("z", 3.0, 1, 7, (10, 10)), geom.cyl("z", 3.4, -1, 7, (20, 10)),
                     geom.cyl("z", 3.0, -1, 7, (30, 10)))
    return Part("plate", "plate", "base", "machined", shape, loc(z=100, rx=180), material="aluminium-6082")


def screw_into(params, name, x, link="base", key="iso7380-M3x8"):
    """A screw from below the placed plate (its top face is at z = 94 in the link), up along +z into it."""
    return purchased.screw(params, name, key, link, loc(x, -10, 90))


def test_a_screw_in_a_hole_of_its_diameter_makes_it_tapped(params):
    part = plate(params)
    found = threads.tapped_holes(params, [part, screw_into(params, "a", 10), screw_into(params, "b", 20),
                                          screw_into(params, "c", 30, link="other")])
    (hole,) = found["plate"]
    assert (hole.thread, hole.diameter, hole.tap_drill) == ("M3", 3.0, 2.5)
    # the design frame: the axis at x = 10, y = 10; the hole's face from z = 1 to 6
    assert hole.point == (10.0, 10.0, 0.0) and hole.direction == (0.0, 0.0, 1.0)
    assert hole.span == (1.0, 6.0)
    assert hole.as_dict()["span"] == [1.0, 6.0]


def test_a_standoff_stud_taps_its_hole_and_nothing_else_does(params):
    part = plate(params)
    stud = purchased.standoff(params, "s", "standoff-M3x6-MF", "base", loc(30, -10, 100))   # stud up through it
    bearing = purchased.bearing(params, "b", params.drive("neck_roll").text("bearing"), "base", loc(10, -10, 90))
    found = threads.tapped_holes(params, [part, stud, bearing])
    assert [(h.thread, h.point) for h in found["plate"]] == [("M3", (30.0, 10.0, 0.0))]
    assert threads.tapped_holes(params, [part, bearing]) == {}
