# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: CERN-OHL-S-2.0
"""The docs' copies of the package's pictures (docs/images/pictures.yaml): where each comes from in a built package,
how far a copy has drifted from it, and the copying (python -m robogene_head.docs_pictures --fab DIR --docs DIR).

The comparison tolerates what differs between two renders of the same model (anti-aliasing on edges, a different
OpenGL build) and catches a part that moved: it counts the pixels whose colour differs by more than CHANNEL_STEP
in any channel."""
from __future__ import annotations

import argparse
import json
import shutil
import sys
from pathlib import Path

import numpy as np
import yaml
from PIL import Image

from robogene_head_model import strict_yaml

CHANNEL_STEP = 48          # of 255: well above rendering noise, well below a part's colour against the background
MAX_CHANGED = 0.01         # the share of changed pixels a copy may have and still count as the package's picture


class PictureError(ValueError):
    """A pictures.yaml entry that names nothing the package has."""


def load(path: Path) -> dict[str, dict[str, str]]:
    try:
        data = strict_yaml.load(path.read_text(encoding="utf-8"))
    except yaml.MarkedYAMLError as exc:
        mark = exc.problem_mark
        raise PictureError(f"{path}:{mark.line + 1 if mark else '?'}: YAML error: {exc.problem}") from None
    if not isinstance(data, dict):
        raise PictureError(f"{path}: expected a mapping of picture file names to their sources")
    for name, entry in data.items():
        if not isinstance(entry, dict) or len(entry) != 1 or not set(entry) <= {"render", "step", "harness"}:
            raise PictureError(f"{path}: {name}: expected exactly one of render:, step: or harness:")
    return data


def step_picture(fab: Path, ref: str) -> Path:
    """The package's picture of the step `<context>: <name>`, as the assembly check's report names it."""
    context, sep, name = ref.partition(": ")
    if not sep:
        raise PictureError(f"step {ref!r}: expected '<context>: <name>'")
    report = fab / "reports" / "assembly.json"
    for step in json.loads(report.read_text())["steps"]:
        if "picture" not in step:
            raise PictureError(f"{report}: its steps name no pictures (written by an older build): run make fab")
        if step["context"] == context and step["name"] == name:
            return fab / "assembly" / "steps" / step["picture"]
    raise PictureError(f"step {ref!r}: no such step in {report}")


def source(fab: Path, entry: dict[str, str]) -> Path:
    if "render" in entry:
        return fab / "renders" / entry["render"]
    if "harness" in entry:
        return fab / "harness" / entry["harness"]
    return step_picture(fab, entry["step"])


def changed_share(a: Path, b: Path) -> float:
    """The share of pixels that differ visibly between two pictures (1 when their sizes differ)."""
    pa, pb = (np.asarray(Image.open(p).convert("RGB"), dtype=np.int16) for p in (a, b))
    if pa.shape != pb.shape:
        return 1.0
    return float(np.mean(np.abs(pa - pb).max(axis=2) > CHANNEL_STEP))


def copy_all(fab: Path, docs: Path) -> list[Path]:
    out = []
    for name, entry in load(docs / "pictures.yaml").items():
        src = source(fab, entry)
        if not src.is_file():
            raise PictureError(f"{name}: {src} is not in the package: build it first (make fab)")
        shutil.copyfile(src, docs / name)
        out.append(docs / name)
    return out


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--fab", type=Path, required=True)
    ap.add_argument("--docs", type=Path, required=True, help="docs/images, with its pictures.yaml")
    args = ap.parse_args(argv)
    try:
        for path in copy_all(args.fab, args.docs):
            print(f"copied {path}")
    except (PictureError, OSError) as exc:
        print(f"docs_pictures: {exc}", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
