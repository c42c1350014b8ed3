# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""Each motor pulley sits on its jackshaft over its whole bore. No pulley sits on a gearhead's own output shaft any
more: the 16/7's and the 22/7's are too short for a catalogue pulley (docs/fabricate.md, "The jackshaft stages").

Measured on the placed solids: the jackshaft's volume inside a cylinder of its diameter along the pulley's length,
over the shaft's cross-section, is the length of shaft the pulley holds."""
import math

import cadquery as cq
import pytest

from robogene_head.geom import exact_bounds


@pytest.mark.parametrize("joint, axis", [("eyes_tilt", 1), ("neck_yaw", 2)])
def test_each_motor_pulley_sits_on_its_jackshaft_over_its_whole_bore(assembly, params, joint, axis):
    """The tilt's and the yaw's catalogue pulleys are on their jackshafts (parts/jackshaft.py; the tilt's along y, the
    yaw's down z): the whole 20 mm bore (14.3 over the flanges and the 5.7 mm hub) holds the shaft, less the two
    0.5 mm flats under its set screws (about 0.45 mm of the shaft's section-length), and the shaft ends with it."""
    placed = {p.part.name: p.shape for p in assembly.pose({})}
    # exact bounds: OCCT's plain bounding box pads by the shapes' tolerance (about 0.03 mm here)
    p0, p1 = exact_bounds(placed[f"{joint}_motor_pulley"])
    j0, j1 = exact_bounds(placed[f"{joint}_jackshaft"])
    key = "tilt_jackshaft" if joint == "eyes_tilt" else "yaw_jackshaft"
    radius = params.geometry(key, "shaft").num("diameter") / 2
    # the jackshaft placed at the zero pose (the head frame sits above the neck base, not turned)
    centre = [(a + b) / 2 for a, b in zip(j0, j1)]
    start, direction = list(centre), [0, 0, 0]
    start[axis], direction[axis] = p0[axis], 1
    length = p1[axis] - p0[axis]
    region = cq.Solid.makeCylinder(radius, length, cq.Vector(*start), cq.Vector(*direction))
    engaged = placed[f"{joint}_jackshaft"].intersect(region).Volume() / (math.pi * radius ** 2)
    assert length == pytest.approx(14.3 + 5.7)
    # the jackshaft ends with the pulley's hub: the tilt's outboard (+y), the yaw's below (-z)
    assert (p1[axis] == pytest.approx(j1[axis])) if axis == 1 else (p0[axis] == pytest.approx(j0[axis]))
    assert 20 - 0.6 < engaged < 20
