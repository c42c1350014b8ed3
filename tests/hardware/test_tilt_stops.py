# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""The eye tilt's hard stops against the geometry: the tilt frame's arm meets its pin exactly at each stop angle,
is clear of it over the whole range, and stops angles inside the range or pins off the arm are refused."""
import pytest
import yaml
from OCP.Bnd import Bnd_Box
from OCP.BRepBndLib import BRepBndLib
from OCP.BRepExtrema import BRepExtrema_DistShapeShape

from robogene_head_model.params import DEFAULT_PATH, ParameterError, load
from robogene_head.parts import tilt_stops


def _distance(a, b) -> float:
    d = BRepExtrema_DistShapeShape(a.wrapped, b.wrapped)
    d.Perform()
    return d.Value()


def _y_range(shape) -> tuple[float, float]:
    """The shape's exact extent along y (OpenCASCADE's optimal box, not the meshed one)."""
    box = Bnd_Box()
    BRepBndLib.AddOptimal_s(shape.wrapped, box, False, False)
    x0, y0, z0, x1, y1, z1 = box.Get()
    return y0, y1


def _copy(tmp_path, **stop):
    data = yaml.safe_load(DEFAULT_PATH.read_text())
    data["geometry"]["eyes"]["tilt_stop"].update(stop)
    path = tmp_path / "head-parameters.yaml"
    path.write_text(yaml.safe_dump(data, sort_keys=False))
    return load(path)


@pytest.mark.timeout(900)
@pytest.mark.parametrize("side, plate", [(0, "left"), (1, "left"), (1, "right")])
def test_the_arm_strikes_its_pin_at_the_stop(params, assembly, side, plate):
    """At the stop angle the arm touches the pin; half a degree short it is clear, two degrees past it they overlap;
    at the joint's limit it keeps the fabricator's minimum clearance."""
    stop = tilt_stops.stops_deg(params)[side]          # side 0: the lower stop (pin 0), 1: the upper (pin 1)
    pin = f"eyes_tilt_stop_pin_{plate}_{side}"

    def shapes(angle):
        placed = {p.part.name: p.shape for p in assembly.pose(chain={"eyes_tilt": angle})}
        return placed["eyes_tilt_frame"], placed[pin]
    inward = -1 if stop > 0 else 1
    assert _distance(*shapes(stop)) < 0.01
    assert _distance(*shapes(stop + inward * 0.5)) > 0.05
    frame, p = shapes(stop - inward * 2)
    assert frame.intersect(p).Volume() > 0.1
    joint = params.joints["eyes_tilt"]
    limit = joint.upper if stop > 0 else joint.lower
    assert _distance(*shapes(limit)) >= params.geometry("clearances").num("minimum")


def test_the_pins_stand_in_the_side_plates(params, assembly):
    """Each pin is pressed pin_depth into its plate's inner face and stands out towards the arm."""
    parts = {p.name: p for p in assembly.parts}
    depth = params.geometry("eyes", "tilt_stop").num("pin_depth")
    for plate in ("left", "right"):
        for i in (0, 1):
            pin, side = parts[f"eyes_tilt_stop_pin_{plate}_{i}"], parts[f"head_side_plate_{plate}"]
            inside = pin.shape.intersect(side.shape).Volume()
            assert inside < 1e-3                      # the hole takes it: no overlap
            (pin_y0, pin_y1), (plate_y0, plate_y1) = _y_range(pin.shape), _y_range(side.shape)
            into = (pin_y1 - plate_y0) if plate == "left" else (plate_y1 - pin_y0)
            assert into == pytest.approx(depth, abs=1e-6)


@pytest.mark.parametrize("stop, where", [
    ({"stops_deg": [-35, 29]}, r"geometry\.eyes\.tilt_stop\.stops_deg: expected lower stop < -30 and upper stop > 30"),
    ({"depth": 40}, r"geometry\.eyes\.tilt_stop\.depth: 40 puts the pins off the arm's faces"),
    ({"pin_depth": 7}, r"geometry\.eyes\.tilt_stop\.pin_depth"),
])
def test_a_wrong_tilt_stop_is_named(tmp_path, stop, where):
    with pytest.raises(ParameterError, match=where):
        tilt_stops.pins(_copy(tmp_path, **stop), 60, (51, 82), "head_frame")
