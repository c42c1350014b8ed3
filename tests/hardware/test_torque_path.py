# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""The torque-path check: each element's capacity against closed-form and independent results, the drives' peak
torques against the drive limits and the motors' data, and the check refusing broken variants (a round shaft, an
undersized set screw, a clamp of weak screws) that a sound connection of the same joint passes."""
import json
import math

import pytest

from robogene_head import docs_sync, torque_elements, torque_path
from robogene_head_model import drive_limits
from robogene_head_model.params import ParameterError

from param_variants import edited

# A set screw for the variants. The holding force is the cup-point figure the inch tables give for the nearest size
# (#5: 200 lbf for M3, #2: 85 lbf for M2); what matters here is that the check uses it.
SET_SCREWS = {
    "iso4029-M3x4": {"kind": "set_screw", "diameter": 3, "length": 4, "holding_force_N": 890, "mass": 0.0002},
    "iso4029-M2x3": {"kind": "set_screw", "diameter": 2, "length": 3, "holding_force_N": 378, "mass": 0.0001},
}


def _variant(tmp_path, **paths):
    def edit(data):
        data["purchased"].update(SET_SCREWS)
        data["torque_paths"].update(paths)
    return edited(tmp_path, edit)


def _joint(report, joint):
    return [e for e in report.elements if e.joint == joint]


def test_a_flat_passes_what_its_linear_pressure_integrates_to():
    """Shaft 6, flat 0.5 deep: width 2 sqrt(3^2 - 2.5^2). The flat turns about the shaft axis, so the pressure rises
    linearly from its middle to its edge on the side that closes; integrated numerically, p(s) s ds over half the
    width, with the edge at the allowed pressure, gives the closed form per flat."""
    w = 2 * math.sqrt(9 - 6.25)
    assert torque_elements.flat_width(6, 0.5) == pytest.approx(w)
    p, length, n = 100.0, 12.0, 20000
    ds = (w / 2) / n
    integral = sum(p * ((i + 0.5) * ds) / (w / 2) * ((i + 0.5) * ds) * length * ds for i in range(n)) / 1000
    assert torque_elements.d_flat(6, 0.5, 12, 1, p) == pytest.approx(integral, rel=1e-6)
    assert torque_elements.d_flat(6, 0.5, 12, 2, p) == pytest.approx(2 * integral, rel=1e-6)
    with pytest.raises(torque_elements.ElementError):
        torque_elements.flat_width(6, 3)


def test_a_clamp_screw_is_preloaded_to_ninety_per_cent_of_its_yield():
    """The preload's tension and the thread torque's shear, combined by von Mises in the stress section, reach 90 %
    of the yield stress: computed here from the thread's torque M = F d2/2 (P / (pi d2) + 1.155 mu) over the section's
    fully plastic torsion modulus pi d^3/12, as VDI 2230 takes it."""
    for d, cls in ((3.0, "12.9"), (2.0, "A2-70"), (8.0, "8.8")):
        mu = 0.12
        f = torque_elements.preload(d, cls, mu)
        p = torque_elements.COARSE_PITCH[d]
        d2, d3 = d - 0.649519 * p, d - 1.226869 * p
        ds = (d2 + d3) / 2
        sigma = f / (math.pi / 4 * ds ** 2)
        tau = f * d2 / 2 * (p / (math.pi * d2) + 1.155 * mu) / (math.pi / 12 * ds ** 3)
        assert math.sqrt(sigma ** 2 + 3 * tau ** 2) == pytest.approx(0.9 * torque_elements.YIELD_MPA[cls], rel=1e-9)
    # two screws, friction 0.15, on a 6 mm shaft: mu n F d
    assert torque_elements.clamp(6, 2, 3.0, "12.9", 0.12, 0.15) == pytest.approx(
        0.15 * 2 * torque_elements.preload(3.0, "12.9", 0.12) * 6 / 1000)
    with pytest.raises(torque_elements.ElementError, match="property class"):
        torque_elements.preload(3.0, "9.9", 0.12)
    with pytest.raises(torque_elements.ElementError, match="M7"):
        torque_elements.preload(7.0, "8.8", 0.12)


def test_mxl_rating_follows_iso_5299():
    """A 1/4 in belt on a 1 in pitch diameter pulley, six teeth in mesh: Qr = 1 x (2.63 - 3.21e-3) lbf in; five teeth
    in mesh take 0.8 of it, one tooth none."""
    full = (2.63 - 3.21e-3) * 4.4482216 * 0.0254
    assert torque_elements.mxl_rating(25.4, 6.4, 6) == pytest.approx(full)
    assert torque_elements.mxl_rating(25.4, 6.4, 9) == pytest.approx(full)
    assert torque_elements.mxl_rating(25.4, 6.4, 5) == pytest.approx(0.8 * full)
    assert torque_elements.mxl_rating(25.4, 6.4, 1) == 0
    with pytest.raises(torque_elements.ElementError, match="ISO 5299"):
        torque_elements.mxl_rating(25.4, 10, 6)
    # equal pulleys: the belt wraps half of each
    assert torque_elements.teeth_in_mesh(20, 12.9, 12.9, 40) == 10


LBF_IN = 4.4482216 * 0.0254   # N m


def test_xl_and_l_ratings_follow_ip24():
    """IP-24's power rating as a torque, T = 63025 HP / r: on a 1 in pitch diameter pulley at 1000 rpm an XL 037 belt
    passes 63.025 (0.0916 - 7.07e-5) lbf in, an L 100 belt 63.025 (0.436 - 3.01e-4); stalled, 63.025 x 0.0916 and
    63.025 x 0.436 (about 0.65 N m per inch of pitch diameter for XL). Five teeth in mesh keep 0.8 of it."""
    xl = 63.025 * (0.0916 - 7.07e-5) * LBF_IN
    assert torque_elements.belt_rating("XL", 25.4, 9.525, 6, 1000) == pytest.approx(xl)
    assert torque_elements.belt_rating("XL", 25.4, 9.525, 5, 1000) == pytest.approx(0.8 * xl)
    assert torque_elements.belt_rating("XL", 25.4, 9.525, 7, 0) == pytest.approx(63.025 * 0.0916 * LBF_IN)
    assert torque_elements.belt_rating("XL", 25.4, 9.525, 7, 0) == pytest.approx(0.652, abs=1e-3)
    assert torque_elements.belt_rating("L", 25.4, 25.4, 6, 1000) == pytest.approx(63.025 * (0.436 - 3.01e-4) * LBF_IN)
    # twice the pitch diameter at half the speed: the same belt speed, twice the torque
    assert torque_elements.belt_rating("XL", 50.8, 9.525, 6, 500) == pytest.approx(2 * xl)
    # MXL keeps its own torque rating, whatever the speed
    assert torque_elements.belt_rating("MXL", 25.4, 6.4, 6, 5000) == torque_elements.mxl_rating(25.4, 6.4, 6)


def test_the_speed_term_is_in_thousands_of_rpm():
    """The secondary sources print the speed term as (d r)^2. Read with r in rpm, a 1 in XL pulley's rating turns
    negative above 36 rpm; with r in thousands it stays positive up to the standard's own 6500 ft/min (d r = 24828),
    where it has lost 7.07e-5 x 24.8^2 / 0.0916 = 48 % of its stalled value. Beyond that speed the rating is refused."""
    rpm = 6500 * 12 / math.pi - 1
    at_limit = torque_elements.belt_rating("XL", 25.4, 9.525, 6, rpm)
    stalled = torque_elements.belt_rating("XL", 25.4, 9.525, 6, 0)
    assert 0 < at_limit < stalled
    assert at_limit / stalled == pytest.approx(1 - 7.07e-5 * (rpm / 1000) ** 2 / 0.0916)
    assert torque_elements.belt_rating("XL", 25.4, 9.525, 6, 40) > 0.99 * stalled
    with pytest.raises(torque_elements.ElementError, match="6500 ft/min"):
        torque_elements.belt_rating("XL", 25.4, 9.525, 6, rpm + 2)


@pytest.mark.parametrize("profile, width, field", [("T5", 10, "profile"), ("GT2", 6, "profile"), ("XL", 6.4, "width"),
                                                    ("L", 12.7, "width"), ("MXL", 9.525, "width")])
def test_a_belt_the_standard_does_not_rate_is_refused_by_its_field(profile, width, field):
    with pytest.raises(torque_elements.ElementError) as error:
        torque_elements.belt_rating(profile, 25.4, width, 6, 100)
    assert error.value.field == field


def _xl_stage(data, belt="xl-belt-037", width=9.525, profile="XL", pitch=5.08, yaw=(14, 20), tilt=(14, 24),
              yaw_limit=550):
    """The yaw and tilt stages re-rated on another belt stock (a check of the ratings only: the CAD is not rebuilt)."""
    data["purchased"][belt] = {"kind": "belt", "profile": profile, "width": width, "thickness": 2.3,
                               "tooth_height": 1.27, "mass_per_metre": 0.03}
    pulleys = data["geometry"]["pulleys"]
    pulleys["yaw"].update(motor_teeth=yaw[0], joint_teeth=yaw[1], belt=belt, pitch=pitch)
    pulleys["tilt"].update(motor_teeth=tilt[0], joint_teeth=tilt[1], belt=belt, pitch=pitch)
    data["motor_control"]["joints"]["neck_yaw"]["current_limit"] = yaw_limit


def test_the_belt_is_rated_by_its_profile(tmp_path):
    """On the same 14-tooth motor pulley at the same peak, an XL 037 belt passes where an MXL belt fails: IP-24
    dispatches on the belt stock's profile. The yaw stage at a 550 mA limit: peak 0.373 N m at the gearhead, XL 14T
    rated 63.025 x 0.891 in x 0.0916 lbf in (six teeth in mesh, the speed term negligible at 118 rpm)."""
    xl = torque_path.analyse(edited(tmp_path, _xl_stage))
    belt = [e for e in _joint(xl, "neck_yaw") if e.element == "belt"][0]
    d = 14 * 5.08 / math.pi / 25.4
    assert belt.capacity_Nm == pytest.approx(63.025 * d * (0.0916 - 7.07e-5 * (d * 7800 / 66 / 1000) ** 2) * LBF_IN)
    assert belt.margin == pytest.approx(1.56, abs=0.005) and belt.margin >= xl.required
    # the tilt stage (docs/fabricate.md, "Torque paths"): the same 14T pulley, its peak the 620 mA limit's 0.261 N m
    tilt = [e for e in _joint(xl, "eyes_tilt") if e.element == "belt"][0]
    assert tilt.capacity_Nm == pytest.approx(belt.capacity_Nm, rel=1e-4) and tilt.margin == pytest.approx(2.23, abs=0.005)
    mxl = torque_path.analyse(edited(tmp_path, lambda data: _xl_stage(data, width=6.4, profile="MXL", pitch=2.032)))
    assert [e for e in _joint(mxl, "neck_yaw") if e.element == "belt"][0] in mxl.failures()


@pytest.mark.parametrize("edit, where", [
    (lambda data: _xl_stage(data, profile="T5"), r"purchased\.xl-belt-037\.profile: unknown belt profile 'T5'"),
    (lambda data: _xl_stage(data, width=6.35), r"purchased\.xl-belt-037\.width: a 6\.35 mm XL belt"),
    (lambda data: _xl_stage(data, pitch=2.032), r"geometry\.pulleys\.yaw\.pitch: 2\.032 mm is not the pitch of the XL"),
    (lambda data: data["purchased"]["xl-belt-037"].pop("profile"), r"purchased\.xl-belt-037\.profile: missing"),
])
def test_a_belt_the_check_cannot_rate_is_named(tmp_path, edit, where):
    with pytest.raises(ParameterError, match=where):
        torque_path.analyse(edited(tmp_path, edit))


def test_the_drive_peak_is_its_continuous_rating_or_what_the_current_limit_allows(params):
    """The continuous part is the drive limit at the gearhead shaft; the current part is kt x I x N x eta with kt from
    the motor's speed constant (rpm per volt): 30000 / (pi kn) mN m/A."""
    for joint in ("neck_pitch", "neck_roll", "neck_yaw", "eyes_tilt", "left_eye_pan"):
        peak = torque_path.peak(params, joint)
        limit = drive_limits.limit(params, joint)
        assert peak.continuous_Nm == pytest.approx(limit.rated / limit.belt)
        drive = params.drive(joint)
        motor, gear = params.purchased(drive.text("motor")), params.purchased(drive.text("gearhead"))
        kn = motor.num("no_load_speed_rpm") / motor.num("voltage")
        assert peak.kt_mNm_per_A == pytest.approx(30000 / (math.pi * kn))
        amps = params.root.node("motor_control").node("joints").node(
            "eyes_version" if joint == "left_eye_pan" else joint).num("current_limit") / 1000
        assert peak.current_Nm == pytest.approx(30 / (math.pi * kn) * amps * gear.num("ratio") * gear.num("efficiency"))
        assert peak.at_gearhead == max(peak.continuous_Nm, peak.current_Nm)


def test_every_element_passes(params):
    """Every element passes: pitch and roll have their set screws (test_drive_hubs.py), the joint pulleys theirs
    (test_joint_pulley_hubs.py), the yaw and tilt stages their jackshafts, couplings and XL belts
    (test_yaw_jackshaft.py, test_tilt_jackshaft.py), the eye pans their hubs: two M2 set screws hold
    2 x 378 N x 1.5 mm, the hub's two flats in the printed pocket 2 x 15 MPa x 3 mm x w^2 / 12
    (w = 2 sqrt(6^2 - 4^2)), against the 0.162 N m the current limit allows. So the build enforces them (fab.py);
    the yaw stage on its old MXL belt fails, and only there."""
    report = torque_path.analyse(params)
    for joint in ("left_eye_pan", "right_eye_pan"):
        screws, flats = _joint(report, joint)
        assert screws.capacity_Nm == pytest.approx(2 * 378 * 1.5 / 1000)
        assert flats.capacity_Nm == pytest.approx(2 * 15 * 3 * (4 * (36 - 16)) / 12 / 1000)
        assert report.weakest(joint) is flats and flats.margin >= report.required
    assert report.failures() == [] and report.ok
    torque_path.enforce(report)


def test_the_yaw_stage_on_mxl_stock_fails_alone(tmp_path):
    mxl = edited(tmp_path, lambda data: data["geometry"]["pulleys"]["yaw"].update(
        belt="mxl-belt-6mm", pitch=2.032, width=8, flange_thickness=0.6))
    report = torque_path.analyse(mxl)
    assert [(e.joint, e.element) for e in report.failures()] == [("neck_yaw", "belt")]
    assert report.failures()[0].margin < 1
    with pytest.raises(torque_path.TorquePathError, match=r"neck_yaw\[3\] belt") as raised:
        torque_path.enforce(report)
    assert "eyes_tilt[" not in str(raised.value).splitlines()[0]


SOUND_CLAMP = {"element": "clamp", "at": "gearhead", "shaft": "gearhead", "count": 2, "screw_diameter": 3,
               "strength_class": "12.9", "thread_friction": 0.12, "friction": 0.15, "what": "split hub, 2 x M3 12.9"}


def test_a_round_shaft_fails_where_a_clamp_hub_passes(tmp_path):
    """Pitch's peak is 3.23 N m (its continuous rating): two M3 12.9 clamp screws carry 7.7 N m; the round shaft in a
    round bore, as drawn today, nothing."""
    sound = torque_path.analyse(_variant(tmp_path, neck_pitch=[SOUND_CLAMP]))
    (clamp,) = _joint(sound, "neck_pitch")
    assert clamp.margin >= sound.required and clamp not in sound.failures()
    weak_screws = dict(SOUND_CLAMP, strength_class="A2-70", count=1)
    weak = torque_path.analyse(_variant(tmp_path, neck_pitch=[weak_screws]))
    assert [e.joint for e in weak.failures()].count("neck_pitch") == 1
    round_shaft = torque_path.analyse(_variant(tmp_path, neck_pitch=[
        {"element": "plain", "at": "gearhead", "shaft": "gearhead", "length": 12, "what": "round"}]))
    assert _joint(round_shaft, "neck_pitch")[0] in round_shaft.failures()


def test_an_undersized_set_screw_fails(tmp_path):
    """Two M3 set screws on the 6 mm pitch shaft hold 2 x 890 N x 3 mm = 5.3 N m against 1.5 x 3.23; two M2 hold
    2.3 N m and fail, and so does a D bore too short for the pressure the aluminium takes."""
    screws = {"element": "set_screw", "at": "gearhead", "shaft": "gearhead", "count": 2, "what": "2 set screws"}
    good = torque_path.analyse(_variant(tmp_path, neck_pitch=[dict(screws, screw="iso4029-M3x4")]))
    assert not [e for e in good.failures() if e.joint == "neck_pitch"]
    assert _joint(good, "neck_pitch")[0].capacity_Nm == pytest.approx(2 * 890 * 3 / 1000)
    small = torque_path.analyse(_variant(tmp_path, neck_pitch=[dict(screws, screw="iso4029-M2x3")]))
    assert [e.joint for e in small.failures()].count("neck_pitch") == 1
    with pytest.raises(torque_path.TorquePathError, match=r"neck_pitch\[0\] set_screw"):
        torque_path.enforce(small)
    flat = {"element": "d_flat", "at": "gearhead", "shaft": "gearhead", "depth": 0.5, "flats": 1, "length": 12,
            "pressure_MPa": 125, "what": "one flat"}
    assert [e.joint for e in torque_path.analyse(_variant(tmp_path, neck_pitch=[flat])).failures()].count(
        "neck_pitch") == 1


def test_a_belt_counts_at_the_pulley_it_is_declared_on(tmp_path, params):
    """The same belt tension: at the joint pulley its torque is the belt stage's ratio times the motor pulley's."""
    at_motor = [e for e in torque_path.analyse(params).elements if e.joint == "neck_yaw" and e.element == "belt"][0]
    moved = _variant(tmp_path, neck_yaw=[{"element": "belt", "at": "joint", "what": "belt"}])
    at_joint = _joint(torque_path.analyse(moved), "neck_yaw")[0]
    assert at_joint.capacity_Nm == pytest.approx(at_motor.capacity_Nm * 20 / 14)
    assert at_joint.margin == pytest.approx(at_motor.margin)


@pytest.mark.parametrize("paths, where", [
    ({"neck_pitch": [{"element": "weld", "at": "gearhead", "what": "?"}]}, r"torque_paths\.neck_pitch\[0\]\.element"),
    ({"neck_pitch": [dict(SOUND_CLAMP, at="motor")]}, r"torque_paths\.neck_pitch\[0\]\.at"),
    ({"neck_pitch": [{"element": "belt", "at": "gearhead", "what": "?"}]}, r"neck_pitch has no belt stage"),
    ({"neck_pitch": []}, r"torque_paths\.neck_pitch: expected a list"),
    ({"neck_pitch": [dict(SOUND_CLAMP, count=1.5)]}, r"torque_paths\.neck_pitch\[0\]\.count"),
    ({"neck_pitch": [dict(SOUND_CLAMP, strength_class="9.9")]}, r"torque_paths\.neck_pitch\[0\]\.element: property"),
    ({"neck_pitch": [dict(SOUND_CLAMP, element="set_screw", screw="iso7380-M3x8")]},
     r"torque_paths\.neck_pitch\[0\]\.screw: 'iso7380-M3x8' is a screw"),
    ({"neck_pich": [SOUND_CLAMP]}, r"torque_paths\.neck_pich: not a chain joint"),
])
def test_a_wrong_torque_path_is_named(tmp_path, paths, where):
    with pytest.raises(ParameterError, match=where):
        torque_path.analyse(_variant(tmp_path, **paths))


def test_the_package_reports_the_torque_paths(fab, params):
    data = json.loads((fab / "reports" / "torque-path.json").read_text())
    fresh = torque_path.report_json(torque_path.analyse(params))
    assert data == json.loads(json.dumps(fresh))
    assert data["ok"]
    text = (fab / "reports" / "torque-path.txt").read_text()
    assert "TOO WEAK" not in text and "neck_pitch" in text


def test_each_belt_stage_is_rated_on_its_own_belt_stock(params):
    """The stages name their belts apart (geometry.pulleys.<yaw|tilt>.belt): the tilt stage on XL 037 stock, 14T to
    24T, passes (margin 2.23 at the 620 mA limit), and so does the yaw stage on the same stock, 14T to 20T (1.56 at
    550 mA); the yaw stage alone back on MXL stock fails, the tilt's belt unchanged."""
    report = torque_path.analyse(params)
    belts = {e.joint: e for e in report.elements if e.element == "belt"}
    assert belts["eyes_tilt"].margin == pytest.approx(2.23, abs=0.005) and belts["eyes_tilt"] not in report.failures()
    assert belts["neck_yaw"].margin == pytest.approx(1.56, abs=0.005) and belts["neck_yaw"] not in report.failures()


BOUGHT = "catalogue-coupling-16-3-6"


def _tilt_coupling(tmp_path, **fields):
    """The parameter file with the tilt's coupling bought instead of made: a catalogue entry of the made one's outline
    and screws carrying `fields` (a maker's rating, other bores), which the jackshaft draws and the clamps name."""
    def edit(data):
        made = data["geometry"]["tilt_jackshaft"]["coupling"]
        outline = {k: made[k] for k in ("diameter", "length", "bores", "screw", "offset", "seat")}
        data["purchased"][BOUGHT] = dict(outline, kind="coupling", mass=0.007, **fields)
        data["geometry"]["tilt_jackshaft"]["coupling"] = BOUGHT
        for element in data["torque_paths"]["eyes_tilt"]:
            if element["element"] == "clamp":
                element["coupling"] = BOUGHT
    return edited(tmp_path, edit)


def _tilt_clamps(report):
    return [e for e in report.elements if e.joint == "eyes_tilt" and e.element == "clamp"]


def test_the_made_couplings_are_held_by_their_clamps_alone(params):
    """The couplings are made here (geometry.<stage>.coupling is their own parameters): no clamp element names a
    catalogue coupling, and none carries a maker's rating, the clamp model's figures are theirs."""
    for stage, joint in (("tilt_jackshaft", "eyes_tilt"), ("yaw_jackshaft", "neck_yaw")):
        assert isinstance(params.root.node("geometry").node(stage).raw("coupling"), dict)
        clamps = [e for e in params.root.node("torque_paths").raw(joint) if e["element"] == "clamp"]
        assert len(clamps) == 2 and all("coupling" not in e for e in clamps)
    report = torque_path.analyse(params)
    assert all(e.rated_Nm is None for e in report.elements if e.element == "clamp")


def test_a_bought_coupling_is_drawn_as_the_catalogue_part_the_clamps_name(tmp_path):
    """Swapping in a catalogue coupling: the jackshaft draws the purchased part (no drawing, no fits of its own) and
    the torque path counts its rating."""
    from robogene_head.parts import tilt_jackshaft
    variant = _tilt_coupling(tmp_path, rated_torque_Nm=50)
    coupling = next(p for p in tilt_jackshaft.build(variant) if p.name == "eyes_tilt_coupling")
    assert (coupling.kind, coupling.design, coupling.clamp_bores) == ("purchased", BOUGHT, ())
    assert all(e.rated_Nm == 50 for e in _tilt_clamps(torque_path.analyse(variant)))


def test_a_coupling_rated_below_the_drive_fails_where_its_clamps_hold(tmp_path):
    """The clamp model lets the coupling's screws hold the tilt's peak with margin; a coupling its maker rates below
    1.5 x that peak fails both hubs all the same, and one rated above it leaves the clamp model's figures."""
    free = _tilt_clamps(torque_path.analyse(_tilt_coupling(tmp_path)))
    peak = free[0].peak_Nm
    required = torque_path.analyse(_tilt_coupling(tmp_path)).required
    assert all(e.margin >= required for e in free)
    weak = torque_path.analyse(_tilt_coupling(tmp_path, rated_torque_Nm=round(peak * 1.2, 3)))
    failed = [e for e in weak.failures() if e.joint == "eyes_tilt"]
    assert [e.element for e in failed] == ["clamp", "clamp"]
    assert all(e.capacity_Nm == pytest.approx(peak * 1.2, abs=1e-3) for e in failed)
    with pytest.raises(torque_path.TorquePathError, match=r"eyes_tilt\[0\] clamp"):
        torque_path.enforce(weak)
    assert "the coupling's rating" in torque_path.format_table(weak)
    rows = [r for r in docs_sync.torque_table(json.loads(torque_path.dumps(weak))).splitlines() if "| eyes_tilt | clamp" in r]
    assert len(rows) == 2 and all("the coupling's rating" in r and "too weak" in r for r in rows)
    strong = _tilt_clamps(torque_path.analyse(_tilt_coupling(tmp_path, rated_torque_Nm=50)))
    assert [e.capacity_Nm for e in strong] == pytest.approx([e.capacity_Nm for e in free])
    assert all(e.rated_Nm == 50 for e in strong)


def test_a_clamp_naming_a_wrong_coupling_is_refused(tmp_path):
    """A coupling without a bore for the clamped shaft, or a part that is no coupling, is named where it is set."""
    with pytest.raises(ParameterError, match=r"torque_paths\.eyes_tilt\[1\]\.coupling: .*none for the element's 6 mm"):
        torque_path.analyse(_tilt_coupling(tmp_path, bores=[3, 5]))
    with pytest.raises(ParameterError, match=r"\.bores: expected a list"):
        torque_path.analyse(_tilt_coupling(tmp_path, bores="3 to 6"))

    def not_a_coupling(data):
        data["torque_paths"]["eyes_tilt"][0]["coupling"] = "iso4029-M3x4"
    with pytest.raises(ParameterError, match=r"torque_paths\.eyes_tilt\[0\]\.coupling: 'iso4029-M3x4' is a set_screw"):
        torque_path.analyse(edited(tmp_path, not_a_coupling))


def _mxl_yaw(data):
    """The yaw stage back on MXL stock, with its old 36T joint pulley (a 20T MXL pulley is smaller than the 15 mm
    shaft): its pulleys redrawn at the MXL pitch, the motor pulley bought as the XL one is."""
    data["geometry"]["pulleys"]["yaw"].update(belt="mxl-belt-6mm", pitch=2.032, width=8, rim=1.5, joint_teeth=36,
                                              flange_thickness=0.6)
    data["purchased"]["mxl-pulley-14T-bore6"] = dict(data["purchased"]["xl-pulley-14T-bore6"])


@pytest.mark.timeout(1800)
def test_the_build_stops_on_a_torque_path_too_weak(fab, tmp_path):
    """The whole build, from a copy of the package's caches, with the yaw stage on an MXL belt: the torque-path check
    stops it with the table (before the bearing loads, which the MXL pulley's larger belt pull fails too)."""
    import shutil

    from robogene_head import fab as fab_mod
    from robogene_head.progress import Progress
    from param_variants import edited_file
    out = tmp_path / "fab"
    shutil.copytree(fab, out, ignore=shutil.ignore_patterns("drawings", "renders", "assembly", "bom", "electronics"))
    path = edited_file(tmp_path, _mxl_yaw)
    board = json.loads((fab / "manifest.json").read_text())["board_step"]["path"]
    with pytest.raises(fab_mod.BuildError, match=r"^torque path elements below the required margin 1\.5: "
                                                 r"neck_yaw\[3\] belt"):
        fab_mod.build(out, path, [], None, Progress(), board_step=board)
    table = (out / "reports" / "torque-path.txt").read_text()
    assert "TOO WEAK" in table and "MXL" not in table.split("neck_yaw")[0]
