# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""The exact least distance over many pairs of shapes, measuring in OpenCASCADE only the pairs that can still beat it.

The gap between two shapes' bounding boxes is never more than the gap between the shapes, so once the least distance
found is at most the next pair's box gap, no pair left can come closer: the answer is the same as measuring every
pair, at a fraction of the cost when most pairs stand far apart."""
import math
from typing import Iterable

import cadquery as cq
import numpy as np

from robogene_head.geom import distance, exact_bounds


class Bounds:
    """Each shape's exact bounds (lower corner, upper corner), taken once. The shapes are kept, so that the id a
    bound is filed under is never reused by another shape (a part's .shape is a new object at each access)."""

    def __init__(self):
        self._seen: dict[int, tuple[cq.Shape, tuple[np.ndarray, np.ndarray]]] = {}

    def __call__(self, shape: cq.Shape) -> tuple[np.ndarray, np.ndarray]:
        if id(shape) not in self._seen:
            self._seen[id(shape)] = (shape, exact_bounds(shape))
        return self._seen[id(shape)][1]


def box_gap(a: tuple[np.ndarray, np.ndarray], b: tuple[np.ndarray, np.ndarray]) -> float:
    """The least distance between two axis-aligned boxes, each (lower corner, upper corner); 0 where they overlap."""
    (a_lo, a_hi), (b_lo, b_hi) = a, b
    return float(np.linalg.norm(np.maximum(0.0, np.maximum(a_lo - b_hi, b_lo - a_hi))))


def least_distance(pairs: Iterable[tuple[cq.Shape, cq.Shape]], bounds: Bounds | None = None) -> float:
    """min(distance(a, b) for a, b in pairs), exactly. Pass the same `bounds` to calls that share shapes to take their
    bounds once."""
    bounds = Bounds() if bounds is None else bounds
    gaps = [(box_gap(bounds(a), bounds(b)), a, b) for a, b in pairs]
    least = math.inf
    for gap, a, b in sorted(gaps, key=lambda g: g[0]):
        if gap >= least:
            break
        least = min(least, distance(a, b))
    return least
