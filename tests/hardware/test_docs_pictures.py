# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""The docs' pictures are the package's (docs/images/pictures.yaml): each still looks like what the package renders,
so a design change cannot leave an old picture in docs/fabricate.md (one stood there for a session, drawn before
the pitch bearing moved). `make docs-pictures` refreshes them."""
import json
import re
from pathlib import Path

import numpy as np
import pytest
from PIL import Image

from robogene_head import docs_pictures as dp

REPO = Path(__file__).resolve().parents[2]
IMAGES = REPO / "docs" / "images"
ENTRIES = dp.load(IMAGES / "pictures.yaml")


@pytest.mark.parametrize("name", sorted(ENTRIES))
def test_docs_picture_is_the_packages(fab, name):
    share = dp.changed_share(IMAGES / name, dp.source(fab, ENTRIES[name]))
    assert share <= dp.MAX_CHANGED, (f"docs/images/{name} differs from the package's in {share:.1%} of its pixels: "
                                     f"run `make docs-pictures` and look at the pictures before committing them")


def test_every_listed_picture_is_in_the_docs():
    text = "".join(p.read_text() for p in (REPO / "docs").glob("*.md"))
    used = set(re.findall(r"\]\(images/([^)]+\.png)\)", text))
    assert set(ENTRIES) <= used, sorted(set(ENTRIES) - used)


def test_a_neighbouring_steps_picture_counts_as_stale(fab):
    """Each step's picture against the one before it (other parts highlighted, one step less built) fails."""
    steps = [e["step"] for e in ENTRIES.values() if "step" in e]
    assert steps
    for ref in steps:
        here = dp.step_picture(fab, ref)
        index = int(here.name.split("-")[0])
        before = sorted(here.parent.glob(f"{index - 1:02d}-*.png"))
        assert len(before) == 1, before
        assert dp.changed_share(here, before[0]) > dp.MAX_CHANGED, (ref, before[0].name)


def test_render_noise_passes_and_a_moved_picture_fails(fab, tmp_path):
    """What two renders of one model differ by (a few levels everywhere, anti-aliased edges) passes; the same
    picture with everything 8 px to the side, as after a part moved, fails."""
    src = dp.source(fab, ENTRIES["head-front-3q.png"])
    pixels = np.asarray(Image.open(src).convert("RGB"), dtype=np.int16)
    rng = np.random.default_rng(0)
    noisy = np.clip(pixels + rng.integers(-12, 13, pixels.shape), 0, 255).astype(np.uint8)
    Image.fromarray(noisy).save(tmp_path / "noisy.png")
    assert dp.changed_share(src, tmp_path / "noisy.png") <= dp.MAX_CHANGED
    Image.fromarray(np.roll(pixels, 8, axis=1).astype(np.uint8)).save(tmp_path / "moved.png")
    assert dp.changed_share(src, tmp_path / "moved.png") > dp.MAX_CHANGED
    Image.fromarray(pixels[:-2].astype(np.uint8)).save(tmp_path / "cropped.png")
    assert dp.changed_share(src, tmp_path / "cropped.png") == 1.0


def test_an_unknown_step_is_named(fab, tmp_path):
    with pytest.raises(dp.PictureError, match="no such step"):
        dp.step_picture(fab, "main: a step nobody wrote")
    with pytest.raises(dp.PictureError, match="<context>: <name>"):
        dp.step_picture(fab, "no context here")
    bad = tmp_path / "pictures.yaml"
    bad.write_text("x.png: {render: a.png, step: 'main: b'}\n")
    with pytest.raises(dp.PictureError, match="x.png: expected exactly one"):
        dp.load(bad)


def test_the_assembly_report_names_each_steps_picture(fab):
    """The report, not a second parser of its labels, says which picture is a step's: each one it names is drawn,
    and every drawn step is named once."""
    steps = json.loads((fab / "reports" / "assembly.json").read_text())["steps"]
    named = [s["picture"] for s in steps]
    drawn = sorted(p.name for p in (fab / "assembly" / "steps").glob("*.png"))
    assert sorted(named) == drawn
    first = steps[0]
    assert dp.step_picture(fab, f"{first['context']}: {first['name']}").name == first["picture"]


def test_a_report_from_an_older_build_is_named(tmp_path):
    (tmp_path / "reports").mkdir()
    (tmp_path / "reports" / "assembly.json").write_text(json.dumps(
        {"steps": [{"step": "step 1 'base'", "context": "main"}]}))
    with pytest.raises(dp.PictureError, match="run make fab"):
        dp.step_picture(tmp_path, "main: base")
