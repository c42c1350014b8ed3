# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: CERN-OHL-S-2.0
"""Each joint encoder measured in the CAD against the AS5048A's magnet window (purchased.<board>.air_gap and
displacement): over the joint's range, the air gap between the magnet's face and the IC's face, and how far the IC's
centre is from the magnet's axis (which also catches a magnet off the joint's axis: it swings round the IC then).

Nothing is taken from the parameters but which parts to look at and the window: the magnet's axis and face come from
its cylindrical and planar faces, the IC's face is the board's planar face nearest the magnet (the IC's package
stands out of the board towards it), all as the assembly places them at each angle."""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from OCP.BRepAdaptor import BRepAdaptor_Surface
from OCP.GeomAbs import GeomAbs_Cylinder, GeomAbs_Plane

from robogene_head_model.params import HeadParameters

from .. import kinematics
from ..geom import location
from ..parts.joint_encoders import JOINTS

SAMPLES = 5   # angles per joint over its range, both limits included


@dataclass
class Row:
    joint: str
    gap_min: float          # mm, magnet face to the IC's face, over the range
    gap_max: float
    offset_max: float       # mm, the IC's centre from the magnet's axis, over the range
    window: tuple[float, float]
    displacement: float

    @property
    def problems(self) -> list[str]:
        out = []
        if self.gap_min < self.window[0] - 1e-6:
            out.append(f"air gap {self.gap_min:.2f} mm, under the datasheet's {self.window[0]:g}")
        if self.gap_max > self.window[1] + 1e-6:
            out.append(f"air gap {self.gap_max:.2f} mm, over the datasheet's {self.window[1]:g}")
        if self.offset_max > self.displacement + 1e-6:
            out.append(f"IC {self.offset_max:.2f} mm off the magnet's axis, the datasheet allows {self.displacement:g}")
        return out

    @property
    def ok(self) -> bool:
        return not self.problems


@dataclass
class Report:
    rows: list[Row]

    @property
    def ok(self) -> bool:
        return all(r.ok for r in self.rows)

    @property
    def failures(self) -> list[str]:
        return [f"{r.joint}: {p}" for r in self.rows for p in r.problems]


def _vec(v) -> np.ndarray:
    """An OCP point or direction, or a CadQuery Vector, as an array."""
    if hasattr(v, "X"):
        return np.array([v.X(), v.Y(), v.Z()])
    return np.array([v.x, v.y, v.z])


def _magnet_axis(shape) -> tuple[np.ndarray, np.ndarray, list[np.ndarray]]:
    """(point on the axis, unit direction, centres of the two end faces) of a magnet's cylinder."""
    axis, ends = None, []
    for face in shape.Faces():
        surface = BRepAdaptor_Surface(face.wrapped)
        if surface.GetType() == GeomAbs_Cylinder:
            ax = surface.Cylinder().Axis()
            axis = (_vec(ax.Location()), _vec(ax.Direction()))
        elif surface.GetType() == GeomAbs_Plane:
            ends.append(_vec(face.Center()))
    if axis is None or len(ends) != 2:
        raise ValueError("a joint encoder's magnet must be a plain cylinder")
    return axis[0], axis[1] / np.linalg.norm(axis[1]), ends


def _ic_face(shape, towards: np.ndarray, along: np.ndarray) -> np.ndarray:
    """Centre of the board's planar face across the axis that stands nearest the magnet's face."""
    best = None
    for face in shape.Faces():
        surface = BRepAdaptor_Surface(face.wrapped)
        if surface.GetType() != GeomAbs_Plane:
            continue
        normal = _vec(surface.Plane().Axis().Direction())
        if abs(abs(normal @ along) - 1) > 1e-6:
            continue
        centre = _vec(face.Center())
        d = abs((centre - towards) @ along)
        if best is None or d < best[0]:
            best = (d, centre)
    if best is None:
        raise ValueError("a joint encoder's board has no face across the magnet's axis")
    return best[1]


def measure(params: HeadParameters, parts, joint: str) -> Row:
    by_name = {p.name: p for p in parts}
    magnet, board = by_name[f"{joint}_encoder_magnet"], by_name[f"{joint}_joint_encoder"]
    b = params.purchased(board.design)
    window = b.vec("air_gap", 2)
    j = params.joints[joint]
    gaps, offsets = [], []
    for angle in np.linspace(j.lower, j.upper, SAMPLES):
        poses = kinematics.link_poses(params, {joint: float(angle)})
        m = magnet.shape.moved(location(poses[magnet.link]))
        s = board.shape.moved(location(poses[board.link]))
        point, direction, ends = _magnet_axis(m)
        # the magnet's face towards the board: the end face nearer the board's centre
        centre = _vec(s.Center())
        face = min(ends, key=lambda e: np.linalg.norm(e - centre))
        ic = _ic_face(s, face, direction)
        gaps.append(abs((ic - face) @ direction))
        radial = (ic - point) - ((ic - point) @ direction) * direction
        offsets.append(float(np.linalg.norm(radial)))
    return Row(joint, float(min(gaps)), float(max(gaps)), float(max(offsets)), window,
               b.num("displacement", positive=True))


def check(params: HeadParameters, parts) -> Report:
    return Report([measure(params, parts, joint) for joint in JOINTS])


def report_json(report: Report) -> dict:
    return {"joints": [{"joint": r.joint, "gap_min_mm": round(r.gap_min, 4), "gap_max_mm": round(r.gap_max, 4),
                        "air_gap_window_mm": list(r.window), "ic_off_axis_mm": round(r.offset_max, 4),
                        "displacement_mm": r.displacement, "ok": r.ok, "problems": r.problems}
                       for r in report.rows]}


def format_report(report: Report) -> str:
    lines = ["Joint encoders: the AS5048A's air gap and the IC's displacement from the magnet's axis, measured in the",
             "CAD over each joint's range (reports/joint-encoders.txt).",
             "",
             f"{'joint':<12} {'air gap (mm)':>14} {'window':>10} {'IC off axis (mm)':>17} {'allowed':>8}  result"]
    for r in report.rows:
        gap = f"{r.gap_min:.2f}" if abs(r.gap_max - r.gap_min) < 0.005 else f"{r.gap_min:.2f}-{r.gap_max:.2f}"
        lines.append(f"{r.joint:<12} {gap:>14} {r.window[0]:>4g}-{r.window[1]:<5g} {r.offset_max:>17.3f} "
                     f"{r.displacement:>8g}  {'ok' if r.ok else 'FAIL: ' + '; '.join(r.problems)}")
    return "\n".join(lines)
