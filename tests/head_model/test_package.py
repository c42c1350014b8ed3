# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""The head model is an installed package that the code generator and the CAD import the normal way: from
.venv, with no search path set by hand, and without the CAD's dependencies."""
import importlib.metadata
import json
import os
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
MODEL = ROOT / "hardware" / "head-model"


def run(code: str, tmp_path, **env) -> dict:
    """Runs `code` in a fresh interpreter of .venv, outside the repository and with no PYTHONPATH unless
    given; it prints one JSON value, returned here."""
    clean = {k: v for k, v in os.environ.items() if k != "PYTHONPATH"}
    result = subprocess.run([sys.executable, "-c", code], cwd=tmp_path, env=dict(clean, **env),
                            capture_output=True, text=True, timeout=60)
    assert result.returncode == 0, result.stderr
    return json.loads(result.stdout)


def test_installed_in_the_venv_from_its_folder():
    dist = importlib.metadata.distribution("robogene-head-model")
    assert dist.requires == ["PyYAML"]
    # Editable: the installed package is the folder in the repository, so the parameter file beside it is the
    # default and an edit needs no reinstall.
    direct = json.loads(dist.read_text("direct_url.json"))
    assert direct["dir_info"] == {"editable": True}
    assert Path(direct["url"].removeprefix("file://")).resolve() == MODEL


def test_imports_normally_and_reads_the_repositorys_parameter_file(tmp_path):
    got = run("import json, robogene_head_model.params as p; "
              "print(json.dumps([p.__file__, str(p.DEFAULT_PATH), p.load().baseline]))", tmp_path)
    assert Path(got[0]).resolve() == MODEL / "robogene_head_model" / "params.py"
    assert Path(got[1]).resolve() == ROOT / "hardware" / "head-parameters.yaml"
    assert got[2] == 68


def test_the_model_needs_no_cad(tmp_path):
    loaded = run("import json, sys; from robogene_head_model import drive_limits, joint_config, params; "
                 "joint_config.config(params.load()); print(json.dumps(sorted(sys.modules)))", tmp_path)
    assert not {"cadquery", "OCP", "numpy", "trimesh", "robogene_head"} & set(loaded)


def test_the_code_generator_imports_the_model_not_the_cad_package(tmp_path):
    """The board configuration is checked against the head model; the generator finds it installed, and
    neither puts the mechanics folder on the path nor loads the CAD package."""
    got = run("import json, sys; from pathlib import Path; "
              "from robogene_codegen.generate import render; "
              f"out = render(Path({str(ROOT)!r}), ['can-driver-config']); "
              "print(json.dumps([sorted(out), sys.modules['robogene_head_model'].__file__, "
              "'robogene_head' in sys.modules, [p for p in sys.path if 'mechanics' in p]]))",
              tmp_path, PYTHONPATH=str(ROOT / "codegen"))
    outputs, model_file, cad_loaded, mechanics_on_path = got
    assert outputs == ["drivers/can/generated/head.ini"]
    assert Path(model_file).resolve() == MODEL / "robogene_head_model" / "__init__.py"
    assert not cad_loaded and not mechanics_on_path

