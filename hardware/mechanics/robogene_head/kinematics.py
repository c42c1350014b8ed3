# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: CERN-OHL-S-2.0
"""The head's kinematic tree, shared by the CAD assembly and the URDF generator.

Link frames sit on their joint axes; a joint's origin is in its parent's frame (mm) and its axis in the
child's frame. Angles are degrees at the interface and radians inside."""
from __future__ import annotations

import math

import numpy as np

from robogene_head_model.params import CHAIN_JOINTS, CONTROL_JOINTS, HeadParameters

ROOT_LINK = "neck_base"


def rotation(axis, angle_rad: float) -> np.ndarray:
    x, y, z = axis
    c, s, t = math.cos(angle_rad), math.sin(angle_rad), 1 - math.cos(angle_rad)
    return np.array([[t * x * x + c, t * x * y - s * z, t * x * z + s * y],
                     [t * x * y + s * z, t * y * y + c, t * y * z - s * x],
                     [t * x * z - s * y, t * y * z + s * x, t * z * z + c]])


def transform(rot: np.ndarray | None = None, trans=(0.0, 0.0, 0.0)) -> np.ndarray:
    m = np.eye(4)
    if rot is not None:
        m[:3, :3] = rot
    m[:3, 3] = trans
    return m


def chain_angles(params: HeadParameters, control: dict[str, float] | None = None) -> dict[str, float]:
    """Control-board angles (deg, by CONTROL_JOINTS name; missing = 0) -> physical chain angles (deg)."""
    control = dict(control or {})
    unknown = set(control) - set(CONTROL_JOINTS)
    if unknown:
        raise KeyError(f"unknown control joint(s): {', '.join(sorted(unknown))}")
    version, vergence = control.get("eyes_version", 0.0), control.get("eyes_vergence", 0.0)
    return {
        "neck_pitch": control.get("neck_pitch", 0.0),
        "neck_roll": control.get("neck_roll", 0.0),
        "neck_yaw": control.get("neck_yaw", 0.0),
        "eyes_tilt": control.get("eyes_tilt", 0.0),
        "left_eye_pan": version + vergence / 2,
        "right_eye_pan": version - vergence / 2,
    }


def link_poses(params: HeadParameters, angles: dict[str, float] | None = None) -> dict[str, np.ndarray]:
    """World (neck_base) pose of every link frame for chain angles in degrees (missing = 0)."""
    angles = angles or {}
    poses = {ROOT_LINK: np.eye(4)}
    pending = [params.joints[name] for name in CHAIN_JOINTS]
    while pending:
        progressed = False
        for joint in list(pending):
            if joint.parent in poses:
                q = math.radians(angles.get(joint.name, 0.0))
                poses[joint.child] = poses[joint.parent] @ transform(trans=joint.origin) @ transform(rotation(joint.axis, q))
                pending.remove(joint)
                progressed = True
        if not progressed:
            raise ValueError("joints do not form a tree rooted at " + ROOT_LINK + ": " +
                             ", ".join(f"{j.name} (parent {j.parent})" for j in pending))
    return poses


def joint_axes_world(params: HeadParameters, angles: dict[str, float] | None = None) -> dict[str, tuple[np.ndarray, np.ndarray]]:
    """Each joint's axis in the world frame as (point on axis, unit direction)."""
    poses = link_poses(params, angles)
    out = {}
    for name in CHAIN_JOINTS:
        j = params.joints[name]
        pose = poses[j.child]
        out[name] = (pose[:3, 3].copy(), pose[:3, :3] @ np.array(j.axis))
    return out


def links(params: HeadParameters) -> list[str]:
    return [ROOT_LINK] + [params.joints[name].child for name in CHAIN_JOINTS]
