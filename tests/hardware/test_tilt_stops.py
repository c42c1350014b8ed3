# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""The eye tilt's hard stops against the geometry: the tilt frame's arm meets its pin exactly at each stop angle,
is clear of it over the whole range, and stops angles inside the range or pins off the arm are refused."""
import pytest

from robogene_head_model.params import ParameterError
from robogene_head.parts import tilt_stops
from robogene_head.geom import distance, exact_bounds

from param_variants import edited


def _copy(tmp_path, **stop):
    return edited(tmp_path, lambda d: d["geometry"]["eyes"]["tilt_stop"].update(stop))


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
    assert distance(*shapes(stop)) < 0.01
    assert distance(*shapes(stop + inward * 0.5)) > 0.05
    frame, p = shapes(stop - inward * 2)
    assert frame.intersect(p).Volume() > 0.1
    joint = params.joints["eyes_tilt"]
    limit = joint.upper if stop > 0 else joint.lower
    assert distance(*shapes(limit)) >= params.geometry("clearances").num("minimum")


def test_the_pins_stand_in_the_side_plates(params, assembly):
    """Each pin is pressed pin_depth into its plate's inner face and stands out towards the arm."""
    parts = {p.name: p for p in assembly.parts}
    depth = params.geometry("eyes", "tilt_stop").num("pin_depth")
    for plate in ("left", "right"):
        for i in (0, 1):
            pin, side = parts[f"eyes_tilt_stop_pin_{plate}_{i}"], parts[f"head_side_plate_{plate}"]
            inside = pin.shape.intersect(side.shape).Volume()
            assert inside < 1e-3                      # the hole takes it: no overlap
            (pin_lo, pin_hi), (plate_lo, plate_hi) = exact_bounds(pin.shape), exact_bounds(side.shape)
            into = (pin_hi[1] - plate_lo[1]) if plate == "left" else (plate_hi[1] - pin_lo[1])
            assert into == pytest.approx(depth, abs=1e-6)


@pytest.mark.parametrize("stop, where", [
    ({"stops_deg": [-35, 29]}, r"geometry\.eyes\.tilt_stop\.stops_deg: expected lower stop < -30 and upper stop > 30"),
    ({"depth": 40}, r"geometry\.eyes\.tilt_stop\.depth: 40 puts the pins off the arm's faces"),
    ({"pin_depth": 7}, r"geometry\.eyes\.tilt_stop\.pin_depth"),
])
def test_a_wrong_tilt_stop_is_named(tmp_path, stop, where):
    with pytest.raises(ParameterError, match=where):
        tilt_stops.pins(_copy(tmp_path, **stop), 60, (51, 82), "head_frame")
