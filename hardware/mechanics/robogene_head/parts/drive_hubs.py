# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: CERN-OHL-S-2.0
"""The hubs that take the direct neck drives' gearhead output shafts (geometry.drive_hubs): the pitch stage's left
journal and the roll stage's rear journal grow to the hub's diameter around the shaft's bore, and two ISO 4029
cup-point set screws, 90 deg apart in one plane, press on the gearhead's round output shaft there. What they carry
is the torque-path check's (torque_paths:, torque_path.py); why set screws and not a flat or a clamp is in
docs/fabricate.md, "Torque paths".

Everything here is in the link frame of the stage, whose joint axis is `axis` through `at` (the other two
coordinates, in geom.cyl's order)."""
from __future__ import annotations

import math
from dataclasses import dataclass

import cadquery as cq

from robogene_head_model.params import HeadParameters, ParameterError

from .. import geom
from .base import loc

_AXES = {"x": (1.0, 0.0, 0.0), "y": (0.0, 1.0, 0.0), "z": (0.0, 0.0, 1.0)}
LAND_DEPTH = 0.5   # mm: the flat land milled at each set screw's mouth, below the hub's round surface


@dataclass(frozen=True)
class Hub:
    joint: str
    axis: str                   # the joint axis in the link frame
    at: tuple[float, float]     # where it runs, geom.cyl's order
    diameter: float
    clearance: float
    shaft: float                # the gearhead's output shaft
    screw: str                  # purchased key of the set screws
    screw_diameter: float
    screw_length: float
    tip: float                  # coordinate along the axis of the gearhead shaft's end
    plane: float                # coordinate along the axis of the set screws' axes
    directions: tuple[str, ...]  # each screw's axis, pointing from the shaft out to its socket: "x", "y" or "z"
    access: float               # diameter of the access holes through the wall around the hub (0: none)

    def centre(self) -> tuple[float, float, float]:
        a, b = self.at
        return {"x": (self.plane, a, b), "y": (a, self.plane, b), "z": (a, b, self.plane)}[self.axis]

    def screw_location(self, direction: str) -> cq.Location:
        """The set screw's frame (purchased.set_screw: socket end at z = 0, point at z = length): its point on the
        shaft, its socket inside the hub."""
        c = self.centre()
        u = _AXES[direction]
        r = self.shaft / 2 + self.screw_length
        x, y, z = (c[k] + u[k] * r for k in range(3))
        turn = {"z": {"rx": 180.0}, "x": {"ry": -90.0}, "y": {"rx": 90.0}}[direction]   # its +z towards the shaft
        return loc(x, y, z, **turn)

    def tapped_holes(self) -> list[cq.Shape]:
        """The set screws' threads, drawn at the nominal diameter from the bore out through the hub."""
        return [self._radial(d, self.screw_diameter, 0.0, self.diameter / 2 + 1) for d in self.directions]

    def lands(self) -> list[cq.Shape]:
        """A flat land LAND_DEPTH deep across the hub at each tapped hole's mouth, SCREW + 2 wide along the joint
        axis: the drill and tap start square on it, and the hole opens in a plane, so its drawing shows a circle."""
        out = []
        c = self.centre()
        along = "xyz".index(self.axis)
        for d in self.directions:
            k = "xyz".index(d)
            lo, hi = [0.0] * 3, [0.0] * 3
            for i in range(3):
                if i == k:
                    lo[i], hi[i] = c[i] + self.diameter / 2 - LAND_DEPTH, c[i] + self.diameter / 2 + 1
                elif i == along:
                    lo[i], hi[i] = c[i] - (self.screw_diameter + 2) / 2, c[i] + (self.screw_diameter + 2) / 2
                else:
                    lo[i], hi[i] = c[i] - self.diameter / 2 - 1, c[i] + self.diameter / 2 + 1
            out.append(geom.box(lo[0], hi[0], lo[1], hi[1], lo[2], hi[2]))
        return out

    def access_holes(self, outer: dict[str, float]) -> list[cq.Shape]:
        """Holes through the wall the hub turns in, one along each screw from the hub out to the wall's face at
        outer[direction], for the screw and its hex key."""
        if not self.access:
            return []
        return [self._radial(d, self.access, self.diameter / 2 - 1, outer[d] + 1) for d in self.directions]

    def _radial(self, direction: str, diameter: float, r0: float, r1: float) -> cq.Shape:
        c = self.centre()
        k = "xyz".index(direction)
        others = tuple(c[i] for i in range(3) if i != k)
        return geom.cyl(direction, diameter, c[k] + r0, c[k] + r1, others)


def hub(params: HeadParameters, joint: str, axis: str, at: tuple[float, float], tip: float,
        towards_gearhead: float) -> Hub:
    """The hub of `joint`: the gearhead's shaft ends at `tip` along `axis` and comes from the side of sign
    `towards_gearhead`."""
    g = params.geometry("drive_hubs")
    j = g.node(joint)
    where = f"{params.path}: geometry.drive_hubs"
    screw_key = g.text("screw")
    screw = params.purchased(screw_key)
    if screw.text("kind") != "set_screw":
        raise ParameterError(f"{where}.screw: {screw_key} is a {screw.text('kind')}, expected a set_screw")
    shaft = params.purchased(params.drive(joint).text("gearhead")).num("shaft_diameter", positive=True)
    diameter = g.num("diameter", positive=True)
    length = screw.num("length", positive=True)
    # the screw's socket end, edge included, stays inside the hub, which turns close to the wall around it
    if math.hypot(shaft / 2 + length, screw.num("diameter") / 2) > diameter / 2 - LAND_DEPTH:
        raise ParameterError(f"{where}.diameter: the {screw_key}s on the {shaft:g} mm shaft stand out of a "
                             f"{diameter:g} mm hub")
    directions = j.raw("directions")
    if (not isinstance(directions, list) or len(directions) != 2 or any(d not in "xyz" or d == axis or len(d) != 1
                                                                          for d in directions)
            or directions[0] == directions[1]):
        raise ParameterError(f"{where}.{joint}.directions: expected two different axes across the {axis} joint "
                             f"axis (x, y or z), got {directions!r}")
    from_tip = j.num("from_tip", positive=True)
    point = screw.num("diameter", positive=True) / 2
    if from_tip < point:
        raise ParameterError(f"{where}.{joint}.from_tip: {from_tip:g} puts the {screw_key} past the shaft's end")
    access = j.num("access", positive=True) if j.has("access") else 0.0
    if access and access <= screw.num("diameter"):
        raise ParameterError(f"{where}.{joint}.access: a {access:g} mm hole does not pass the {screw_key}")
    return Hub(joint, axis, at, diameter, g.num("clearance", positive=True), shaft, screw_key,
               screw.num("diameter"), length, tip, tip + towards_gearhead * from_tip, tuple(directions), access)
