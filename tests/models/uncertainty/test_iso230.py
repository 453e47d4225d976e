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


def test_a_and_r_need_every_targets_s():
    """A target approached once has no s: A and R of its direction are not evaluated (an
    envelope of the other targets alone fell below E, #41 item 6); E still is."""
    positions = [0, 10, 20, 20]
    deviations = [0.0, 2.5, 1.0, 1.05]
    result = iso230_evaluate(positions, deviations)
    assert result.figures["E_up"] == pytest.approx(2.5)
    assert "A_up" not in result.figures and "R_up" not in result.figures
    np.testing.assert_allclose(result.approached_once["up"], [0, 10])
    both = iso230_evaluate([0, 10, 0, 10, 0, 0, 10], [0.0, 2.0, 0.1, 2.2, 1.0, 1.2, 3.0],
                           [1, 1, 1, 1, -1, -1, -1])
    assert "A_up" in both.figures and both.figures["A_up"] >= both.figures["E_up"]
    assert "A" not in both.figures and "R" not in both.figures  # 10 approached once down
    assert "A_down" not in both.figures and "B" in both.figures
