import numpy as np
import pytest

from models.uncertainty.iso230 import iso230_evaluate


def test_hand_computed_example():
    positions = np.array([0, 10, 0, 10, 0, 10, 0, 10], dtype=float)
    directions = np.array([1, 1, 1, 1, -1, -1, -1, -1])
    deviations = np.array([1.0, 2.0, 3.0, 2.0, 0.0, -1.0, 0.0, -1.0])
    result = iso230_evaluate(positions, deviations, directions)
    np.testing.assert_allclose(result.forward.mean, [2.0, 2.0])
    np.testing.assert_allclose(result.backward.mean, [0.0, -1.0])
    np.testing.assert_allclose(result.forward.std, [np.sqrt(2), 0.0])
    np.testing.assert_allclose(result.reversal, [2.0, 3.0])
    f = result.figures
    assert f["E_up"] == 0.0
    assert f["E"] == 3.0
    assert f["M"] == pytest.approx(0.5)
    assert f["B"] == 3.0
    assert f["R_up"] == pytest.approx(4 * np.sqrt(2))
    assert f["R"] == pytest.approx(max(2 * np.sqrt(2) + 2.0, 3.0, 4 * np.sqrt(2)))
    assert f["A"] == pytest.approx((2 + 2 * np.sqrt(2)) - (-1.0))


def test_unidirectional_only():
    result = iso230_evaluate([0, 1, 0, 1], [1.0, 2.0, 1.5, 2.5])
    assert result.backward is None and "B" not in result.figures
    assert result.figures["E_up"] == pytest.approx(1.0)
