"""Cross-calibration model (issue #33, model core): round trips on an exact rig, the full
rosette's closed form, Monte Carlo coverage of U, and bad input refused naming the row."""

from __future__ import annotations

import ast
import math
from pathlib import Path

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from models.crosscal.solve import CrossCalibrationInputError, solve_crosscal
from models.validation.crosscal_rig import CrossCalRig

HARMONICS = {1: (2.0, 0.3), 2: (1.0, 1.1), 3: (0.5, 2.0), 4: (0.2, 0.7), 6: (0.3, 0.5)}


def _rig(n: int, seed: int, **kw) -> CrossCalRig:
    dev = np.random.default_rng(100 + seed).normal(0.0, 1.5, n)
    harmonics = {h: v for h, v in HARMONICS.items() if h <= n // 2}
    return CrossCalRig(n, harmonics, dev, rng=np.random.default_rng(seed), **kw)


def _solve(rows, n, **kw):
    j, i, a, c = (np.array(col) for col in zip(*rows, strict=True))
    return solve_crosscal(j, i, a, c, faces=n, **kw)


def _without(values: np.ndarray, orders) -> np.ndarray:
    """The test's own harmonic filter (FFT): ``values`` with harmonic orders removed."""
    spectrum = np.fft.fft(values)
    n = values.size
    for h in orders:
        spectrum[h % n] = 0.0
        spectrum[-h % n] = 0.0
    return np.fft.ifft(spectrum).real


def test_rig_imports_nothing_from_the_code_it_checks():
    path = Path(__file__).resolve().parents[3] / "models" / "validation" / "crosscal_rig.py"
    for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
        if isinstance(node, ast.ImportFrom | ast.Import):
            module = node.module if isinstance(node, ast.ImportFrom) else node.names[0].name
            assert module in ("__future__", "dataclasses", "numpy", "models.validation.rotation"), module


@pytest.mark.parametrize(("mountings", "tol"), [(list(range(12)), 0.002), ([0, 1, 5], 0.006),
                                             ([0, 2, 7], 0.006), ([3, 4], 0.01)])
@pytest.mark.parametrize("stops", [True, False])
def test_round_trip_noise_free(mountings, tol, stops):
    """Mounting errors ±20″, stops ±15″, drift ±0.5″ per mounting, the polygon seated with
    a tilt up to 60″: E and d recovered within a few milli-arcseconds. What is left is
    physics the linear model leaves out: the encoder's error moves (≤ 0.0016″ here) between
    its step and where the shaft stopped, and a tilt ψ turns each face's azimuth by up to
    ψ²/4 rad (0.002″ at 60″), differently in each mounting; partial rosettes amplify both.
    With no tilt, no mounting error and exact stops the shaft stops within a face deviation
    (″) of its step, and the round trip is exact to 0.3 mas."""
    extra = {"tilt_arcsec": 60.0} if stops else {"mounting_error_arcsec": 0.0, "stop_arcsec": 0.0}
    rig = _rig(12, 1, drift_arcsec=0.5, **extra)
    result = _solve(rig.rows(mountings), 12, noise_arcsec=0.01)
    true_e, true_d = rig.truth()
    assert result.separable
    tol = tol if stops else 3e-4
    assert np.abs(result.encoder_error_arcsec - true_e).max() < tol
    assert np.abs(result.polygon_deviation_arcsec - true_d).max() < tol
    assert np.all(np.isfinite(result.drift_arcsec))
    assert np.ptp(true_e) > 4.0 and np.ptp(true_d) > 3.0  # the check is not trivial


def test_drift_is_reported_as_the_autocollimators():
    """An autocollimator whose zero drifted by D over a mounting gives drift D, the polygon
    workbench's (c′ − c) − (a′ − a); a mounting without its closure reading has its drift
    fitted through the others' (their closure readings fix the encoder's error over the turn,
    and the mounting's readings against it show its drift), the same drift."""
    rig = _rig(12, 7, drift_arcsec=2.0)
    rows = rig.rows([0, 1, 5])
    result = _solve(rows, 12, noise_arcsec=0.01)
    np.testing.assert_allclose(result.drift_arcsec, rig.drifts_arcsec, atol=0.003)
    assert np.abs(rig.drifts_arcsec).min() > 0.5  # drift of either sign would show
    no_closure = [r for q, r in enumerate(rows) if q != 12]  # mounting 0 ends without one
    result = _solve(no_closure, 12, noise_arcsec=0.01)
    np.testing.assert_allclose(result.drift_arcsec, rig.drifts_arcsec, atol=0.01)
    assert np.isnan(result.closure_drift_arcsec[0])  # not measured: fitted
    assert any("fitted through the other mountings' closure readings" in w for w in result.warnings)


def test_round_trip_with_noise_within_its_uncertainty():
    rig = _rig(12, 2, drift_arcsec=0.5, noise_arcsec=0.05)
    result = _solve(rig.rows([0, 1, 5]), 12)
    true_e, true_d = rig.truth()
    assert 0.03 < result.sigma_arcsec < 0.08
    assert result.dof == 36 + 3 - (12 + 12 + 3 + 3 - 2)
    z_e = (result.encoder_error_arcsec - true_e) / result.encoder_error_u_arcsec
    z_d = (result.polygon_deviation_arcsec - true_d) / result.polygon_deviation_u_arcsec
    assert np.abs(z_e).max() < 4.0 and np.abs(z_d).max() < 4.0
    # a partial rosette correlates the two result sets; their covariance is stated
    assert np.abs(result.correlation[:12, 12:]).max() > 0.1


@pytest.mark.parametrize(("n", "mountings", "unseen"), [
    (12, [0, 4, 8], (3, 6)), (12, [0, 6], (2, 4, 6)), (12, [2, 5, 8, 11], (4,)), (9, [0, 3, 6], (3,)),
    (24, [0, 8, 16], (3, 6, 9, 12))])
def test_design_that_cannot_separate_names_the_harmonics_and_reports_none(n, mountings, unseen):
    """Mountings all a multiple of g faces apart (g | n) leave the harmonics h with
    h·g ≡ 0 (mod n) unseen: 0,4,8 of 12 -> 3 and 6. The values are withheld; the part made
    of the seen harmonics is recovered."""
    rig = _rig(n, 3, drift_arcsec=0.3)
    result = _solve(rig.rows(mountings), n, noise_arcsec=0.01)
    assert result.undetermined_encoder_harmonics == unseen
    assert result.undetermined_polygon_harmonics == unseen
    assert result.encoder_error_arcsec is None and result.polygon_deviation_arcsec is None
    assert not result.separable
    true_e, true_d = rig.truth()
    assert np.abs(result.encoder_error_determined_arcsec - _without(true_e, unseen)).max() < 0.002
    assert np.abs(result.polygon_deviation_determined_arcsec - _without(true_d, unseen)).max() < 0.002
    assert np.all(np.isfinite(result.encoder_error_u_arcsec))


@settings(max_examples=25, deadline=None)
@given(st.integers(4, 16).flatmap(lambda n: st.tuples(
    st.just(n), st.lists(st.integers(0, n - 1), min_size=2, max_size=4, unique=True),
    st.booleans(), st.integers(0, 10_000))))
def test_unseen_harmonics_follow_the_mountings_spacing(case):
    """Whatever the mountings (in any order, with or without closure readings), the
    harmonics withheld are exactly those with h·g ≡ 0 (mod n), g = gcd(n, the mountings'
    differences): E_k = f(k), d_i = −f(i − 1 − j) fits every mounting iff f has period g."""
    n, mountings, closure, seed = case
    g = math.gcd(n, *(j - mountings[0] for j in mountings[1:]))
    expected = tuple(h for h in range(1, n // 2 + 1) if h * g % n == 0)
    # without its closure reading a mounting's drift is not modelled (it would pass into E)
    rig = _rig(n, seed, drift_arcsec=0.3 if closure else 0.0, noise_arcsec=0.01)
    result = _solve(rig.rows(mountings, closure=closure), n, noise_arcsec=0.01)
    assert result.undetermined_encoder_harmonics == expected
    assert result.undetermined_polygon_harmonics == expected
    assert (result.encoder_error_arcsec is None) == bool(expected)
    true_e, true_d = rig.truth()
    miss_e = np.abs(result.encoder_error_determined_arcsec - _without(true_e, expected))
    miss_d = np.abs(result.polygon_deviation_determined_arcsec - _without(true_d, expected))
    # within 5 u, plus the encoder's error between step and stop amplified by a thin design
    assert np.all(miss_e < 5 * result.encoder_error_u_arcsec + 0.02)
    assert np.all(miss_d < 5 * result.polygon_deviation_u_arcsec + 0.02)


def test_full_rosette_closed_form():
    """Full rosette (m = n mountings, every face at every step once), one reading per cell,
    equal σ, no drift term: the design is a Latin square (step k, face i, mounting j, any two
    fix the third), orthogonal, so with Σ E = Σ d = 0 the estimates are
    Ê_k = ȳ(step k) − ȳ and d̂_i = ȳ(face i) − ȳ. Hence

        u²(Ê_k) = u²(d̂_i) = σ²/n − σ²/n² = σ²·(n − 1)/n²,
        cov(Ê_k, Ê_l) = cov(d̂_i, d̂_l) = −σ²/n² (k ≠ l),   cov(Ê_k, d̂_i) = 0,
        ν = n² − (3(n − 1) + 1) = (n − 1)(n − 2),

    Estler's closure result for the simple (full) rosette, derived here from the design."""
    n, sigma = 24, 0.02
    rig = _rig(n, 4, noise_arcsec=sigma)
    rows = rig.rows(range(n), closure=False)
    result = _solve(rows, n, noise_arcsec=sigma)
    cov = result.covariance_arcsec2
    expected = np.block([[np.eye(n) * sigma**2 / n - sigma**2 / n**2, np.zeros((n, n))],
                         [np.zeros((n, n)), np.eye(n) * sigma**2 / n - sigma**2 / n**2]])
    np.testing.assert_allclose(cov, expected, atol=1e-14)
    np.testing.assert_allclose(result.encoder_error_u_arcsec, sigma * np.sqrt(n - 1) / n, rtol=1e-10)
    assert result.coverage_factor == pytest.approx(2.0)
    # U(k=2) = 2·0.02·√23/24 = 0.0080″, within the 0.02″ target for 24 faces
    assert result.encoder_error_expanded_arcsec.max() == pytest.approx(0.00799305, rel=1e-5)
    free = _solve(rows, n)
    assert free.dof == (n - 1) * (n - 2)
    assert free.sigma_arcsec == pytest.approx(sigma, rel=0.1)


@pytest.mark.slow
def test_monte_carlo_coverage_of_the_expanded_uncertainty():
    """400 seeded runs of a partial rosette (n = 6, mountings 0, 1, 3 with closure and drift):
    σ from the residuals (ν = 5), k from ν; U covers the truth 95.45 % ± 3 %."""
    n, hits, total = 6, 0, 0
    for seed in range(400):
        rig = _rig(n, 1000 + seed, drift_arcsec=0.5, noise_arcsec=0.2)
        result = _solve(rig.rows([0, 1, 3]), n)
        true_e, true_d = rig.truth()
        miss_e = np.abs(result.encoder_error_arcsec - true_e)
        miss_d = np.abs(result.polygon_deviation_arcsec - true_d)
        hits += int(np.sum(miss_e <= result.encoder_error_expanded_arcsec)
                    + np.sum(miss_d <= result.polygon_deviation_expanded_arcsec))
        total += 2 * n
    assert result.dof == 5
    assert abs(hits / total - 0.9545) <= 0.03, hits / total


def _good_rows():
    return [list(r) for r in _rig(6, 5, noise_arcsec=0.02).rows([0, 1, 3])]


def _refused(rows, n=6, **kw):
    with pytest.raises(CrossCalibrationInputError) as caught:
        _solve(rows, n, **kw)
    return caught.value


def test_bad_input_is_refused_naming_the_row():
    rows = _good_rows()  # 7 rows per mounting (6 faces + closure)
    dup = [r[:] for r in rows]
    dup[9][1] = dup[8][1]  # row 10 repeats row 9's face in mounting 1
    err = _refused(dup)
    assert err.row == 10 and "row 10" in str(err) and "duplicate" in str(err)

    missing = [r for q, r in enumerate(rows) if q != 16]  # mounting 3 loses a face
    err = _refused(missing)
    assert "mounting 3" in str(err) and "missing" in str(err)

    err = _refused([r for r in rows if r[0] == 0])
    assert "not connected" in str(err)

    shifted = [r[:] for r in rows]
    for r in shifted[7:14]:
        r[0] = 2  # mounting 1's readings labelled as mounting 2
    err = _refused(shifted)
    assert err.row == 8 and "starts elsewhere" in str(err)

    wrong_face = [r[:] for r in rows]
    wrong_face[3][1] = 7
    err = _refused(wrong_face)
    assert err.row == 4 and "face 7" in str(err)

    nan = [r[:] for r in rows]
    nan[5][3] = float("nan")
    assert _refused(nan).row == 6


def test_no_redundancy_is_refused_without_a_stated_sigma():
    rig = _rig(6, 6)
    err = _refused(rig.rows([0, 1], closure=False))
    assert "none left over" in str(err)
    result = _solve(rig.rows([0, 1], closure=False), 6, noise_arcsec=0.02)
    assert result.separable


def test_signs_agree_with_the_polygon_workbench():
    """Mounting 0 analysed by the polygon workbench's equation with the deviations found
    here as its certificate gives the encoder errors found here, about face 1: the two
    workbenches state the same errors of indication and the same face deviations."""
    from models.polygon.model import face_errors_arcsec

    n = 12
    rig = _rig(n, 8, noise_arcsec=0.0)
    rows = rig.rows([0, 1, 5], closure=False)
    result = _solve(rows, n, noise_arcsec=0.01)
    _, face, a, c = (np.array(col) for col in zip(*rows[:n], strict=True))
    dev = result.polygon_deviation_arcsec[face - 1]
    nominal = (face - 1) * 360.0 / n
    errors = face_errors_arcsec(a, dev, c, nominal, zero=(a[0], nominal[0], dev[0], c[0]))
    expected = result.encoder_error_arcsec - result.encoder_error_arcsec[0]
    np.testing.assert_allclose(errors, expected, atol=0.003)
    assert np.ptp(expected) > 4.0
