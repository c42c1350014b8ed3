# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""codegen/generated-manifest.yaml is the one list of generated files: it names exactly the files of the
tree that carry a do-not-edit header, every generated block of the docs, and `check` holds the tree to it."""
import re
import shutil
import subprocess
from pathlib import Path

import pytest

from robogene_codegen import doc_blocks
from robogene_codegen.__main__ import main
from robogene_codegen.emitters.common import DO_NOT_EDIT
from robogene_codegen.idl import IdlErrors
from robogene_codegen.idl.loader import load
from robogene_codegen.manifest import MANIFEST, parse, read

ROOT = Path(__file__).resolve().parents[2]
HEADER = re.compile(re.escape(DO_NOT_EDIT), re.I)  # in any capitalisation


def tree_files() -> list[str]:
    """Every file of the working tree that git would see: committed, or new and not ignored."""
    out = subprocess.run(["git", "ls-files", "-z", "--cached", "--others", "--exclude-standard"], cwd=ROOT,
                         capture_output=True, check=True).stdout.decode()
    return sorted(p for p in set(out.split("\0")) if p and (ROOT / p).is_file())


def carrying_the_header() -> set[str]:
    found = set()
    for rel in tree_files():
        data = (ROOT / rel).read_bytes()
        if b"\0" in data[:8192]:
            continue  # binary
        if HEADER.search(data.decode("utf-8", errors="replace")):
            found.add(rel)
    return found


def test_the_manifest_lists_exactly_the_files_that_carry_a_do_not_edit_header():
    manifest = read(ROOT)
    headerless = {p for g in manifest.generators if g.no_header for p in g.paths}
    listed = set(manifest.files) | set(manifest.block_documents)
    found = carrying_the_header()
    assert not found - listed, f"generated (they carry the header) but not in {MANIFEST}: {sorted(found - listed)}"
    assert not (listed - headerless) - found, \
        f"in {MANIFEST} but without a do-not-edit header: {sorted((listed - headerless) - found)}"
    assert not headerless & found, f"said to have no header, yet they carry one: {sorted(headerless & found)}"


def test_the_scan_would_see_an_unlisted_generated_file(tmp_path):
    """The scan above is not vacuous: every listed file is found by it, and so is a new file with the header."""
    manifest = read(ROOT)
    found = carrying_the_header()
    assert {p for g in manifest.generators if not g.no_header for p in g.paths} <= found and len(found) > 40
    assert HEADER.search(f"// {DO_NOT_EDIT.upper()}: made by a script")


def test_every_generated_block_of_the_tree_is_listed():
    manifest = read(ROOT)
    in_docs = {}
    for rel in tree_files():
        if rel.endswith(".md"):
            names = doc_blocks.names((ROOT / rel).read_text(encoding="utf-8"))
            if names:
                in_docs[rel] = sorted(names)
    assert in_docs == {doc: sorted(names) for doc, names in manifest.block_documents.items()}


def test_every_listed_file_exists_and_every_generated_folder_holds_only_listed_files():
    manifest = read(ROOT)
    assert all((ROOT / p).is_file() for p in manifest.files)
    assert manifest.generated_folders  # the folders check-generated sweeps
    for folder in manifest.generated_folders:
        present = {p.relative_to(ROOT).as_posix() for p in (ROOT / folder).rglob("*")
                   if p.is_file() and "__pycache__" not in p.parts}
        assert present == {p for p in manifest.files if p.startswith(folder + "/")}, folder


def test_make_reads_the_generators_needs_from_the_manifest(capsys):
    assert main(["needs"]) == 0
    needs = capsys.readouterr().out.split()
    assert needs == sorted({g.needs for g in read(ROOT).generators if g.needs}) and needs
    shown = subprocess.run(["make", "-n", "--no-print-directory", "check-generated"], cwd=ROOT,
                           capture_output=True, text=True)
    assert "robogene_codegen check --fab" in shown.stdout, shown.stderr
    # What make computes from the manifest is what the manifest says.
    printed = subprocess.run(["make", "--no-print-directory", "-pn", "check-generated"], cwd=ROOT,
                             capture_output=True, text=True).stdout
    rule = next(line for line in printed.splitlines() if line.startswith("check-generated:"))
    assert all(n in rule.split() for n in needs), rule


# ---------------------------------------------------------------------------------------- a tree to break

@pytest.fixture
def tree(tmp_path):
    """What the IDL generators read and write: the manifest, the IDL, the generated folders, the docs with
    blocks and the head parameters."""
    root = tmp_path / "tree"
    shutil.copytree(ROOT / "interfaces", root / "interfaces")
    manifest = read(ROOT)
    for rel in [MANIFEST, "hardware/head-parameters.yaml", *manifest.block_documents]:
        (root / rel).parent.mkdir(parents=True, exist_ok=True)
        shutil.copy(ROOT / rel, root / rel)
    for d in manifest.generated_folders:
        shutil.copytree(ROOT / d, root / d, ignore=shutil.ignore_patterns("__pycache__"), dirs_exist_ok=True)
    return root


def check(root, capsys, *extra) -> tuple[int, str]:
    code = main(["check", "--root", str(root), "--only", "idl", *extra])
    return code, capsys.readouterr().err


def test_check_passes_on_a_faithful_copy(tree, capsys):
    assert check(tree, capsys) == (0, "")


def test_check_fails_on_a_stale_file(tree, capsys):
    ini = tree / "drivers/can/generated/head.ini"
    ini.write_text(ini.read_text().replace("bitrate 1000000", "bitrate 500000"))
    code, err = check(tree, capsys)
    assert code == 1 and "stale: drivers/can/generated/head.ini: differs from what its generator writes" in err


def test_check_fails_on_a_missing_file(tree, capsys):
    (tree / "hardware/electronics/firmware/generated/robogene_head_board_config.h").unlink()
    code, err = check(tree, capsys)
    assert code == 1 and "stale: hardware/electronics/firmware/generated/robogene_head_board_config.h: missing" in err


def test_a_changed_homing_current_makes_both_board_configs_stale_and_generate_writes_it(tree, capsys):
    """motor_control.homing.<joint>.current_limit reaches the driver's [HOMING] and the firmware's table; a changed
    value makes both stale, and generate writes it, byte for byte the same on a second run."""
    params = tree / "hardware/head-parameters.yaml"
    text = params.read_text()
    assert text.count("timeout: 20, current_limit: 100}") == 1
    params.write_text(text.replace("timeout: 20, current_limit: 100}", "timeout: 20, current_limit: 150}"))
    code, err = check(tree, capsys)
    assert code == 1
    ini, table = "drivers/can/generated/head.ini", "hardware/electronics/firmware/generated/robogene_head_board_config.h"
    for rel in (ini, table):
        assert f"stale: {rel}: differs from what its generator writes" in err, err
    assert main(["generate", "--root", str(tree), "--only", "idl"]) == 0
    first = {rel: (tree / rel).read_bytes() for rel in (ini, table)}
    assert re.search(rb"\ncurrent 0 0 0 0 150 0\n", first[ini])
    assert b"20000u, 150," in first[table]
    assert main(["generate", "--root", str(tree), "--only", "idl"]) == 0
    assert {rel: (tree / rel).read_bytes() for rel in (ini, table)} == first
    assert check(tree, capsys)[0] == 0


def test_check_fails_on_an_extra_file_in_a_generated_folder_and_generate_removes_it(tree, capsys):
    # The firmware's headers were in a folder the old sweep did not cover: a renamed board config left its
    # old header behind, unnoticed.
    extra = tree / "hardware/electronics/firmware/generated/robogene_old_board_config.h"
    extra.write_text("// left behind\n")
    code, err = check(tree, capsys)
    assert code == 1
    assert ("stale: hardware/electronics/firmware/generated/robogene_old_board_config.h: in a generated folder but "
            "not in the manifest") in err
    assert main(["generate", "--root", str(tree), "--only", "idl"]) == 0
    assert not extra.exists() and check(tree, capsys) == (0, "")


def test_a_generated_file_missing_from_the_manifest_stops_generate_before_it_writes(tree, capsys):
    manifest = tree / MANIFEST
    manifest.write_text(manifest.read_text().replace("files: [head.ini]", "files: [head.ini, head2.ini]"))
    ini = tree / "drivers/can/generated/head.ini"
    ini.write_text("edited\n")
    assert main(["generate", "--root", str(tree), "--only", "idl"]) == 1
    err = capsys.readouterr().err
    assert ("error: the manifest lists file drivers/can/generated/head2.ini under can-driver-config, which no longer "
            "writes it") in err
    assert ini.read_text() == "edited\n"  # nothing written


def test_an_unlisted_output_is_named_with_its_generator(tree, capsys):
    manifest = tree / MANIFEST
    manifest.write_text(manifest.read_text().replace("files: [motor_control.cpp, motor_control.hpp]",
                                                     "files: [motor_control.cpp]"))
    code, err = check(tree, capsys)
    assert code == 1
    assert "error: cpp-can writes file drivers/can/generated/motor_control.hpp, which the manifest does not list" in err


def test_a_failing_command_generator_is_named_with_what_it_needs(tree, capsys):
    code = main(["check", "--root", str(tree), "--only", "fabrication-tables", "--fab", str(tree / "no-fab")])
    err = capsys.readouterr().err
    assert code == 1 and "error: fabrication-tables:" in err and "it needs `make fab` first" in err


@pytest.mark.parametrize("old, new, message", [
    ("  - name: cpp-can\n", "  - name: cpp-can\n    colour: blue\n", "unknown key 'colour'"),
    ("  - name: can-dbc\n", "  - name: cpp-can\n", "generator 'cpp-can' is listed twice"),
    ("files: [head.dbc]", "files: [motor_control.cpp]", "drivers/can/generated/motor_control.cpp is listed under cpp-can too"),
    ("into: drivers/can/generated\n    files: [head.ini]", "into: drivers/can/config\n    files: [head.ini]",
     "can-driver-config: drivers/can/config is not in a folder named `generated`: say `why:`"),
    ("files: [motor_control.cpp, motor_control.hpp]", "files: [motor_control.hpp, motor_control.cpp]",
     "cpp-can: keep the files sorted"),
    ("into: runtime/devices/src/dev/generated", "into: ../outside/generated", "'../outside/generated' is not a plain relative path"),
    ("emitter: dbc:emit", "emitter: dbc:emit\n    command: [x, \"{out}\"]", "can-dbc: give exactly one of"),
])
def test_a_wrong_manifest_is_refused_naming_the_line(old, new, message):
    text = (ROOT / MANIFEST).read_text()
    assert old in text
    with pytest.raises(IdlErrors) as info:
        parse(load(MANIFEST, text.replace(old, new, 1)))
    line = text.replace(old, new, 1)[:text.index(old)].count("\n") + 1
    errors = [str(e) for e in info.value.errors]
    assert any(e.startswith(f"{MANIFEST}:") and message in e for e in errors), errors
    assert any(abs(e.mark.line - line) <= 2 for e in info.value.errors), (line, errors)


def test_a_broken_device_description_is_an_error_naming_the_generator(tree, capsys):
    svd_dir = tree / "hardware/electronics/firmware/stm32"
    svd_dir.mkdir(parents=True)
    text = (ROOT / "hardware/electronics/firmware/stm32/stm32g431.svd").read_text()
    (svd_dir / "stm32g431.svd").write_text(text.replace("<name>IWDG</name><baseAddress>0x40003000</baseAddress>",
                                                        "<name>IWDG</name><baseAddress>0x4000z000</baseAddress>"))
    assert main(["check", "--root", str(tree), "--only", "stm32-registers"]) == 1
    err = capsys.readouterr().err
    assert "error: stm32-registers: stm32g431.svd: IWDG.baseAddress: '0x4000z000' is not a number" in err, err
