# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""Which committed YARP vectors travel as one line through `write`/`read`, and a readable comparison."""
from __future__ import annotations


def line_cases(vectors: list[dict]) -> list[dict]:
    """Well-formed, non-empty, single-line texts (malformed ones we may reject on purpose)."""
    return [v for v in vectors
            if not v["name"].startswith("malformed_") and v["text"].strip() and "\n" not in v["text"]]


def by_name(vectors: list[dict], names: list[str]) -> list[dict]:
    table = {v["name"]: v for v in vectors}
    return [table[n] for n in names]


def assert_same_lines(cases: list[dict], got: list[str], how: str) -> None:
    want = [c["canonical_text"] for c in cases]
    if got[:len(want)] == want and len(got) == len(want):
        return
    problems = []
    for i, case in enumerate(cases):
        line = got[i] if i < len(got) else "<missing>"
        if line != case["canonical_text"]:
            problems.append(f"  {case['name']}: sent {case['text']!r}\n     want {case['canonical_text']!r}\n"
                            f"     got  {line!r}")
    extra = got[len(want):]
    raise AssertionError(f"{how}: {len(problems)} of {len(cases)} bottles differ"
                         + (f", {len(extra)} unexpected extra lines {extra[:5]!r}" if extra else "")
                         + "\n" + "\n".join(problems))
