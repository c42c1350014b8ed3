# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""The committed tests/vectors/yarp3_*.json are what the YARP peer produces today: regenerating
them into a temp dir gives identical files (so they were neither hand-edited nor left stale)."""
import pytest

from interop_peer import ROOT, yarp_python
from interop_procs import run

pytestmark = pytest.mark.timeout(120)


def test_regenerated_vectors_equal_the_committed_ones(tmp_path):
    done = run([yarp_python(), str(ROOT / "tests" / "interop" / "gen_yarp3_vectors.py"), str(tmp_path)],
               env=None, timeout=90)
    assert done.returncode == 0, done.stderr.decode()
    for name in ("yarp3_bottles.json", "yarp3_typed_values.json"):
        assert (tmp_path / name).read_text() == (ROOT / "tests" / "vectors" / name).read_text(), name
