# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""Runs the paper's section 3.3 program (build/bin/paper_section_3_3) against a served control board
and checks what it prints: joint 0 moving towards 40 deg at 5 deg/s, joint 1 running at 5 deg/s."""
import re
import subprocess
from pathlib import Path


def run_against(robogene_bin: str, env: dict, remote: str, seconds: float) -> None:
    program = Path(robogene_bin).parent / "paper_section_3_3"
    run = subprocess.run([str(program), "--device", "remote_controlboard", "--remote", remote, "--local", "/paper",
                          "--seconds", str(seconds)], capture_output=True, text=True, env=env, timeout=30)
    assert run.returncode == 0, run.stderr
    m = re.fullmatch(r"t=(\S+) s  joint 0: +(\S+) deg  joint 1: +(\S+) deg", run.stdout.splitlines()[-1])
    assert m, run.stdout
    t, j0, j1 = (float(g) for g in m.groups())
    # 5 deg/s after a 0.05 s ramp, less one state period when remote.
    assert 5 * (t - 0.2) < j0 <= 5 * t + 1e-6, run.stdout
    assert 5 * (t - 0.2) < j1 <= 5 * t + 1e-6, run.stdout
