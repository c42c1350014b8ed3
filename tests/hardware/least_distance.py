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


def box_gap(a: tuple[np.ndarray, np.ndarray], b: tuple[np.ndarray, np.ndarray]) -> float:
    """The least distance between two axis-aligned boxes, each (lower corner, upper corner); 0 where they overlap."""
    (a_lo, a_hi), (b_lo, b_hi) = a, b
    return float(np.linalg.norm(np.maximum(0.0, np.maximum(a_lo - b_hi, b_lo - a_hi))))


def least_distance(pairs: Iterable[tuple[cq.Shape, cq.Shape]]) -> float:
    """min(distance(a, b) for a, b in pairs), exactly; each shape's bounds are taken once, however many pairs it is in."""
    bounds: dict[int, tuple[np.ndarray, np.ndarray]] = {}

    def bounds_of(shape: cq.Shape):
        if id(shape) not in bounds:
            bounds[id(shape)] = exact_bounds(shape)
        return bounds[id(shape)]

    pairs = list(pairs)
    ranked = sorted(range(len(pairs)), key=lambda i: box_gap(bounds_of(pairs[i][0]), bounds_of(pairs[i][1])))
    least = math.inf
    for i in ranked:
        a, b = pairs[i]
        if box_gap(bounds_of(a), bounds_of(b)) >= least:
            break
        least = min(least, distance(a, b))
    return least
