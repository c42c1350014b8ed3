# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: CERN-OHL-S-2.0
"""How much torque each kind of shaft-hub connection and belt stage can pass: the element library of the torque-path
check (torque_path.py). Every function returns N m; lengths are mm, stresses MPa (N/mm^2).

The models, each the usual machine-design estimate, conservative where a choice was needed:
  plain      a round shaft in a round bore (slide or transition fit): no element passes torque, so 0. The friction of
             a slide fit is not a design torque.
  bonded     a retaining compound in the gap: shear strength x the bonded area (pi d L) x d/2.
  set_screw  n set screws bearing on the shaft: n x the screw's axial holding force (the maker's table, cup point at
             its seating torque) x d/2.
  d_flat     flats on the shaft in a matching D bore: turning the shaft presses each flat into the bore's flat with a
             pressure rising linearly from the flat's middle to its edge, so per flat T = p L w^2 / 12, w the flat's
             width (2 sqrt(r^2 - (r - t)^2), t its depth), p the allowable pressure on the softer part.
  clamp      a split hub clamped by n screws, each at its assembly preload F_M (VDI 2230: 90 % of the yield stress at
             the thread's stress section under tension and thread torque): T = mu n F_M d (each screw presses both
             half-shells on the shaft; the friction acts at d/2 on both).
  belt       a trapezoidal timing belt stage, rated by ANSI/RMA IP-24 (ISO 5295, 5296, 5299; IS 9804) at its small
             pulley, d the pulley's pitch diameter in inches, Kz by the teeth in mesh on it:
               MXL        a torque rating, Qr = Kz d (a - b d^2) lbf in, (a, b) by belt width;
               XL, L      a power rating at the profile's base width, HP = Kz d (r/1000) (a - b (d r/1000)^2), r the
                          faster shaft's rpm; as a torque, T = 63025 HP / r = 63.025 Kz d (a - b (d r/1000)^2) lbf in.
             The secondary sources print the speed term as (d r)^2; read with r in rpm it makes every rating negative
             above about 36 rpm on a one-inch pulley, so r is in thousands of rpm there as in the first factor (the
             reading that keeps the rating positive up to the standard's own limit of 6500 ft/min)."""
from __future__ import annotations

import math

N_PER_LBF = 4.4482216
MM_PER_IN = 25.4

# ISO 898-1 / ISO 3506-1: lower yield stress Rp0.2 (MPa) by property class, for the clamp screws' preload.
YIELD_MPA = {"8.8": 640.0, "10.9": 940.0, "12.9": 1100.0, "A2-70": 450.0, "A4-80": 600.0}

# ISO 261 coarse pitches (mm), as in threads.py.
COARSE_PITCH = {1.6: 0.35, 2.0: 0.4, 2.5: 0.45, 3.0: 0.5, 4.0: 0.7, 5.0: 0.8, 6.0: 1.0, 8.0: 1.25}

# ANSI/RMA IP-24, ISO 5299: MXL torque rating coefficients (a, b) by belt width in inches, and the factor Kz by the
# teeth in mesh on the small pulley (six or more: 1).
MXL_RATING = {0.12: (1.13, 1.38e-3), 0.19: (1.88, 2.30e-3), 0.25: (2.63, 3.21e-3)}
MXL_TEETH_IN_MESH = {6: 1.0, 5: 0.8, 4: 0.6, 3: 0.4, 2: 0.2}

# ANSI/RMA IP-24, ISO 5296: pitch (mm) of the trapezoidal profiles this library rates; for the power-rated ones the
# base width (in) the rating holds at and the coefficients (a, b) above. IP-24 gives no factor for other widths here,
# so a belt of any other width is refused rather than scaled.
BELT_PITCH_MM = {"MXL": 2.032, "XL": 5.08, "L": 9.525}
POWER_RATING = {"XL": (0.38, 0.0916, 7.07e-5), "L": (1.00, 0.436, 3.01e-4)}
MAX_SURFACE_SPEED_FPM = 6500.0   # IP-24: the ratings hold up to this pulley surface speed

VDI_UTILISATION = 0.9   # VDI 2230: a screw is tightened to 90 % of its yield under tension and thread torque


class ElementError(ValueError):
    """Numbers no model of this library covers; the caller names the parameter (`field`, where the error is about
    one of the belt's own fields: its profile or width)."""

    def __init__(self, message: str, field: str = ""):
        super().__init__(message)
        self.field = field


def plain() -> float:
    return 0.0


def bonded(shaft: float, length: float, shear_strength: float) -> float:
    return shear_strength * math.pi * shaft * length * shaft / 2 / 1000.0


def set_screws(count: int, holding_force_n: float, shaft: float) -> float:
    return count * holding_force_n * shaft / 2 / 1000.0


def flat_width(shaft: float, depth: float) -> float:
    r = shaft / 2
    if not 0 < depth < r:
        raise ElementError(f"a flat {depth:g} deep on a {shaft:g} mm shaft")
    return 2 * math.sqrt(r * r - (r - depth) ** 2)


def d_flat(shaft: float, depth: float, length: float, flats: int, pressure: float) -> float:
    w = flat_width(shaft, depth)
    return flats * pressure * length * w * w / 12 / 1000.0


def thread_pitch(diameter: float) -> float:
    if diameter not in COARSE_PITCH:
        raise ElementError(f"M{diameter:g} is not a coarse metric thread this library knows "
                           f"({', '.join(f'M{d:g}' for d in COARSE_PITCH)})")
    return COARSE_PITCH[diameter]


def preload(diameter: float, strength_class: str, thread_friction: float) -> float:
    """VDI 2230 assembly preload (N) of a coarse metric screw tightened to VDI_UTILISATION of its yield."""
    if strength_class not in YIELD_MPA:
        raise ElementError(f"property class {strength_class!r} (known: {', '.join(YIELD_MPA)})")
    p = thread_pitch(diameter)
    d2 = diameter - 0.649519 * p          # pitch diameter
    d3 = diameter - 1.226869 * p          # minor diameter of the screw
    d0 = (d2 + d3) / 2                    # stress section
    a0 = math.pi / 4 * d0 * d0
    torsion = 1.5 * d2 / d0 * (p / (math.pi * d2) + 1.155 * thread_friction)
    return a0 * VDI_UTILISATION * YIELD_MPA[strength_class] / math.sqrt(1 + 3 * torsion * torsion)


def clamp(shaft: float, count: int, screw_diameter: float, strength_class: str, thread_friction: float,
          friction: float) -> float:
    return friction * count * preload(screw_diameter, strength_class, thread_friction) * shaft / 1000.0


def teeth_in_mesh(small_teeth: int, small_pitch_d: float, large_pitch_d: float, centre: float) -> int:
    """Whole teeth of the small pulley inside the belt's wrap."""
    s = (large_pitch_d - small_pitch_d) / (2 * centre)
    if not -1 < s < 1:
        raise ElementError(f"pulleys of {small_pitch_d:g} and {large_pitch_d:g} mm cannot run {centre:g} mm apart")
    wrap = math.pi - 2 * math.asin(s)
    return math.floor(small_teeth * wrap / (2 * math.pi) + 1e-9)


def mesh_factor(in_mesh: int) -> float:
    """IP-24's Kz: the share of the rating a stage with this many teeth in mesh on its small pulley keeps."""
    return 1.0 if in_mesh >= 6 else MXL_TEETH_IN_MESH.get(in_mesh, 0.0)


def mxl_rating(small_pitch_d: float, belt_width: float, in_mesh: int) -> float:
    """N m at the small pulley."""
    width_in = belt_width / MM_PER_IN
    row = min(MXL_RATING, key=lambda w: abs(w - width_in))
    if abs(row - width_in) > 0.01:
        raise ElementError(f"a {belt_width:g} mm MXL belt: ISO 5299 rates 3.0, 4.8 and 6.4 mm (0.12, 0.19, 0.25 in)",
                           "width")
    a, b = MXL_RATING[row]
    d = small_pitch_d / MM_PER_IN
    return mesh_factor(in_mesh) * d * (a - b * d * d) * N_PER_LBF * MM_PER_IN / 1000.0


def power_rating(profile: str, small_pitch_d: float, belt_width: float, in_mesh: int, rpm: float) -> float:
    """N m at the small pulley of an XL or L stage whose faster shaft turns at rpm (its fastest, for a bound)."""
    if profile not in POWER_RATING:
        raise ElementError(f"{profile!r} has no power rating here (known: {', '.join(POWER_RATING)})", "profile")
    base, a, b = POWER_RATING[profile]
    if abs(belt_width / MM_PER_IN - base) > 0.01:
        raise ElementError(f"a {belt_width:g} mm {profile} belt: IP-24 rates {profile} at its base width, "
                           f"{base:g} in ({base * MM_PER_IN:.1f} mm), and this library knows no factor for others",
                           "width")
    if rpm < 0:
        raise ElementError(f"a negative speed, {rpm:g} rpm")
    d = small_pitch_d / MM_PER_IN
    if math.pi * d * rpm / 12 > MAX_SURFACE_SPEED_FPM:
        raise ElementError(f"a {small_pitch_d:g} mm pulley at {rpm:g} rpm runs faster than the {MAX_SURFACE_SPEED_FPM:g}"
                           f" ft/min the IP-24 ratings hold to")
    v = d * rpm / 1000
    lbf_in = 63.025 * mesh_factor(in_mesh) * d * (a - b * v * v)
    return lbf_in * N_PER_LBF * MM_PER_IN / 1000.0


def belt_rating(profile: str, small_pitch_d: float, belt_width: float, in_mesh: int, rpm: float) -> float:
    """N m at the small pulley, by the belt's profile: MXL's torque rating or the others' power rating."""
    if profile == "MXL":
        return mxl_rating(small_pitch_d, belt_width, in_mesh)
    if profile in POWER_RATING:
        return power_rating(profile, small_pitch_d, belt_width, in_mesh, rpm)
    raise ElementError(f"unknown belt profile {profile!r} (known: {', '.join(BELT_PITCH_MM)})", "profile")
