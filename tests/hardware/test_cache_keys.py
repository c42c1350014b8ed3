# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""The build's cache keys see a part's geometry, and only its geometry: exporting a part (which meshes it) must not
change its hash, or a package built from nothing redraws its drawings and pictures on the next build."""
import sys
from pathlib import Path
from types import SimpleNamespace

import cadquery as cq
import pytest
from OCP.BRepMesh import BRepMesh_IncrementalMesh

from robogene_head.export import shape_hash, write_stl


def _plate():
    return cq.Workplane().box(40, 20, 5).faces(">Z").workplane().hole(3.2).edges("|Z").fillet(2).val()


def test_exporting_a_part_leaves_its_hash_alone(tmp_path):
    plate = _plate()
    before = shape_hash(plate, "machined")
    write_stl(plate, tmp_path / "plate.stl")      # attaches a triangulation and marks sub-shapes checked
    assert (tmp_path / "plate.stl").stat().st_size > 0
    assert shape_hash(plate, "machined") == before


def test_a_meshed_and_an_unmeshed_build_of_the_same_geometry_hash_the_same():
    meshed, unmeshed = _plate(), _plate()
    BRepMesh_IncrementalMesh(meshed.wrapped, 0.01, False, 0.1, True).Perform()
    assert shape_hash(meshed) == shape_hash(unmeshed)


def test_geometry_and_labels_change_the_hash():
    plate = _plate()
    wider = cq.Workplane().box(40.01, 20, 5).faces(">Z").workplane().hole(3.2).edges("|Z").fillet(2).val()
    assert shape_hash(wider) != shape_hash(plate)
    assert shape_hash(plate, "machined") != shape_hash(plate, "printed")


def _meshed(shape):
    BRepMesh_IncrementalMesh(shape.wrapped, 0.5, False, 0.5, True).Perform()
    return shape


def _sphere_cap():
    # A curved part whose coarse mesh falls visibly inside its true surface.
    return cq.Workplane().sphere(20).cut(cq.Workplane().box(60, 60, 60).translate((0, 0, -25))).val()


def test_exact_bounds_ignore_a_triangulation():
    from robogene_head.geom import exact_bounds
    cap = _sphere_cap()
    lo, hi = exact_bounds(cap)
    r = (20 ** 2 - 5 ** 2) ** 0.5      # the cap is widest where it was cut, at z = 5
    assert lo == pytest.approx([-r, -r, 5], abs=1e-6) and hi == pytest.approx([r, r, 20], abs=1e-6)
    _meshed(cap)
    assert all(a == pytest.approx(b, abs=1e-9) for a, b in zip(exact_bounds(cap), (lo, hi)))


def test_the_harness_key_does_not_change_when_the_parts_are_meshed(params):
    from robogene_head.harness.build import _checks_key
    parts = [SimpleNamespace(name="cap", link="head_frame", shape=_sphere_cap())]
    before = _checks_key(params, parts, "geometry")
    _meshed(parts[0].shape)
    assert _checks_key(params, parts, "geometry") == before


def _probe_package(root: Path) -> None:
    """A package named like this one: a imports b (a function of it), b imports parts.c; d is imported by no one."""
    pkg = root / "robogene_head_probe"
    (pkg / "parts").mkdir(parents=True)
    files = {"__init__.py": "", "a.py": "from .b import helper\n", "b.py": "from .parts import c\n\ndef helper():\n"
             "    return c.SIZE\n", "d.py": "X = 1\n", "parts/__init__.py": "", "parts/c.py": "SIZE = 3\n"}
    for name, text in files.items():
        (pkg / name).write_text(text)


def test_a_code_digest_follows_imports_into_the_package(tmp_path, monkeypatch):
    from robogene_head.cache import code_digest
    _probe_package(tmp_path)
    monkeypatch.syspath_prepend(str(tmp_path))
    import importlib
    a = importlib.import_module("robogene_head_probe.a")
    importlib.import_module("robogene_head_probe.d")
    before = code_digest(a)
    pkg = tmp_path / "robogene_head_probe"
    (pkg / "d.py").write_text("X = 2\n")                    # not used by a
    (pkg / "parts" / "c.py").write_text("SIZE = 4\n")       # a part builder: its shapes are hashed, not its code
    assert code_digest(a) == before
    (pkg / "b.py").write_text((pkg / "b.py").read_text() + "# changed\n")    # used by a, through a function
    assert code_digest(a) != before
    for name in [m for m in sys.modules if m.startswith("robogene_head_probe")]:
        monkeypatch.delitem(sys.modules, name)


def test_the_pictures_keys_see_the_renderer():
    """The renderer's stage() changed under the step pictures and the harness picture, whose keys did not see
    render.py: a warm build kept the old pictures and only a fresh build ran the broken call."""
    from robogene_head import render_steps
    from robogene_head.cache import code_modules
    from robogene_head.harness import build
    assert "robogene_head.render" in code_modules(render_steps)
    assert {"robogene_head.render", "robogene_head.fcl_mesh"} <= set(code_modules(build))
