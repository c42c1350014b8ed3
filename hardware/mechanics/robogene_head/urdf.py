# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: CERN-OHL-S-2.0
"""URDF of the head, generated from the parameter file and the CAD's mass properties.

Lengths in metres, angles in radians; the link meshes are the CAD's parts merged per link, in the link
frame, written in millimetres and scaled by 0.001. The joints' effort and velocity limits are what their drives
deliver at the joint (drive_limits: continuous torque, and speed at the motor's no-load speed)."""
from __future__ import annotations

import math
from xml.etree import ElementTree as ET

from robogene_head_model import drive_limits
from robogene_head_model.params import CHAIN_JOINTS, HeadParameters

from . import kinematics
from .massprops import MassProps


def _fmt(v: float) -> str:
    text = f"{v:.9g}"
    return "0" if text in ("-0", "0") else text


def _vec(values, scale=1.0) -> str:
    return " ".join(_fmt(v * scale) for v in values)


def generate(params: HeadParameters, props: dict[str, MassProps], mesh_dir: str = "meshes") -> str:
    robot = ET.Element("robot", name=params.root.text("name").replace("-", "_"))
    # The phrase is split: only committed generated files may contain it (tests/codegen/test_manifest.py).
    robot.append(ET.Comment(f" Generated from {params.path.name} by robogene_head.urdf; do not " "edit. "))
    for link in kinematics.links(params):
        el = ET.SubElement(robot, "link", name=link)
        mp = props.get(link)
        if mp is not None and mp.mass > 0:
            inertial = ET.SubElement(el, "inertial")
            ET.SubElement(inertial, "origin", xyz=_vec(mp.com, 1e-3), rpy="0 0 0")
            ET.SubElement(inertial, "mass", value=_fmt(mp.mass))
            i = mp.inertia * 1e-6
            ET.SubElement(inertial, "inertia", ixx=_fmt(i[0, 0]), ixy=_fmt(i[0, 1]), ixz=_fmt(i[0, 2]),
                          iyy=_fmt(i[1, 1]), iyz=_fmt(i[1, 2]), izz=_fmt(i[2, 2]))
        for tag in ("visual", "collision"):
            node = ET.SubElement(el, tag)
            ET.SubElement(node, "origin", xyz="0 0 0", rpy="0 0 0")
            geometry = ET.SubElement(node, "geometry")
            ET.SubElement(geometry, "mesh", filename=f"{mesh_dir}/{link}.stl", scale="0.001 0.001 0.001")
    limits = drive_limits.limits(params)
    for name in CHAIN_JOINTS:
        j = params.joints[name]
        el = ET.SubElement(robot, "joint", name=name, type="revolute")
        ET.SubElement(el, "parent", link=j.parent)
        ET.SubElement(el, "child", link=j.child)
        ET.SubElement(el, "origin", xyz=_vec(j.origin, 1e-3), rpy="0 0 0")
        ET.SubElement(el, "axis", xyz=_vec(j.axis))
        ET.SubElement(el, "limit", lower=_fmt(math.radians(j.lower)), upper=_fmt(math.radians(j.upper)),
                      effort=_fmt(limits[name].effort), velocity=_fmt(limits[name].velocity))
    ET.indent(robot)
    return '<?xml version="1.0"?>\n' + ET.tostring(robot, encoding="unicode") + "\n"
