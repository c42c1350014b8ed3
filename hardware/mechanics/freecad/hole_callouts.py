# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: CERN-OHL-S-2.0
"""Which hole each circle of a view is, and what its diameter dimension says about it (⌀ diameter, ↧ depth,
⌴ counterbore):

- the bore of a hole: "⌀d" through (a hole given no depth goes through), "⌀d ↧depth" blind; a tapped one "Md" or
  "Md ↧depth" (drawn at the thread's nominal diameter, so the number TechDraw measures is the thread's size);
- its counterbore: "⌴⌀D ↧depth";
- a circle that is no hole (a shaft, the outline of a round part): plain "⌀d".

Pure Python. A view shows model points at (p . across - cx, p . up - cy): TechDraw centres a view on the part's
bounding box, which it does not report exactly, so the centre is found as the one that puts the most hole
circles on circles of the view (starting from the box's centre, within SEARCH)."""
from __future__ import annotations

from collections import Counter
from dataclasses import dataclass

from hole_features import point

MATCH = 1e-3       # mm: a circle of the view is a hole's when centre and diameter agree to this
SEARCH = 0.5       # mm: how far from the box's centre the view's centre may be


@dataclass(frozen=True)
class Callout:
    symbol: str      # before the number: "⌀", "M" or "⌴⌀"
    suffix: str      # after it: " ↧8" (blind), "" (through, or no hole)
    holes: frozenset # which holes the circle stands for (holes in line along the view coincide; the count is of
                     # holes, not circles)


def number(value: float) -> str:
    """As TechDraw's %.2w prints: up to two decimals, no trailing zeros."""
    return f"{value:.2f}".rstrip("0").rstrip(".")


def callouts_of(hole) -> dict:
    """Diameter (rounded) -> (symbol, suffix) for each circle of the hole seen along its axis."""
    main = hole.main
    bore_suffix = "" if hole.through else f" ↧{number(hole.depth)}"
    out = {}
    for s in hole.segments:
        out.setdefault(round(s.d, 4), ("⌀", ""))
    for s, _ in hole.counterbores:
        out[round(s.d, 4)] = ("⌴⌀", f" ↧{number(s.hi - s.lo)}")
    out[round(main.d, 4)] = ("M" if hole.thread else "⌀", bore_suffix)
    return out


def _project(hole, across: tuple, up: tuple) -> tuple:
    p = point(hole.axis, hole.u, hole.v, 0.0)
    return (sum(a * b for a, b in zip(p, across)), sum(a * b for a, b in zip(p, up)))


def label(circles: list, holes: list, depth_axis: int, across: tuple, up: tuple, box_centre: tuple) -> dict:
    """circles: the view's full circles (edge, x, y, r); holes: hole_features.Hole. Returns edge -> [Callout] for
    the circles that are holes seen along their axis (the view looks along model axis depth_axis): one per
    callout, as holes in line behind each other may differ."""
    seen = [(i, h) for i, h in enumerate(holes) if h.axis == depth_axis]
    if not seen or not circles:
        return {}
    centre0 = (sum(a * b for a, b in zip(box_centre, across)), sum(a * b for a, b in zip(box_centre, up)))
    projected = {i: _project(h, across, up) for i, h in seen}
    votes = Counter()
    for c in circles:
        for i, h in seen:
            if any(abs(2 * c.r - s.d) < MATCH for s in h.segments):
                cx, cy = projected[i][0] - c.x, projected[i][1] - c.y
                if abs(cx - centre0[0]) <= SEARCH and abs(cy - centre0[1]) <= SEARCH:
                    votes[(round(cx, 3), round(cy, 3))] += 1
    if not votes:
        return {}
    cx, cy = votes.most_common(1)[0][0]
    out = {}
    for c in circles:
        kinds: dict = {}
        for i, h in seen:
            x, y = projected[i][0] - cx, projected[i][1] - cy
            if abs(x - c.x) > 2 * MATCH or abs(y - c.y) > 2 * MATCH:
                continue
            kind = next((v for d, v in callouts_of(h).items() if abs(d - 2 * c.r) < MATCH), None)
            if kind is not None:
                kinds.setdefault(kind, set()).add(i)
        if kinds:
            out[c.edge] = [Callout(k[0], k[1], frozenset(ids)) for k, ids in sorted(kinds.items())]
    return out
