# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: CERN-OHL-S-2.0
"""The least distances between two polylines' pieces, every piece of one against every piece of the other, exactly
(closest points of two segments, clamped to their ends): a broad phase that samples points along the pieces measures
up to a third of a piece too far and lets through two cables that touch between the samples."""
from __future__ import annotations

import numpy as np

_TINY = 1e-12


def piece_distances(first: np.ndarray, second: np.ndarray) -> np.ndarray:
    """(n-1) x (m-1): the least distance between piece i of the polyline `first` (n x 3 points) and piece j of
    `second` (m x 3)."""
    p1, d1 = first[:-1], np.diff(first, axis=0)
    p2, d2 = second[:-1], np.diff(second, axis=0)
    r = p1[:, None, :] - p2[None, :, :]
    a = np.maximum((d1 * d1).sum(1), _TINY)[:, None]          # squared lengths; a point piece counts as very short
    e = np.maximum((d2 * d2).sum(1), _TINY)[None, :]
    b = d1 @ d2.T
    c = np.einsum("ik,ijk->ij", d1, r)
    f = np.einsum("jk,ijk->ij", d2, r)
    denom = a * e - b * b
    # the closest point on the first piece's line to the second's, clamped; parallel pieces start from its start
    s = np.where(denom > _TINY * a * e, np.clip((b * f - c * e) / np.where(denom > 0, denom, 1.0), 0.0, 1.0), 0.0)
    t = (b * s + f) / e
    # beyond the second piece's ends: clamp it there and take the first's closest point to that end again
    s = np.where(t < 0, np.clip(-c / a, 0.0, 1.0), np.where(t > 1, np.clip((b - c) / a, 0.0, 1.0), s))
    t = np.clip(t, 0.0, 1.0)
    gap = r + s[..., None] * d1[:, None, :] - t[..., None] * d2[None, :, :]
    return np.sqrt((gap * gap).sum(-1))
