# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""Each motor pulley sits on its gearhead's output shaft over most of the shaft's length.

Measured on the placed solids: the pulley's bore (its smallest cylindrical faces) gives the axis and the
region along it that the pulley holds; the shaft is the gearhead's cylindrical face of the bore's radius on
that axis. The engagement is the volume of gearhead inside the bore region over the bore's cross-section."""
import math

import cadquery as cq
import numpy as np
import pytest
import yaml
from OCP.BRepAdaptor import BRepAdaptor_Surface
from OCP.BRepTools import BRepTools
from OCP.GeomAbs import GeomAbs_Cylinder

from robogene_head_model.params import DEFAULT_PATH, ParameterError, load
from robogene_head.geom import exact_bounds
from robogene_head.parts import build_all

MIN_ENGAGEMENT = 0.75   # of the shaft's length


def cylinders(shape):
    """(radius, point on axis, unit axis, first, last) per cylindrical face; first/last along the axis."""
    out = []
    for face in shape.Faces():
        surface = BRepAdaptor_Surface(face.wrapped)
        if surface.GetType() != GeomAbs_Cylinder:
            continue
        axis = surface.Cylinder().Axis()
        point, direction = np.array(axis.Location().Coord()), np.array(axis.Direction().Coord())
        _, _, v0, v1 = BRepTools.UVBounds_s(face.wrapped)
        out.append((surface.Cylinder().Radius(), point, direction, v0, v1))
    return out


def span(faces, origin, axis):
    """The extent of coaxial faces along `axis`, measured from `origin`."""
    ends = [np.dot(p + v * d - origin, axis) for _, p, d, v0, v1 in faces for v in (v0, v1)]
    return min(ends), max(ends)


def engagement(pulley, gearhead):
    """(engaged length, shaft length) in mm."""
    faces = cylinders(pulley)
    radius = min(f[0] for f in faces)
    bore = [f for f in faces if abs(f[0] - radius) < 1e-6]
    origin, axis = bore[0][1], bore[0][2]

    def on_axis(f):
        offset = f[1] - origin
        return abs(abs(np.dot(f[2], axis)) - 1) < 1e-9 and np.linalg.norm(offset - np.dot(offset, axis) * axis) < 1e-6
    assert all(on_axis(f) for f in bore)
    shaft = [f for f in cylinders(gearhead) if abs(f[0] - radius) < 1e-6 and on_axis(f)]
    assert shaft, "no gearhead shaft in the pulley's bore"
    lo, hi = span(bore, origin, axis)
    region = cq.Solid.makeCylinder(radius, hi - lo, cq.Vector(*(origin + lo * axis)), cq.Vector(*axis))
    engaged = gearhead.intersect(region).Volume() / (math.pi * radius ** 2)
    s0, s1 = span(shaft, origin, axis)
    return engaged, s1 - s0


def test_motor_pulley_holds_most_of_the_shaft(assembly, params):
    joint = "neck_yaw"
    placed = {p.part.name: p.shape for p in assembly.pose({})}
    engaged, shaft = engagement(placed[f"{joint}_motor_pulley"], placed[f"{joint}_gearhead"])
    expected = params.purchased(params.drive(joint).text("gearhead")).num("shaft_length")
    assert shaft == pytest.approx(expected)
    assert engaged >= MIN_ENGAGEMENT * shaft, f"{joint}: the pulley holds {engaged:.2f} of {shaft:g} mm of shaft"


def test_the_tilt_motor_pulley_sits_on_the_jackshaft_over_its_whole_bore(assembly, params):
    """The tilt's catalogue pulley is on its jackshaft (parts/tilt_jackshaft.py): its whole 20 mm bore (14.3 over the
    flanges and the 5.7 mm hub) holds the shaft, less the two 0.5 mm flats under its set screws (about 0.45 mm of the
    shaft's section-length)."""
    from robogene_head.parts import tilt_jackshaft
    placed = {p.part.name: p.shape for p in assembly.pose({})}
    lay = tilt_jackshaft.layout(params)
    # exact bounds: OCCT's plain bounding box pads by the shapes' tolerance (about 0.03 mm here)
    (_, ymin, _), (_, ymax, _) = exact_bounds(placed["eyes_tilt_motor_pulley"])
    radius = tilt_jackshaft.node(params).node("shaft").num("diameter") / 2
    # the jackshaft placed at the zero pose (the head frame sits above the neck base, not turned)
    lo, hi = exact_bounds(placed["eyes_tilt_jackshaft"])
    x, z = (lo[0] + hi[0]) / 2, (lo[2] + hi[2]) / 2
    region = cq.Solid.makeCylinder(radius, ymax - ymin, cq.Vector(x, ymin, z), cq.Vector(0, 1, 0))
    engaged = placed["eyes_tilt_jackshaft"].intersect(region).Volume() / (math.pi * radius ** 2)
    assert ymax - ymin == pytest.approx(14.3 + 5.7) and lay.shaft[1] == pytest.approx(ymax)
    assert 20 - 0.6 < engaged < 20


def test_a_hub_gap_that_leaves_no_hub_is_named(params, external, tmp_path):
    data = yaml.safe_load(DEFAULT_PATH.read_text())
    data["geometry"]["pulleys"]["hub"]["gap"] = 20
    path = tmp_path / "p.yaml"
    path.write_text(yaml.safe_dump(data))
    with pytest.raises(ParameterError, match=r"geometry\.pulleys\.hub\.gap: 20 leaves no hub"):
        build_all(load(path), external)
