# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""least_distance (the tests' pruned search for the closest of many pairs) gives what measuring every pair gives,
also where the pair whose boxes are closest is not the closest pair."""
import math

import cadquery as cq
import numpy as np
import pytest

from robogene_head.geom import box, cyl, distance, exact_bounds

from least_distance import box_gap, least_distance


def _box(lo, hi):
    return np.array(lo, dtype=float), np.array(hi, dtype=float)


def test_box_gap_is_the_gap_between_boxes():
    unit = _box([0, 0, 0], [1, 1, 1])
    assert box_gap(unit, _box([4, 0, 0], [5, 1, 1])) == pytest.approx(3)
    assert box_gap(unit, _box([4, 5, 0], [5, 6, 1])) == pytest.approx(5)      # 3 and 4 apart: 5 corner to corner
    assert box_gap(_box([4, 5, 0], [5, 6, 1]), unit) == pytest.approx(5)
    assert box_gap(unit, _box([0.5, 0.5, 0.5], [2, 2, 2])) == 0


def test_the_closest_pair_is_found_where_its_boxes_are_not_the_closest():
    # A rod across the diagonal x + y = 42: its box comes within 1.65 mm of the block, the rod itself 15 mm; a cube
    # 3 mm off the block is the closest pair, though its boxes rank second; a post 10 mm off ranks last.
    block = box(0, 10, 0, 10, 0, 10)
    rod = cq.Solid.makeCylinder(0.5, 30 * math.sqrt(2), cq.Vector(12, 30, 5), cq.Vector(1, -1, 0))
    cube = box(13, 15, 0, 2, 0, 2)
    post = cyl("z", 1, 0, 10, at=(-8, -8))
    pairs = [(block, rod), (block, cube), (block, post)]
    assert box_gap(*_bounds(block, rod)) < box_gap(*_bounds(block, cube)) < box_gap(*_bounds(block, post))
    every = min(distance(a, b) for a, b in pairs)
    assert every == pytest.approx(3)
    assert least_distance(pairs) == every
    assert least_distance(list(reversed(pairs))) == every
    assert least_distance([(block, rod), (block, post)]) == pytest.approx(min(distance(block, rod), distance(block, post)))


def _bounds(*shapes):
    return [exact_bounds(s) for s in shapes]


def test_touching_shapes_are_zero_apart():
    block = box(0, 10, 0, 10, 0, 10)
    assert least_distance([(block, box(20, 22, 0, 2, 0, 2)), (block, box(10, 12, 0, 2, 0, 2))]) == pytest.approx(0)
