# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: CERN-OHL-S-2.0
"""The eyes' angular error budget for stereo, and what the eye-pan drives leave against it.

Two cameras a baseline B apart, verged on a point at distance Z, see it under the vergence angle g = 2 atan(B / 2Z);
an error dg in vergence moves the fixated depth by dZ = (Z^2 + B^2/4) / B x dg. The budget (eye_accuracy in the
parameter file) allows a depth error at a distance; it gives the vergence error allowed, and half of it per eye
(the two eyes' errors may add, in opposite directions). Version (the common gaze direction) carries one eye's error.

Each pan's error is the sum of its terms (eye_error_terms.py). The budget assumes each eye is calibrated against the
cameras after assembly (docs/fabricate.md, "Eyes for stereo"), so it counts only the terms that are not repeatable;
the repeatable ones are reported beside them, with what the eye would err uncalibrated. A non-repeatable term the
maker does not publish leaves the budget unshown: the drive does not meet it until the number is known."""
from __future__ import annotations

import json
import math
from dataclasses import asdict, dataclass

from robogene_head_model.params import HeadParameters

from .eye_error_terms import Term, terms

PANS = ("left_eye_pan", "right_eye_pan")


class EyeAccuracyError(RuntimeError):
    """The eye-pan drives miss the stereo budget; the message is the report."""


@dataclass(frozen=True)
class EyeBudget:
    distance_mm: float
    depth_error_mm: float             # allowed
    vergence_allowed_deg: float
    per_eye_allowed_deg: float
    joint: str                        # the pan with the larger error
    terms: tuple[Term, ...]
    depth_per_rad: float              # mm of depth per radian of vergence at distance_mm

    def _sum(self, repeatable: bool | None) -> float | None:
        picked = [t for t in self.terms if repeatable is None or t.repeatable == repeatable]
        return None if any(t.deg is None for t in picked) else sum(t.deg for t in picked)

    @property
    def unknown(self) -> list[str]:
        return [t.name for t in self.terms if t.deg is None and not t.repeatable]

    @property
    def per_eye_deg(self) -> float | None:
        """What the budget counts: the non-repeatable terms, None while one is unknown."""
        return self._sum(False)

    @property
    def known_per_eye_deg(self) -> float:
        """The known non-repeatable terms: a lower bound while some are unknown."""
        return sum(t.deg for t in self.terms if not t.repeatable and t.deg is not None)

    @property
    def uncalibrated_deg(self) -> float | None:
        return self._sum(None)

    @property
    def vergence_deg(self) -> float:
        return 2 * self.known_per_eye_deg

    @property
    def depth_mm(self) -> float:
        return self.depth_per_rad * math.radians(self.vergence_deg)

    @property
    def ok(self) -> bool:
        return self.per_eye_deg is not None and self.per_eye_deg <= self.per_eye_allowed_deg


def depth_per_vergence(baseline: float, distance: float) -> float:
    """mm of depth per radian of vergence at a fixation distance (both mm)."""
    return (distance ** 2 + baseline ** 2 / 4) / baseline


def budget(params: HeadParameters, dynamic_Nm: dict[str, float]) -> EyeBudget:
    """dynamic_Nm: per pan, the peak torque its gearhead passes to the eye (drive sizing's load)."""
    node = params.root.node("eye_accuracy")
    z, allowed = node.num("distance", positive=True), node.num("depth_error", positive=True)
    per_rad = depth_per_vergence(params.baseline, z)
    vergence_allowed = math.degrees(allowed / per_rad)
    found = {j: tuple(terms(params, j, dynamic_Nm[j])) for j in PANS}

    def worst(j: str) -> tuple[bool, float]:
        e = EyeBudget(z, allowed, vergence_allowed, vergence_allowed / 2, j, found[j], per_rad)
        return e.per_eye_deg is None, e.known_per_eye_deg
    joint = max(PANS, key=worst)
    return EyeBudget(z, allowed, vergence_allowed, vergence_allowed / 2, joint, found[joint], per_rad)


def _deg(value: float | None) -> str:
    return "not published" if value is None else f"{value:.4f}"


def format_report(e: EyeBudget) -> str:
    name = max(len("term"), *(len(t.name) for t in e.terms))     # the longest term name sets the column
    lines = [f"Eye accuracy at {e.distance_mm:g} mm: allowed depth error {e.depth_error_mm:g} mm -> vergence error "
             f"{e.vergence_allowed_deg:.4f} deg, {e.per_eye_allowed_deg:.4f} deg per eye (after a per-eye calibration: "
             f"only what is not repeatable counts).",
             f"Terms per eye at the joint, {e.joint} (the larger):",
             f"  {'term':<{name}} {'deg':>13}  {'':<14}  what (source)"]
    for t in e.terms:
        kind = "calibrated" if t.repeatable else "counted"
        lines.append(f"  {t.name:<{name}} {_deg(t.deg):>13}  {kind:<14}  {t.what} ({t.source})")
    if e.per_eye_deg is None:
        lines.append(f"Counted per eye: at least {e.known_per_eye_deg:.4f} deg; unknown: {', '.join(e.unknown)}.")
    else:
        lines.append(f"Counted per eye: {e.per_eye_deg:.4f} deg; uncalibrated the eye would err "
                     f"{_deg(e.uncalibrated_deg)} deg.")
    at_least = "at least " if e.per_eye_deg is None else ""
    verdict = "meets it" if e.ok else "does NOT meet it"
    lines.append(f"Vergence error {at_least}{e.vergence_deg:.4f} deg, depth error {at_least}{e.depth_mm:.1f} mm at "
                 f"{e.distance_mm:g} mm (allowed {e.depth_error_mm:g}): the drive {verdict}.")
    return "\n".join(lines)


def enforce(e: EyeBudget) -> None:
    if not e.ok:
        raise EyeAccuracyError("the eye-pan drives miss the stereo budget (eye_accuracy):\n" + format_report(e))


def dumps(e: EyeBudget) -> str:
    data = asdict(e)
    data.update(ok=e.ok, unknown=e.unknown, per_eye_deg=e.per_eye_deg, known_per_eye_deg=e.known_per_eye_deg,
                uncalibrated_deg=e.uncalibrated_deg, vergence_deg=e.vergence_deg, depth_mm=e.depth_mm)
    return json.dumps(data, indent=1)
