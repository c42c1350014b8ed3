# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""The OpenSCAD printables render headless and follow the head's parameters."""
import numpy as np
import trimesh

from robogene_head import openscad
from robogene_head.checks.mesh import check_stl


def test_camera_spacer_follows_the_baseline(params, tmp_path):
    values = dict(openscad.defines(params)["camera_spacer"])
    scad = openscad.SCAD_DIR / "camera_spacer.scad"
    lengths = {}
    for baseline in (params.baseline, params.baseline + 10):
        values["baseline"] = baseline
        out = tmp_path / f"spacer-{baseline}.stl"
        openscad.render_stl(scad, values, out)
        assert check_stl(out).ok
        lo, hi = trimesh.load(str(out), force="mesh").bounds
        lengths[baseline] = hi[0] - lo[0]
    # bar length = baseline + eye-cup face diameter + 10 mm
    assert np.isclose(lengths[params.baseline], params.baseline + values["face_d"] + 10, atol=1e-3)
    assert np.isclose(lengths[params.baseline + 10] - lengths[params.baseline], 10, atol=1e-3)


def test_a_broken_scad_file_is_reported(tmp_path):
    bad = tmp_path / "bad.scad"
    bad.write_text("cube([1, 2, 3]\n")
    try:
        openscad.render_stl(bad, {}, tmp_path / "bad.stl")
    except RuntimeError as exc:
        assert "openscad failed on bad.scad" in str(exc)
    else:
        raise AssertionError("openscad accepted a broken file")
    assert not (tmp_path / "bad.stl").exists()
