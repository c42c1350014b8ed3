# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""The joint encoders: each AS5048A board held by its bracket at the datasheet's air gap over a magnet in the end of
its joint's shaft, the IC on the magnet's axis, measured in the CAD (checks/joint_encoders.py) over the joint's range;
a bracket too far or too near and a board whose IC is off its holes' centre fail, naming the joint."""
import pytest

from robogene_head_model.params import ParameterError
from robogene_head import kinematics
from robogene_head.checks import joint_encoders as check
from robogene_head.geom import distance, location
from robogene_head.parts import joint_encoders, neck, tilt_bearings, yaw_bearings

from param_variants import edited

JOINTS = ("neck_pitch", "neck_roll", "neck_yaw", "eyes_tilt")


def _encoders(tmp_path, edit):
    params = edited(tmp_path, edit)
    return params, check.check(params, joint_encoders.build(params))


def test_every_board_is_in_the_window_over_its_joints_range(params):
    report = check.check(params, joint_encoders.build(params))
    assert report.ok, report.failures
    assert [r.joint for r in report.rows] == list(JOINTS)
    for r in report.rows:
        assert r.gap_min == pytest.approx(1.5, abs=1e-6) and r.gap_max == pytest.approx(1.5, abs=1e-6)
        assert r.offset_max < 1e-6
        assert r.window == (0.5, 2.0) and r.displacement == 0.25
    text = check.format_report(report)
    assert "neck_yaw" in text and "FAIL" not in text


@pytest.mark.parametrize("gap, words", [(2.6, "air gap 2.60 mm, over the datasheet's 2"),
                                        (0.3, "air gap 0.30 mm, under the datasheet's 0.5")])
def test_a_bracket_too_far_or_too_near_fails_for_every_joint(tmp_path, gap, words):
    _, report = _encoders(tmp_path, lambda d: d["geometry"]["joint_encoders"].update(gap=gap))
    assert not report.ok
    assert report.failures == [f"{j}: {words}" for j in JOINTS]


def test_a_board_with_its_ic_off_the_holes_centre_fails(tmp_path):
    """The brackets centre the board's holes on the axis; a board whose IC is 0.4 mm off their centre is off the
    magnet's axis by that much at every joint."""
    _, report = _encoders(tmp_path, lambda d: d["purchased"]["ams-AS5048A"].update(ic_at=[0.4, 0]))
    assert [r.offset_max for r in report.rows] == pytest.approx([0.4] * 4, abs=1e-6)
    assert report.failures == [f"{j}: IC 0.40 mm off the magnet's axis, the datasheet allows 0.25" for j in JOINTS]


def test_a_magnet_off_the_joints_axis_is_caught_as_it_swings_round_the_ic(params):
    """The check measures the magnet where the shaft carries it: moved 0.3 mm off the axis in its shaft it circles
    the IC, and over the joint's range the IC is off its axis by more than the datasheet allows."""
    parts = joint_encoders.build(params)
    magnet = next(p for p in parts if p.name == "neck_yaw_encoder_magnet")
    magnet.local = magnet.local.translate((0.3, 0, 0))
    report = check.check(params, parts)
    assert [f for f in report.failures if f.startswith("neck_yaw")] == \
        ["neck_yaw: IC 0.30 mm off the magnet's axis, the datasheet allows 0.25"]


def test_the_bracket_follows_the_shaft_end_it_faces(tmp_path):
    """A tilt journal standing further out of its bearing's boss moves the holder, the magnet and the bracket's plate
    with it: the gap stays the bracket's, the feet still stand on the plate's outer face round the boss."""
    params, report = _encoders(tmp_path, lambda d: d["geometry"]["joint_encoders"]["holder"].update(protrusion=7))
    assert report.ok, report.failures
    boss = params.geometry("tilt_bearings", "boss").num("thickness")
    end = joint_encoders.ends(params)["eyes_tilt"]
    assert end.face == pytest.approx(-7 - boss) and end.exit == pytest.approx(-7)


def test_the_yaw_and_tilt_ends_are_the_bearings_shaft_ends(params):
    """The yaw shaft ends above the upper bearing's ring (yaw_bearings), the right tilt journal beyond its boss
    (tilt_bearings): the encoders are placed from those ends, and their brackets stand on the faces really there."""
    ends = joint_encoders.ends(params)
    yaw, tilt = ends["neck_yaw"], ends["eyes_tilt"]
    ze = yaw_bearings.shaft_end(params)
    assert ze > yaw_bearings.layout(params).top
    assert yaw.frame.toTuple()[0] == pytest.approx((0, 0, ze))
    assert yaw.face == pytest.approx(-ze)                         # the floor's top face, z 0
    lay = tilt_bearings.layout(params)
    hw = params.geometry("head", "floor").num("half_width")
    assert tilt.frame.toTuple()[0][1] == pytest.approx(tilt_bearings.shaft_end(params))
    assert tilt_bearings.shaft_end(params) == pytest.approx(-lay.outer - joint_encoders.shaft_protrusion(params))
    assert tilt.face == pytest.approx(tilt_bearings.shaft_end(params) + hw)   # the right plate's outer face


def test_the_yaw_magnets_pocket_stays_clear_of_the_upper_rings_groove(params):
    """The pocket in the yaw shaft's top runs down beside the upper DIN 471 groove: the shaft keeps a wall of more
    than 1 mm between the magnet and the ring in the groove (the groove is 14.3 across, the pocket 6.05)."""
    parts = {p.name: p for p in neck.build(params) + joint_encoders.build(params)}
    poses = kinematics.link_poses(params, {})
    magnet, ring = (parts[n].shape.moved(location(poses[parts[n].link]))
                    for n in ("neck_yaw_encoder_magnet", "neck_yaw_ring_upper"))
    m, r = magnet.BoundingBox(), ring.BoundingBox()
    assert m.zmin < r.zmax and r.zmin < m.zmax                     # side by side along the shaft
    assert distance(magnet, ring) > 1.0


@pytest.mark.parametrize("joint, feet, words", [
    ("neck_yaw", [[0, -17], [0, 17]], r"feet\[0\]: the foot at \(0, -17\) reaches within 0\.8 of the 30 mm boss"),
    ("eyes_tilt", [[-10, 12], [10, 12]], r"feet\[0\]: the foot at \(-10, 12\) reaches within 0\.8 of the 27 mm boss"),
])
def test_a_foot_on_the_bearings_boss_is_refused(tmp_path, joint, feet, words):
    params = edited(tmp_path, lambda d: d["geometry"]["joint_encoders"]["joints"][joint].update(feet=feet))
    with pytest.raises(ParameterError, match=rf"geometry\.joint_encoders\.joints\.{joint}\.{words}"):
        joint_encoders.build(params)


def test_magnets_sit_in_their_pockets_and_brackets_on_their_faces(params, assembly):
    """Each magnet is flush in its pocket (no common volume with the shaft, touching it); each bracket's feet stand
    on the face round the shaft's end, and the board and bracket keep the fabricator's minimum from everything that
    turns with the shaft over the joint's range."""
    minimum = params.geometry("clearances").num("minimum")
    parts = {p.name: p for p in assembly.parts}
    carriers = {"neck_pitch": "neck_pitch_stage", "neck_roll": "neck_roll_stage", "neck_yaw": "neck_roll_stage",
                "eyes_tilt": "eyes_tilt_magnet_holder"}
    faces = {"neck_pitch": "neck_upright_right", "neck_roll": "neck_pitch_front_lug", "neck_yaw": "head_floor",
             "eyes_tilt": "head_side_plate_right"}
    for joint in JOINTS:
        magnet, carrier = parts[f"{joint}_encoder_magnet"].shape, parts[carriers[joint]].shape
        assert magnet.intersect(carrier).Volume() < 1e-6
        assert distance(magnet, carrier) < 1e-6
        bracket, face = parts[f"{joint}_encoder_bracket"].shape, parts[faces[joint]].shape
        assert bracket.intersect(face).Volume() < 1e-6
        assert distance(bracket, face) < 1e-6
        end = joint_encoders.ends(params)[joint]
        turning = [p for p in assembly.parts if p.link == end.shaft]
        j = params.joints[joint]
        for angle in (j.lower, 0.0, j.upper):
            poses = kinematics.link_poses(params, {joint: angle})
            fixed = [parts[f"{joint}_encoder_bracket"], parts[f"{joint}_joint_encoder"]]
            near = [p for p in turning if p.name in (carriers[joint], f"{joint}_encoder_magnet")]
            for a in fixed:
                for b in near:
                    d = distance(a.shape.moved(location(poses[a.link])), b.shape.moved(location(poses[b.link])))
                    assert d >= minimum - 1e-6, (joint, angle, a.name, b.name, d)


@pytest.mark.parametrize("edit, where", [
    (lambda d: d["geometry"]["joint_encoders"]["joints"]["neck_pitch"].update(feet=[[0, -14], [12, -18]]),
     r"geometry\.joint_encoders\.joints\.neck_pitch\.feet\[0\]: the foot at \(0, -14\) stands under the board"),
    (lambda d: d["geometry"]["joint_encoders"]["joints"]["neck_roll"].update(feet=[[16.5, -3.25], [16.5, 3.25]]),
     r"geometry\.joint_encoders\.joints\.neck_roll\.feet: feet 0 and 1 are 6\.5 apart"),
    (lambda d: d["geometry"]["joint_encoders"].update(engagement=1),
     r"geometry\.joint_encoders\.mount_screw: iso7380-M3x12 is too long for the neck_pitch bracket"),
    (lambda d: d["geometry"]["joint_encoders"].update(engagement=11),
     r"geometry\.joint_encoders\.mount_screw: iso7380-M3x12 is too short for the neck_pitch bracket"),
    (lambda d: d["geometry"]["joint_encoders"].update(pocket_clearance=3),
     r"geometry\.joint_encoders\.magnet: a 9 mm pocket leaves under 1 mm of wall in the neck_pitch shaft"),
])
def test_a_wrong_encoder_parameter_is_named(tmp_path, edit, where):
    params = edited(tmp_path, edit)
    with pytest.raises(ParameterError, match=where):
        joint_encoders.build(params)
        neck.build(params)          # the magnets' pockets are cut in the neck's shafts
