"""The reference standard's errors in the figures' intervals: within their U at every target,
whatever their shape, a bias of at most their range on a largest value less a smallest one
(#39's widths, audit 68 §2./5.: E, M, A and the decided quantity 2.1–4.7 times the oracle with
a stated standard).

A once-a-turn error or one shaped as the curve moves E, M and A by up to its range: k · 2u
for a standard stated per reading (each target within k·u, two of them opposite), k · u for
one stated for any angle (the difference of two targets' errors is one more angle). Until
then the widening was a union bound, z(1 − tail/2) · pair on the readings' interval at half
the tail (z = 2.28 at 95.45 %); now the readings' own interval at the probability is moved
out by k · pair (k = 2), as the theodolite takes its circle error.

The readings are simulated here from first principles (numpy only): a rotary axis with an
error curve and a reversal, 5 runs each way with new noise at every approach, and the
reference's own error at each target, the same in every run and both directions, shaped as
the axis's curve at the largest range its statement allows (against the curve: it flattens
the measured curve and lowers E; with it: it raises E). The truth is the axis's E.
"""

from __future__ import annotations

import numpy as np
import pytest
from scipy.special import ndtri
from scipy.stats import binom

from models.certificate.metadata import CertificateMetadata
from models.positioning.analysis import POSITIONING
from models.positioning.report import figure_uncertainties, positioning_budget
from models.readings.sheet import ReadingsSheet

TARGETS = np.arange(0.0, 361.0, 30.0)
U = 1.0  # the reference's stated U (k = 2), arcsec


def _axis(rng: np.random.Generator) -> tuple[np.ndarray, float]:
    """The axis's error at each target (a smooth curve of random phase, about 3″ rms) and
    its reversal."""
    t = np.radians(TARGETS)
    curve = (3.0 * np.sin(t + rng.uniform(0, 2 * np.pi))
             + 1.5 * np.sin(2 * t + rng.uniform(0, 2 * np.pi)))
    return curve, 2.0


def _rows(rng, curve, reversal, sigma, reference) -> list[list[str]]:
    """5 runs forward and backward; each approach's deviation is the axis's, new noise, and
    the reference's error at that target."""
    rows = []
    for run in range(1, 6):
        for sign, order in ((+1, range(TARGETS.size)), (-1, range(TARGETS.size - 1, -1, -1))):
            for i in order:
                x = (curve[i] + 0.5 * sign * reversal + sigma * rng.standard_normal()
                     + reference[i])
                rows.append([f"{TARGETS[i]:g}", str(run), "+" if sign > 0 else "-",
                             f"{x:.4f}", ""])
    return rows


def _metadata(per: str | None) -> CertificateMetadata:
    if per is None:
        return CertificateMetadata()
    return CertificateMetadata.from_dict({"standards": [{
        "description": "Laser rotary calibrator", "uncertainty": U,
        "uncertainty_unit": "arcsec", "basis": "U95", "applies_to": per}]})


def _intervals(rows, per):
    result = POSITIONING.analyze(ReadingsSheet(POSITIONING.columns, rows).parse(), {})
    return figure_uncertainties(result, positioning_budget(result, _metadata(per)))


@pytest.mark.parametrize("per, pair", [("angle", 0.5 * U), ("reading", U)])
def test_the_reference_moves_each_end_out_by_k_times_its_largest_range(per, pair):
    """The same readings with and without the reference: E's, E↑'s, E↓'s and M's ends are the
    readings' own moved out by k · pair (k = 2 at 95.45 %, pair u per angle and 2u per
    reading). E's (and E↑'s, E↓'s) readings' interval is taken at the level at which the whole
    misses at the tail at the least favourable bias ±k · pair (#39's widths): its upper end
    below the readings' own at the probability plus k · pair (those two bounds at the
    probability added, until 0.8.20), by at most what the readings' bound moves between the
    tail and twice it (for a normal error 0.31 of 4 standard deviations, 8 % of its
    interval's width: 20 % allowed). M's (calibrated, its one-sided quantile not exact enough
    for that) is the readings' own at the probability plus k · pair, as before."""
    rng = np.random.default_rng(39)
    curve, reversal = _axis(rng)
    rows = _rows(rng, curve, reversal, 0.5, np.zeros(TARGETS.size))
    bare, stated = _intervals(rows, None), _intervals(rows, per)
    k = float(ndtri(0.5 * (1.0 + 0.9545)))  # to 1e-5: the budget's p is 95.44997 %
    for key in ("E", "E_up", "E_down"):
        width = bare[key].high - bare[key].low
        assert stated[key].value == bare[key].value
        assert stated[key].high < bare[key].high + k * pair - 0.02 * width, key
        assert stated[key].high > bare[key].high + k * pair - 0.2 * width, key
        assert stated[key].low <= bare[key].low - k * pair + 0.2 * width, key
    assert stated["M"].high == pytest.approx(bare["M"].high + k * pair, abs=1e-4)
    assert stated["M"].low <= bare["M"].low - k * pair + 1e-4


@pytest.mark.parametrize("sigma", [0.05, 0.2])
def test_a_standard_stated_for_any_angle_is_no_wider_than_one_stated_per_reading(sigma):
    """A standard whose U is stated for any angle (two targets' errors differ by one more
    angle: within U of each other) says more than one stated per reading at U/√2 (each
    target's error within U/√2, two of them up to √2 U apart): E's and M's intervals with
    the first lie within those with the second. Until 0.8.20 the bootstrap drew a standard
    stated for any angle at its whole u at each target on its own, two targets' errors √2 u
    apart, and E's interval reached lower with it than with the one per reading (7.82″
    against 8.19″ at σ = 0.05″): the part of such errors that can differ from target to
    target is u/√2."""
    rng = np.random.default_rng(39)
    curve, reversal = _axis(rng)
    rows = _rows(rng, curve, reversal, sigma, np.zeros(TARGETS.size))
    result = POSITIONING.analyze(ReadingsSheet(POSITIONING.columns, rows).parse(), {})

    def stated(u: float, per: str):
        meta = CertificateMetadata.from_dict({"standards": [{
            "description": "Laser rotary calibrator", "uncertainty": u,
            "uncertainty_unit": "arcsec", "basis": "U95", "applies_to": per}]})
        return figure_uncertainties(result, positioning_budget(result, meta))

    angle, reading = stated(U, "angle"), stated(U / np.sqrt(2.0), "reading")
    for key in ("E", "M"):
        assert angle[key].low >= reading[key].low - 1e-9, key
        assert angle[key].high <= reading[key].high + 1e-9, key


#: the tests a case in the suite (the smoke version) and in the long form
#: (tests/benchmarks/test_positioning_studies_full.py, ``make bench``), the same check
SMOKE_TESTS, FULL_TESTS = 15, 40
SHAPES = [("angle", -1.0), ("angle", 1.0), ("reading", -1.0)]


@pytest.mark.slow
@pytest.mark.parametrize("per, shape", SHAPES)
def test_errors_at_their_u_shaped_as_the_curve_are_still_covered(per, shape):
    """The smoke version of :func:`check_errors_at_their_u_covered`: 15 tests a case, the
    floor the binomial test's at 0.1 % (10 of 15 at the 92.5 % printed); with the
    reference's errors left out of E's interval (no widening) the two cases against the
    curve fail it (7 and 0 of 15 covered; with the curve, E is raised and still held). The
    full 40 tests a case: tests/benchmarks/test_positioning_studies_full.py."""
    check_errors_at_their_u_covered(per, shape, SMOKE_TESTS, 0.001)


def check_errors_at_their_u_covered(per: str, shape: float, tests: int,
                                    false_alarm: float) -> None:
    """``tests`` tests, each a new axis and noise (σ = 0.5″), the reference's error the axis's
    own curve scaled to the largest range the statement allows at its U (U per angle: any two
    targets within U; per reading: each within U, a range of 2U), against the curve (it
    lowers E) or with it: E's interval covers the true E at least as often as the binomial
    test (``false_alarm``: 1 % in the long form) allows at the probability printed (measured
    40/40 in each case at 40 tests; in an audit-style study of 30 runs, 29–30 of 30)."""
    rng = np.random.default_rng(3900 + int(shape > 0) + 2 * (per == "reading"))
    hits, probability = 0, 1.0
    for _ in range(tests):
        curve, reversal = _axis(rng)
        g = (curve - 0.5 * (curve.max() + curve.min())) / (0.5 * np.ptp(curve))  # −1 … 1
        amplitude = 0.5 * U if per == "angle" else U
        rows = _rows(rng, curve, reversal, 0.5, shape * amplitude * g)
        e = _intervals(rows, per)["E"]
        truth = float(np.ptp(np.concatenate([curve + 0.5 * reversal, curve - 0.5 * reversal])))
        hits += e.low - 1e-9 <= truth <= e.high + 1e-9
        probability = min(probability, e.probability)
    assert hits >= binom.ppf(false_alarm, tests, probability), (hits, probability)
