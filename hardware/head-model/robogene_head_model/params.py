# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: CERN-OHL-S-2.0
"""Load and validate hardware/head-parameters.yaml.

A wrong file gets a ParameterError naming the key path (e.g. joints.neck_yaw.axis[2]) or the
YAML line:column, never a KeyError deep inside the CAD code."""
from __future__ import annotations

import math
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import yaml

from . import strict_yaml

DEFAULT_PATH = Path(__file__).resolve().parents[2] / "head-parameters.yaml"

CONTROL_JOINTS = ("neck_pitch", "neck_roll", "neck_yaw", "eyes_tilt", "eyes_version", "eyes_vergence")
CHAIN_JOINTS = ("neck_pitch", "neck_roll", "neck_yaw", "eyes_tilt", "left_eye_pan", "right_eye_pan")
PURCHASED_KINDS = {
    "motor": ("voltage", "diameter", "length", "shaft_diameter", "shaft_length", "mass"),
    "gearhead": ("ratio", "diameter", "length", "shaft_diameter", "shaft_length", "mass"),
    "encoder": ("lines", "diameter", "length", "mass"),
    "joint_encoder": ("bits", "length", "width", "height", "mass"),
    "bearing": ("bore", "outside", "width", "mass"),
    "retaining_ring": ("bore", "groove_diameter", "groove_width", "thickness", "inner_diameter", "mass"),
    # an external ring (DIN 471) on a shaft: the room its lugs need as mounted (lug_outer_diameter), the shaft it
    # needs beyond its groove (groove_edge)
    "shaft_ring": ("shaft", "groove_diameter", "groove_width", "thickness", "groove_edge", "outside_diameter",
                   "lug_outer_diameter", "mass"),
    "shim": ("bore", "outside", "thickness", "mass"),
    # a shaft coupling: across, long, its two bores (the clamp screws: robogene_head/parts/jackshaft.py)
    "coupling": ("diameter", "length", "offset", "seat", "mass"),
    # a catalogue timing pulley, drawn from its stage (geometry.pulleys)
    "pulley": ("mass",),
    "camera": ("board_width", "board_height", "thickness", "lens_diameter", "lens_length", "mass"),
    "screw": ("diameter", "length", "head_diameter", "head_height", "mass"),
    # a headless set screw (ISO 4026..4029): holding_force_N, the maker's axial holding force at its seating torque
    "set_screw": ("diameter", "length", "holding_force_N", "mass"),
    "pin": ("diameter", "length", "mass"),
    "magnet": ("diameter", "thickness", "mass"),
    "standoff": ("across_flats", "length", "thread", "mass"),
    "belt": ("width", "thickness", "tooth_height", "mass_per_metre"),
    # a power-off holding brake on a motor's rear shaft: static torque, coil voltage and power, the inertia of what
    # turns with the shaft (hub and disc)
    "brake": ("static_torque_mNm", "voltage", "power_W", "diameter", "length", "mass", "rotor_inertia_gcm2"),
}


class ParameterError(ValueError):
    """A parameter file problem; the message starts with the file and the key path."""


class Node:
    """Read-only view of a mapping that reports missing or wrong keys by their full path."""

    def __init__(self, data: Any, path: str, source: str):
        self._data, self._path, self._source = data, path, source

    def fail(self, key: str, what: str) -> ParameterError:
        """The error to raise for `key` of this node: the file, the key's full path, then `what`. Public: the checks
        that read a node report their own findings on its keys through it."""
        where = f"{self._path}.{key}" if self._path else key
        return ParameterError(f"{self._source}: {where}: {what}")

    def has(self, key: str) -> bool:
        return isinstance(self._data, dict) and key in self._data

    def raw(self, key: str) -> Any:
        if not isinstance(self._data, dict):
            raise ParameterError(f"{self._source}: {self._path or '<top>'}: expected a mapping")
        if key not in self._data:
            raise self.fail(key, "missing")
        return self._data[key]

    def node(self, key: str) -> "Node":
        value = self.raw(key)
        if not isinstance(value, dict):
            raise self.fail(key, f"expected a mapping, got {type(value).__name__}")
        return Node(value, f"{self._path}.{key}" if self._path else key, self._source)

    def keys(self) -> list[str]:
        return list(self._data.keys())

    def num(self, key: str, *, positive: bool = False, minimum: float | None = None,
            maximum: float | None = None) -> float:
        value = self.raw(key)
        if isinstance(value, bool) or not isinstance(value, (int, float)) or not math.isfinite(value):
            raise self.fail(key, f"expected a number, got {value!r}")
        if positive and value <= 0:
            raise self.fail(key, f"must be > 0, got {value!r}")
        if minimum is not None and value < minimum:
            raise self.fail(key, f"must be >= {minimum}, got {value!r}")
        if maximum is not None and value > maximum:
            raise self.fail(key, f"must be <= {maximum:g}, got {value!r}")
        return float(value)

    def text(self, key: str) -> str:
        value = self.raw(key)
        if not isinstance(value, str) or not value:
            raise self.fail(key, f"expected a non-empty string, got {value!r}")
        return value

    def vec(self, key: str, n: int = 3) -> tuple[float, ...]:
        value = self.raw(key)
        if not isinstance(value, list) or len(value) != n:
            raise self.fail(key, f"expected a list of {n} numbers, got {value!r}")
        for i, item in enumerate(value):
            if isinstance(item, bool) or not isinstance(item, (int, float)) or not math.isfinite(item):
                raise self.fail(f"{key}[{i}]", f"expected a number, got {item!r}")
        return tuple(float(v) for v in value)

    def points(self, key: str) -> list[tuple[float, float]]:
        """A non-empty list of [x, y] points (hole positions and the like)."""
        value = self.raw(key)
        if not isinstance(value, list) or not value:
            raise self.fail(key, f"expected a list of [x, y] points, got {value!r}")
        items = Node({f"{key}[{i}]": item for i, item in enumerate(value)}, self._path, self._source)
        return [items.vec(f"{key}[{i}]", 2) for i in range(len(value))]

    def __getitem__(self, key: str) -> Any:
        return self.raw(key)


@dataclass(frozen=True)
class Joint:
    name: str
    parent: str
    child: str
    origin: tuple[float, float, float]  # mm, in the parent frame
    axis: tuple[float, float, float]    # unit vector, child frame
    lower: float                        # degrees
    upper: float


@dataclass(frozen=True)
class HeadParameters:
    path: Path
    root: Node
    joints: dict[str, Joint]
    control_limits: dict[str, tuple[float, float]]

    def geometry(self, *keys: str) -> Node:
        node = self.root.node("geometry")
        for key in keys:
            node = node.node(key)
        return node

    def purchased(self, key: str) -> Node:
        return self.root.node("purchased").node(key)

    def drive(self, joint: str) -> Node:
        return self.root.node("drives").node(joint)

    @property
    def baseline(self) -> float:
        return self.root.node("cameras").num("baseline", positive=True)


def _joint(name: str, node: Node) -> Joint:
    axis = node.vec("axis")
    norm = math.sqrt(sum(a * a for a in axis))
    if abs(norm - 1.0) > 1e-9:
        raise node.fail("axis", f"must be a unit vector, has length {norm:.6g}")
    lower, upper = node.num("min"), node.num("max")
    if lower >= upper:
        raise node.fail("min", f"must be below max ({lower} >= {upper})")
    return Joint(name, node.text("parent"), node.text("child"), node.vec("origin"), axis, lower, upper)


def _check_purchased(root: Node) -> None:
    catalog = root.node("purchased")
    for key in catalog.keys():
        part = catalog.node(key)
        kind = part.text("kind")
        if kind not in PURCHASED_KINDS:
            raise part.fail("kind", f"unknown kind {kind!r}; known: {', '.join(sorted(PURCHASED_KINDS))}")
        for field in PURCHASED_KINDS[kind]:
            part.num(field, positive=True)


def _check_drives(root: Node) -> None:
    drives, catalog = root.node("drives"), root.node("purchased")
    for joint in CHAIN_JOINTS:
        drive = drives.node(joint)
        for field, kind in (("motor", "motor"), ("gearhead", "gearhead"), ("encoder", "encoder"),
                            ("joint_encoder", "joint_encoder"), ("bearing", "bearing"), ("brake", "brake")):
            if not drive.has(field):
                if field in ("motor", "gearhead", "encoder"):
                    raise drive.fail(field, "missing")
                continue
            key = drive.text(field)
            if not catalog.has(key):
                raise drive.fail(field, f"{key!r} is not listed under purchased")
            if catalog.node(key).text("kind") != kind:
                raise drive.fail(field, f"{key!r} is a {catalog.node(key).text('kind')}, expected a {kind}")


def parse(data: Any, source: str, path: Path) -> HeadParameters:
    if not isinstance(data, dict):
        raise ParameterError(f"{source}: top level must be a mapping")
    root = Node(data, "", source)
    joints_node = root.node("joints")
    joints = {}
    for name in CHAIN_JOINTS:
        joints[name] = _joint(name, joints_node.node(name))
    extra = set(joints_node.keys()) - set(CHAIN_JOINTS)
    if extra:
        raise joints_node.fail(sorted(extra)[0], "unknown joint (the chain is " + ", ".join(CHAIN_JOINTS) + ")")
    listed = root.raw("control_joints")
    if not isinstance(listed, list) or len(listed) != len(CONTROL_JOINTS):
        raise ParameterError(f"{source}: control_joints: expected a list of {len(CONTROL_JOINTS)} joints")
    limits = {}
    for i, (entry, expected) in enumerate(zip(listed, CONTROL_JOINTS)):
        node = Node(entry, f"control_joints[{i}]", source)
        if node.text("name") != expected:
            raise node.fail("name", f"expected {expected!r} at index {i}, got {node.text('name')!r}")
        lo, hi = node.num("min"), node.num("max")
        if lo >= hi:
            raise node.fail("min", f"must be below max ({lo} >= {hi})")
        limits[expected] = (lo, hi)
    # The virtual eye joints must be reachable by the physical pan joints.
    vs, vg = limits["eyes_version"], limits["eyes_vergence"]
    for side in ("left_eye_pan", "right_eye_pan"):
        j = joints[side]
        need = max(abs(vs[0]) + vg[1] / 2, abs(vs[1]) + vg[1] / 2)
        if need > min(-j.lower, j.upper) + 1e-9:
            raise ParameterError(f"{source}: joints.{side}: range {j.lower}..{j.upper} cannot reach "
                                 f"version {vs} with vergence {vg} (needs +-{need})")
    for name in ("neck_pitch", "neck_roll", "neck_yaw", "eyes_tilt"):
        if limits[name] != (joints[name].lower, joints[name].upper):
            raise ParameterError(f"{source}: control_joints.{name}: limits {limits[name]} differ from "
                                 f"joints.{name} ({joints[name].lower}, {joints[name].upper})")
    _check_purchased(root)
    _check_drives(root)
    cams = root.node("cameras")
    if not root.node("purchased").has(cams.text("model")):
        raise cams.fail("model", f"{cams.text('model')!r} is not listed under purchased")
    half = cams.num("baseline", positive=True) / 2
    if abs(joints["left_eye_pan"].origin[1] - half) > 1e-9 or abs(joints["right_eye_pan"].origin[1] + half) > 1e-9:
        raise ParameterError(f"{source}: joints.left_eye_pan.origin/right_eye_pan.origin: eyes must sit at "
                             f"y = +-baseline/2 = +-{half}")
    for key in root.node("materials").keys():
        root.node("materials").num(key, positive=True)
    return HeadParameters(path, root, joints, limits)


def load(path: Path | str | None = None) -> HeadParameters:
    path = Path(path) if path else DEFAULT_PATH
    try:
        text = path.read_text(encoding="utf-8")
    except OSError as exc:
        raise ParameterError(f"{path}: cannot read: {exc.strerror}") from None
    try:
        data = strict_yaml.load(text)
    except yaml.MarkedYAMLError as exc:
        mark = exc.problem_mark
        where = f"{mark.line + 1}:{mark.column + 1}" if mark else "?"
        raise ParameterError(f"{path}:{where}: YAML error: {exc.problem}") from None
    return parse(data, str(path), path)
