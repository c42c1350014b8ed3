# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""The URDF's joint frames match the CAD assembly's.

The URDF is read back as XML and its forward kinematics computed here, independently of the code that
wrote it. The CAD side is geometry: the bearing bores (and the eye cups' pan bores) of the placed solids
must lie on the URDF's joint axes in every pose, and each child link's solids must move exactly as the
URDF's frames predict."""
import math
import xml.etree.ElementTree as ET

import numpy as np
import pytest
from OCP.BRepAdaptor import BRepAdaptor_Surface
from OCP.GeomAbs import GeomAbs_Cylinder

from robogene_head import kinematics

SAMPLE_POSES = [
    {},
    {"neck_pitch": 22, "neck_roll": -20, "neck_yaw": 45, "eyes_tilt": -30, "eyes_version": 30, "eyes_vergence": 0},
    {"neck_pitch": -30, "neck_roll": 20, "neck_yaw": -45, "eyes_tilt": 30, "eyes_version": -30, "eyes_vergence": 45},
    {"neck_pitch": 7.5, "neck_roll": 3, "neck_yaw": -12, "eyes_tilt": 11, "eyes_version": 4, "eyes_vergence": 21},
]
# Parts whose cylindrical bores physically define each joint's axis.
AXIS_PARTS = {
    "neck_pitch": ["neck_pitch_bearing_right", "neck_upright_right"],
    "neck_roll": ["neck_roll_bearing_front", "neck_pitch_front_lug"],
    "neck_yaw": ["neck_yaw_bearing_lower", "neck_yaw_bearing_upper", "neck_yaw_joint_pulley"],
    "eyes_tilt": ["eyes_tilt_bearing_left", "eyes_tilt_bearing_right", "eyes_tilt_joint_pulley"],
    "left_eye_pan": ["left_eye_cup"],
    "right_eye_pan": ["right_eye_cup"],
}


class Urdf:
    def __init__(self, path):
        root = ET.parse(path).getroot()
        self.links = {l.get("name"): l for l in root.findall("link")}
        self.joints = {}
        for j in root.findall("joint"):
            origin = j.find("origin")
            self.joints[j.get("name")] = {
                "parent": j.find("parent").get("link"), "child": j.find("child").get("link"),
                "xyz": np.array([float(v) for v in origin.get("xyz").split()]) * 1000.0,  # m -> mm
                "rpy": [float(v) for v in origin.get("rpy").split()],
                "axis": np.array([float(v) for v in j.find("axis").get("xyz").split()]),
                "lower": float(j.find("limit").get("lower")), "upper": float(j.find("limit").get("upper")),
            }

    @staticmethod
    def _rpy(r, p, y):
        cr, sr, cp, sp, cy, sy = math.cos(r), math.sin(r), math.cos(p), math.sin(p), math.cos(y), math.sin(y)
        return np.array([[cy * cp, cy * sp * sr - sy * cr, cy * sp * cr + sy * sr],
                         [sy * cp, sy * sp * sr + cy * cr, sy * sp * cr - cy * sr],
                         [-sp, cp * sr, cp * cr]])

    @staticmethod
    def _axis_angle(axis, q):
        k = np.array([[0, -axis[2], axis[1]], [axis[2], 0, -axis[0]], [-axis[1], axis[0], 0]])
        return np.eye(3) + math.sin(q) * k + (1 - math.cos(q)) * k @ k

    def fk(self, angles_deg):
        poses = {"neck_base": np.eye(4)}
        todo = dict(self.joints)
        while todo:
            for name, j in list(todo.items()):
                if j["parent"] in poses:
                    origin = np.eye(4)
                    origin[:3, :3] = self._rpy(*j["rpy"])
                    origin[:3, 3] = j["xyz"]
                    motion = np.eye(4)
                    motion[:3, :3] = self._axis_angle(j["axis"], math.radians(angles_deg.get(name, 0.0)))
                    poses[j["child"]] = poses[j["parent"]] @ origin @ motion
                    del todo[name]
        return poses


@pytest.fixture(scope="module")
def urdf(fab):
    return Urdf(fab / "urdf" / "robogene_head.urdf")


def _cylinder_axes(shape):
    axes = []
    for face in shape.Faces():
        surface = BRepAdaptor_Surface(face.wrapped)
        if surface.GetType() != GeomAbs_Cylinder:
            continue
        cyl = surface.Cylinder()
        loc, d = cyl.Location(), cyl.Axis().Direction()
        axes.append((np.array([loc.X(), loc.Y(), loc.Z()]), np.array([d.X(), d.Y(), d.Z()]), cyl.Radius()))
    return axes


def _line_distance(point, origin, direction):
    v = point - origin
    return np.linalg.norm(v - np.dot(v, direction) * direction)


def test_urdf_lists_the_chain_with_limits(urdf, params):
    assert set(urdf.joints) == set(params.joints)
    for name, j in params.joints.items():
        u = urdf.joints[name]
        assert (u["parent"], u["child"]) == (j.parent, j.child)
        assert u["lower"] == pytest.approx(math.radians(j.lower)) and u["upper"] == pytest.approx(math.radians(j.upper))
    for link in kinematics.links(params):
        mesh = urdf.links[link].find("visual/geometry/mesh").get("filename")
        assert mesh == f"meshes/{link}.stl"


@pytest.mark.parametrize("pose", SAMPLE_POSES)
def test_bearing_bores_lie_on_the_urdf_joint_axes(urdf, params, assembly, pose):
    chain = kinematics.chain_angles(params, pose)
    frames = urdf.fk(chain)
    placed = {p.part.name: p for p in assembly.pose(pose)}
    for joint, part_names in AXIS_PARTS.items():
        j = urdf.joints[joint]
        child = frames[j["child"]]
        origin, direction = child[:3, 3], child[:3, :3] @ j["axis"]
        for name in part_names:
            bores = [(p, d) for p, d, r in _cylinder_axes(placed[name].shape)
                     if abs(abs(np.dot(d, direction)) - 1) < 1e-9 and _line_distance(p, origin, direction) < 1e-6]
            assert bores, f"{name}: no cylindrical face on the URDF axis of {joint} in pose {pose}"


@pytest.mark.parametrize("pose", SAMPLE_POSES[1:])
def test_child_links_move_as_the_urdf_predicts(urdf, params, assembly, pose):
    chain = kinematics.chain_angles(params, pose)
    rest, moved = urdf.fk({}), urdf.fk(chain)
    at_rest = {p.part.name: p.shape for p in assembly.pose({})}
    for placed in assembly.pose(pose):
        link = placed.part.link
        predicted = moved[link] @ np.linalg.inv(rest[link])
        c0 = at_rest[placed.part.name].Center()
        c1 = placed.shape.Center()
        expect = predicted[:3, :3] @ np.array([c0.x, c0.y, c0.z]) + predicted[:3, 3]
        assert np.allclose([c1.x, c1.y, c1.z], expect, atol=1e-6), placed.part.name


def test_urdf_inertials_are_physical(urdf, fab):
    import json
    mass = json.loads((fab / "reports" / "mass.json").read_text())
    for name, link in urdf.links.items():
        inertial = link.find("inertial")
        assert inertial is not None, name
        m = float(inertial.find("mass").get("value"))
        assert m == pytest.approx(mass["links"][name]["mass_kg"], rel=1e-4)
        i = inertial.find("inertia")
        tensor = np.array([[float(i.get("ixx")), float(i.get("ixy")), float(i.get("ixz"))],
                           [float(i.get("ixy")), float(i.get("iyy")), float(i.get("iyz"))],
                           [float(i.get("ixz")), float(i.get("iyz")), float(i.get("izz"))]])
        eig = np.linalg.eigvalsh(tensor)
        assert eig.min() > 0, name
        # Principal moments of a real body obey the triangle inequality.
        assert eig[0] + eig[1] >= eig[2] * (1 - 1e-6), name


def test_urdf_meshes_exist_and_load(urdf, fab):
    import trimesh
    for name, link in urdf.links.items():
        path = fab / "urdf" / link.find("visual/geometry/mesh").get("filename")
        mesh = trimesh.load(str(path), force="mesh")
        assert len(mesh.faces) > 0, name


def test_a_parameter_change_travels_to_cad_and_urdf(params, board_step, tmp_path):
    """Move the eye-tilt axis in the parameter file: the regenerated URDF and the rebuilt CAD agree again."""
    import yaml
    from robogene_head import external, massprops, urdf as urdf_gen
    from robogene_head.assembly import Assembly
    from robogene_head_model.params import load

    data = yaml.safe_load(params.path.read_text())
    data["joints"]["eyes_tilt"]["origin"] = [55, 0, 84]
    path = tmp_path / "moved.yaml"
    path.write_text(yaml.safe_dump(data))
    moved = load(path)
    assembly = Assembly(moved, external=external.render_and_load(moved, board_step, tmp_path))
    (tmp_path / "head.urdf").write_text(urdf_gen.generate(moved, massprops.link_props(moved, assembly.parts)))
    model = Urdf(tmp_path / "head.urdf")
    assert np.allclose(model.joints["eyes_tilt"]["xyz"], [55, 0, 84])
    pose = SAMPLE_POSES[3]
    frames = model.fk(kinematics.chain_angles(moved, pose))
    placed = {p.part.name: p for p in assembly.pose(pose)}
    for name in AXIS_PARTS["eyes_tilt"] + AXIS_PARTS["left_eye_pan"]:
        j = model.joints["eyes_tilt" if name in AXIS_PARTS["eyes_tilt"] else "left_eye_pan"]
        f = frames[j["child"]]
        o, d = f[:3, 3], f[:3, :3] @ j["axis"]
        assert any(abs(abs(np.dot(a, d)) - 1) < 1e-9 and _line_distance(p, o, d) < 1e-6
                   for p, a, r in _cylinder_axes(placed[name].shape)), name
