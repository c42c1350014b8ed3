# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""The crossing check's broad phase measures the cables' centre lines piece against piece exactly
(harness/segments.py): against dense sampling on random polylines, on the special cases (parallel, touching at an
end, a point-long piece), and where the four points per piece it sampled before measured two pieces that pass
0.5 mm apart as 0.87 mm apart: two cables of 0.35 mm radius would touch there and never be looked at again."""
import numpy as np
import pytest

from robogene_head.harness.segments import piece_distances


def _dense(first, second, n=401):
    t = np.linspace(0, 1, n)[:, None]
    out = np.empty((len(first) - 1, len(second) - 1))
    for i in range(len(first) - 1):
        a = first[i] + t * (first[i + 1] - first[i])
        for j in range(len(second) - 1):
            b = second[j] + t * (second[j + 1] - second[j])
            out[i, j] = np.sqrt(((a[:, None] - b[None]) ** 2).sum(-1)).min()
    return out


def test_random_polylines_match_dense_sampling():
    rng = np.random.default_rng(7)
    for _ in range(20):
        first, second = rng.normal(size=(5, 3)) * 10, rng.normal(size=(4, 3)) * 10
        exact, dense = piece_distances(first, second), _dense(first, second)
        # exact is the least distance: never above the samples', and within the samples' spacing of it
        assert np.all(exact <= dense + 1e-9)
        assert exact == pytest.approx(dense, abs=0.2)


def test_special_cases():
    line = np.array([[0.0, 0, 0], [10, 0, 0]])
    parallel = np.array([[2.0, 3, 0], [8, 3, 0]])
    assert piece_distances(line, parallel)[0, 0] == pytest.approx(3.0)
    beyond = np.array([[13.0, 4, 0], [20, 4, 0]])                     # parallel, past the first's end
    assert piece_distances(line, beyond)[0, 0] == pytest.approx(5.0)
    touching = np.array([[10.0, 0, 0], [10, 5, 0]])
    assert piece_distances(line, touching)[0, 0] == pytest.approx(0.0, abs=1e-12)
    point = np.array([[5.0, 2, 0], [5.0, 2, 0]])
    assert piece_distances(line, point)[0, 0] == pytest.approx(2.0)


def test_two_pieces_passing_between_the_old_samples():
    # 3 mm pieces crossing at right angles 0.5 mm apart, where neither has a sample (1/6 of the way along each)
    first = np.array([[-0.5, 0, 0], [2.5, 0, 0]])
    second = np.array([[0, -0.5, 0.5], [0, 2.5, 0.5]])
    t = np.linspace(0, 1, 4)[:, None]
    sampled = np.sqrt((((first[0] + t * (first[1] - first[0]))[:, None]
                        - (second[0] + t * (second[1] - second[0]))[None]) ** 2).sum(-1)).min()
    assert sampled == pytest.approx(np.sqrt(3 * 0.5 ** 2), abs=1e-9)      # 0.87, over 0.35 + 0.35
    assert piece_distances(first, second)[0, 0] == pytest.approx(0.5)     # under it: they touch
