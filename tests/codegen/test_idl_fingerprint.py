# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""Fingerprints change with anything visible on the wire and only with that."""
import shutil
from pathlib import Path

from robogene_codegen.idl import compile_directory

IDL = Path(__file__).resolve().parents[2] / "interfaces" / "idl"


def fingerprints(directory: Path) -> dict:
    idl = compile_directory(directory)
    return {i.name: i.fingerprint for i in idl.interfaces} | {s.name: s.fingerprint for s in idl.services}


def copy(tmp_path: Path) -> Path:
    target = tmp_path / "idl"
    shutil.copytree(IDL, target)
    return target


def edit(path: Path, old: str, new: str) -> None:
    text = path.read_text()
    assert old in text
    path.write_text(text.replace(old, new, 1))


def test_the_project_idl_compiles_with_distinct_fingerprints():
    fps = fingerprints(IDL)
    assert {"IEncoders", "IPositionControl", "IVelocityControl", "ITorqueControl", "IPidControl",
            "IControlMode", "IFrameGrabberImage", "IFrameGrabberControls", "controlboard",
            "grabber"} <= set(fps)
    assert all(len(v) == 16 and int(v, 16) >= 0 for v in fps.values())
    assert len(set(fps.values())) == len(fps)


def test_docs_and_layout_do_not_change_fingerprints(tmp_path):
    d = copy(tmp_path)
    before = fingerprints(d)
    edit(d / "ipositioncontrol.yaml", "doc: Start moving one axis to an absolute position.",
         "doc: >-\n      Start moving one axis to an absolute position (reworded).")
    edit(d / "iencoders.yaml", "\n  - name: getAxes", "\n\n  # a comment\n  - name: getAxes")
    assert fingerprints(d) == before


def test_wire_visible_changes_alter_the_fingerprint(tmp_path):
    d = copy(tmp_path)
    before = fingerprints(d)
    edit(d / "ipositioncontrol.yaml", "wire: [set, pos]", "wire: [set, posx]")
    after = fingerprints(d)
    assert after["IPositionControl"] != before["IPositionControl"]
    assert after["controlboard"] != before["controlboard"]  # a service pins its interfaces
    assert after["IEncoders"] == before["IEncoders"]


def test_units_and_enum_values_are_part_of_the_fingerprint(tmp_path):
    d = copy(tmp_path)
    before = fingerprints(d)
    edit(d / "iencoders.yaml", "{name: v, type: float64, unit: deg}", "{name: v, type: float64, unit: rad}")
    edit(d / "enums_controlboard.yaml", "value: torq", "value: trqq")
    after = fingerprints(d)
    assert after["IEncoders"] != before["IEncoders"]
    assert after["IControlMode"] != before["IControlMode"]
    assert after["IPositionControl"] == before["IPositionControl"]
