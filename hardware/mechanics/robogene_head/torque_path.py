# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: CERN-OHL-S-2.0
"""The torque path of every joint: how the drive's torque passes from its gearhead's output shaft to the link, element
by element (torque_paths: in the parameter file, as the CAD draws them), and whether each element carries the
drive's peak torque there, drive_sizing.margin times over (the element models: torque_elements.py).

The peak torque a drive can put through its elements is the larger of
  continuous  min(motor continuous torque x N x eta, gearhead continuous rating): what the drive sizing counts on
  current     kt x the board's current limit (motor_control.joints.<joint>.current_limit) x N x eta: what the drive
              delivers stalled against a stop or an obstacle, which the board allows. kt = U / omega0 from the motor's
              nominal voltage and no-load speed; the no-load current's voltage drop is left out, which errs high.
at the gearhead's output shaft (at: gearhead), times the belt stage after it (at: joint). An element that carries less
slips or breaks before the drive stalls. A clamp that is one hub of a purchased coupling (`coupling:`) carries the
smaller of what its screws' friction holds and the maker's rated torque of the coupling (rated_torque_Nm), where the
part has one: the rating also bounds the coupling's own body."""
from __future__ import annotations

import json
import math
from dataclasses import asdict, dataclass

from robogene_head_model import drive_limits
from robogene_head_model.params import CHAIN_JOINTS, HeadParameters, Node

from . import torque_elements
from .drive_sizing import required_margin

ELEMENTS = ("plain", "bonded", "set_screw", "d_flat", "clamp", "belt")


class TorquePathError(RuntimeError):
    """An element below the required margin; the message is the table."""


@dataclass(frozen=True)
class Peak:
    joint: str
    continuous_Nm: float        # at the gearhead's output shaft
    current_Nm: float
    kt_mNm_per_A: float
    current_limit_mA: float
    belt: float

    @property
    def at_gearhead(self) -> float:
        return max(self.continuous_Nm, self.current_Nm)

    @property
    def set_by(self) -> str:
        return "continuous rating" if self.continuous_Nm >= self.current_Nm else "current limit"


@dataclass(frozen=True)
class ElementCheck:
    joint: str
    index: int
    element: str
    what: str
    at: str                 # "gearhead" or "joint"
    capacity_Nm: float
    peak_Nm: float          # the drive's peak torque at the element
    margin: float           # capacity / peak
    rated_Nm: float | None = None   # the maker's rating of the coupling a clamp belongs to, where it has one


@dataclass(frozen=True)
class TorqueReport:
    required: float
    peaks: dict[str, Peak]
    elements: list[ElementCheck]

    def weakest(self, joint: str) -> ElementCheck:
        return min((e for e in self.elements if e.joint == joint), key=lambda e: e.margin)

    def failures(self) -> list[ElementCheck]:
        return [e for e in self.elements if e.margin < self.required]

    @property
    def ok(self) -> bool:
        return not self.failures()


def peak(params: HeadParameters, joint: str) -> Peak:
    drive = params.drive(joint)
    motor, gear = params.purchased(drive.text("motor")), params.purchased(drive.text("gearhead"))
    ratio = gear.num("ratio", positive=True)
    eta = gear.num("efficiency", positive=True, maximum=1.0)
    continuous = min(motor.num("continuous_torque_mNm", positive=True) * 1e-3 * ratio * eta,
                     gear.num("continuous_torque_Nm", positive=True))
    kt = drive_limits.torque_constant(params, drive.text("motor"))      # N m / A
    limit = drive_limits.current_limit(params, joint)
    current = kt * limit * 1e-3 * ratio * eta
    return Peak(joint, continuous, current, kt * 1e3, limit, drive_limits.belt_ratio(params, joint))


def _shaft(params: HeadParameters, joint: str, item: Node) -> float:
    value = item.raw("shaft")
    if value == "gearhead":
        return params.purchased(params.drive(joint).text("gearhead")).num("shaft_diameter", positive=True)
    return item.num("shaft", positive=True)


def _count(item: Node, key: str) -> int:
    value = item.num(key, positive=True)
    if value != int(value):
        raise item.fail(key, f"expected a whole number, got {value:g}")
    return int(value)


def _pitch_diameter(stage: Node, teeth: int) -> float:
    return teeth * stage.num("pitch", positive=True) / math.pi


def _belt_centre(params: HeadParameters, joint: str) -> float:
    """The belt stage's centre distance, as the CAD places the motor pulley (drive_limits.belt_centre)."""
    return drive_limits.belt_centre(params, joint)


def _belt(params: HeadParameters, joint: str, item: Node, at: str) -> float:
    """IP-24 rates the belt at its small pulley, at the speed of the faster shaft (here the motor pulley's at the
    gearhead's no-load speed, its fastest); the same tension gives torque in proportion to the pulley's diameter at
    the motor pulley (at: gearhead) and the joint pulley (at: joint). The belt's profile and width are the purchased
    stock's that the joint's stage names (geometry.pulleys.<yaw|tilt>.belt); its pitch must be the one the CAD draws
    the stage's pulleys with (.pitch)."""
    if joint not in drive_limits.BELTED:
        raise item.fail("element", f"{joint} has no belt stage")
    node = params.geometry("pulleys", drive_limits.BELTED[joint])
    key = node.text("belt")
    stock = params.purchased(key)
    profile = stock.text("profile")
    if profile not in torque_elements.BELT_PITCH_MM:
        raise stock.fail("profile", f"unknown belt profile {profile!r} (known: "
                                     f"{', '.join(torque_elements.BELT_PITCH_MM)})")
    pitch = node.num("pitch", positive=True)
    if abs(pitch - torque_elements.BELT_PITCH_MM[profile]) > 1e-6:
        raise node.fail("pitch", f"{pitch:g} mm is not the pitch of the {profile} belt {key} "
                                  f"({torque_elements.BELT_PITCH_MM[profile]:g} mm)")
    motor, joint_teeth = int(node.num("motor_teeth", positive=True)), int(node.num("joint_teeth", positive=True))
    d_motor, d_joint = _pitch_diameter(node, motor), _pitch_diameter(node, joint_teeth)
    small, d_small, d_large = min((motor, d_motor, d_joint), (joint_teeth, d_joint, d_motor))
    in_mesh = torque_elements.teeth_in_mesh(small, d_small, d_large, _belt_centre(params, joint))
    drive = params.drive(joint)
    rpm = (params.purchased(drive.text("motor")).num("no_load_speed_rpm", positive=True)
           / params.purchased(drive.text("gearhead")).num("ratio", positive=True) * max(1.0, d_motor / d_joint))
    try:
        rating = torque_elements.belt_rating(profile, d_small, stock.num("width", positive=True), in_mesh, rpm)
    except torque_elements.ElementError as exc:
        if exc.field:
            raise stock.fail(exc.field, str(exc)) from None
        raise
    return rating * (d_motor if at == "gearhead" else d_joint) / d_small


def _coupling_rating(params: HeadParameters, item: Node, shaft: float) -> float | None:
    """The rated torque (N m) of the purchased coupling a clamp element belongs to (`coupling:`), None where the
    element names none or the part has no rating. The clamp model gives what the screws' friction holds; a maker's
    rating also bounds what the coupling's body and its slit hubs take, so the element counts the smaller."""
    if not item.has("coupling"):
        return None
    key = item.text("coupling")
    part = params.purchased(key)
    if part.text("kind") != "coupling":
        raise item.fail("coupling", f"{key!r} is a {part.text('kind')}, expected a coupling")
    bores = part.raw("bores")
    if not isinstance(bores, list) or not bores or not all(
            isinstance(b, (int, float)) and not isinstance(b, bool) and b > 0 for b in bores):
        raise part.fail("bores", f"expected a list of bore diameters (mm), got {bores!r}")
    if not any(abs(b - shaft) < 1e-6 for b in bores):
        raise item.fail("coupling", f"{key!r} has bores {bores}, none for the element's {shaft:g} mm shaft")
    if not part.has("rated_torque_Nm"):
        return None
    return part.num("rated_torque_Nm", positive=True)


def capacity(params: HeadParameters, joint: str, item: Node, at: str) -> float:
    """N m the element passes, at its own place (the gearhead shaft or the joint)."""
    kind = item.text("element")
    try:
        if kind == "plain":
            _shaft(params, joint, item)
            return torque_elements.plain()
        if kind == "bonded":
            return torque_elements.bonded(_shaft(params, joint, item), item.num("length", positive=True),
                                          item.num("shear_strength_MPa", positive=True))
        if kind == "set_screw":
            screw = item.text("screw")
            entry = params.purchased(screw)
            if entry.text("kind") != "set_screw":
                raise item.fail("screw", f"{screw!r} is a {entry.text('kind')}, expected a set_screw")
            return torque_elements.set_screws(_count(item, "count"), entry.num("holding_force_N", positive=True),
                                              _shaft(params, joint, item))
        if kind == "d_flat":
            return torque_elements.d_flat(_shaft(params, joint, item), item.num("depth", positive=True),
                                          item.num("length", positive=True), _count(item, "flats"),
                                          item.num("pressure_MPa", positive=True))
        if kind == "clamp":
            shaft = _shaft(params, joint, item)
            held = torque_elements.clamp(shaft, _count(item, "count"), item.num("screw_diameter", positive=True),
                                         item.text("strength_class"), item.num("thread_friction", positive=True),
                                         item.num("friction", positive=True))
            rating = _coupling_rating(params, item, shaft)
            return held if rating is None else min(held, rating)
        if kind == "belt":
            return _belt(params, joint, item, at)
    except torque_elements.ElementError as exc:
        raise item.fail("element", str(exc)) from None
    raise item.fail("element", f"unknown element {kind!r}; known: {', '.join(ELEMENTS)}")


def analyse(params: HeadParameters) -> TorqueReport:
    paths = params.root.node("torque_paths")
    extra = sorted(set(paths.keys()) - set(CHAIN_JOINTS))
    if extra:
        raise paths.fail(extra[0], "not a chain joint (" + ", ".join(CHAIN_JOINTS) + ")")
    peaks, checks = {}, []
    for joint in CHAIN_JOINTS:
        listed = paths.raw(joint)
        if not isinstance(listed, list) or not listed:
            raise paths.fail(joint, "expected a list of the elements from the gearhead's output shaft to the link")
        p = peak(params, joint)
        peaks[joint] = p
        for i, entry in enumerate(listed):
            item = Node(entry, f"torque_paths.{joint}[{i}]", str(params.path))
            at = item.text("at")
            if at not in ("gearhead", "joint"):
                raise item.fail("at", f"expected gearhead or joint, got {at!r}")
            demand = p.at_gearhead * (p.belt if at == "joint" else 1.0)
            cap = capacity(params, joint, item, at)
            rated = _coupling_rating(params, item, _shaft(params, joint, item)) if item.text("element") == "clamp" \
                else None
            checks.append(ElementCheck(joint, i, item.text("element"), item.text("what"), at, cap, demand,
                                       cap / demand, rated))
    return TorqueReport(required_margin(params), peaks, checks)


def format_table(report: TorqueReport) -> str:
    lines = [f"Torque paths: each element against the drive's peak torque there, required margin {report.required:g}",
             "joint          element    at        capacity  peak    margin  what",
             "                                    (N m)     (N m)"]
    for e in report.elements:
        flag = "ok" if e.margin >= report.required else "TOO WEAK"
        rated = "" if e.rated_Nm is None else f" (the coupling's rating: {e.rated_Nm:g} N m)"
        lines.append(f"{e.joint:<14} {e.element:<10} {e.at:<8} {e.capacity_Nm:9.3f} {e.peak_Nm:7.3f} {e.margin:7.2f}  "
                     f"{e.what}{rated} [{flag}]")
    lines.append("")
    lines.append("Peak torque at the gearhead's output shaft: the larger of the continuous rating and the board's "
                 "current limit")
    for p in report.peaks.values():
        lines.append(f"{p.joint:<14} continuous {p.continuous_Nm:6.3f}  at {p.current_limit_mA:5.0f} mA "
                     f"(kt {p.kt_mNm_per_A:5.2f} mN m/A) {p.current_Nm:6.3f}  -> {p.at_gearhead:6.3f} N m "
                     f"({p.set_by}), belt stage {p.belt:.3f}")
    return "\n".join(lines)


def report_json(report: TorqueReport) -> dict:
    return {"required_margin": report.required, "ok": report.ok,
            "peaks": {j: dict(asdict(p), at_gearhead_Nm=p.at_gearhead, set_by=p.set_by)
                      for j, p in report.peaks.items()},
            "elements": [dict(asdict(e), ok=e.margin >= report.required) for e in report.elements],
            "weakest": {j: asdict(report.weakest(j)) for j in report.peaks}}


def enforce(report: TorqueReport) -> None:
    if not report.ok:
        names = ", ".join(f"{e.joint}[{e.index}] {e.element} ({e.capacity_Nm:.3f} of {e.peak_Nm:.3f} N m)"
                          for e in report.failures())
        raise TorquePathError(f"torque path elements below the required margin {report.required:g}: {names}\n"
                              + format_table(report))


def dumps(report: TorqueReport) -> str:
    return json.dumps(report_json(report), indent=1)
