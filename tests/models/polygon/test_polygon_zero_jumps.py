"""The autocollimator's zero moving between polygon sets is no reading noise (audit 68,
finding 1).

A zero that jumps between sets (or a drift carried on from set to set) shifts a whole set:
one unknown value per set, a systematic of the set. Taken as the scatter of the sets about
their direction's mean, it was the reading noise, and the decided half range had that much
noise's range excess taken off: 24 faces, 2 sets each way, σ 0.1″, the zero moved by 1″
between sets, noise 1.3″ where the readings' own is 0.14″; decided 0.43″ (interval
0 … 1.05″) for a true 1.153″, "pass" under the grade's ±1″. Now the noise is the scatter
about each set's own level and steady drift, and the offsets are an input of their own, the
same at every position (they move the errors, not their half range).

Simulated by tests/polygon_zero_jump_rig.py (numpy only, exact 3-D), analysed by the
workbench; the study is tests/benchmarks/polygon_zero_jump_study.py (60 runs a cell):

    cell (2 + 2 sets)           decided covered   value − truth   false "pass"
                                before   now      before   now    before  now
    24 faces, jumps 1″          56/60    59/60    −0.18″  +0.01″  15/60   0/60
    24 faces, drift 0.02″/rdg   59/60    59/60    −0.20″  +0.02″   0/60   0/60
    24 faces, jumps + drift     53/60    59/60    −0.27″  +0.01″   1/60   0/60
      the same, drift spread    48/60    58/60    −0.41″  −0.02″   2/60   0/60
    12 faces, jumps 1″          60/60    59/60    −0.13″  +0.01″  12/60   0/60
    12 faces, drift 0.02″/rdg   60/60    58/60    −0.05″  +0.00″   1/60   0/60
    controls (24, 12 faces)     60, 57   59, 57   +0.00″  +0.00″   0/60   0/60

(floor 54 of 60). U at a point, with jumps: 96.5–98.3 % (U 2.7–2.9 times the oracle's: the
offsets' spread has 2 degrees of freedom with 2 sets each way); with drift alone 99.8–100 %
(1.4–1.5×, before 2.0×); controls 96.8–98.3 % (1.05–1.15×, as before). Since the offsets
within each direction are seen (a known bias; only the offset between the directions
unknown), with jumps 96.6–96.8 % at 1.6–2.0× over 150 runs, 93–98 % at 1.0–1.3× where
every set's zero scatters or the zero wanders on (test_polygon_zero_offsets_seen.py).
"""

from __future__ import annotations

import math

import numpy as np

from models.certificate.metadata import CertificateMetadata
from models.polygon.analysis import POLYGON
from models.polygon.report import polygon_budget
from models.readings.sheet import ReadingsSheet
from tests.benchmarks.polygon_zero_jump_study import METADATA, cell
from tests.polygon_zero_jump_rig import ZeroJumpRig

REPEATABILITY = "Repeatability (mean of {sets} sets)"
OFFSETS = "Autocollimator zero offsets between the sets"


def _analyse(rig: ZeroJumpRig, seed: int):
    lines, truth = rig.run(np.random.default_rng(seed))
    result = POLYGON.analyze(ReadingsSheet(POLYGON.columns, [r.split(",") for r in lines[1:]])
                             .parse(), {"grade": 3})
    return result, truth


def _component(budget, template):
    return next((c for c in budget.components
                 if getattr(c.name, "template", c.name) == template), None)


def test_the_noise_is_the_readings_own_not_the_sets_offsets():
    """24 faces, 2 sets each way, σ 0.1″ on the encoder and on each autocollimator reading
    (an error's noise √(0.1² + 0.1²) = 0.141″), the zero moved by σ 1″ between sets: the
    noise in U is the readings' (within 25 % of 0.141″ with 88 degrees of freedom; before:
    the sets' scatter, above 0.5″), the offsets are a common input, the same at every
    position, and the same readings without the jumps give the same noise."""
    meta = CertificateMetadata.from_dict(METADATA)
    jumping, _ = _analyse(ZeroJumpRig(jump_sd=1.0), 3)
    still, _ = _analyse(ZeroJumpRig(jump_sd=0.0), 3)
    assert float(np.max(jumping.repeatability_arcsec)) > 0.5  # the sets' scatter: the jumps
    budget = polygon_budget(jumping, meta, {"grade": 3})
    noise = _component(budget, REPEATABILITY)
    sigma = float(np.max(noise.value)) * 2.0  # σ/√m_eff, m_eff = 4 with 2 + 2 sets
    assert abs(sigma - math.hypot(0.1, 0.1)) < 0.25 * math.hypot(0.1, 0.1), sigma
    quiet = _component(polygon_budget(still, meta, {"grade": 3}), REPEATABILITY)
    # the same draws bar the offsets: the offsets do not reach the noise
    # (the readings typed to 0.0001″: their rounding differs)
    assert abs(float(np.max(quiet.value)) - float(np.max(noise.value))) < 1e-5
    offsets = _component(budget, OFFSETS)
    assert offsets is not None and offsets.common and offsets.evaluation == "A"
    assert np.all(np.asarray(offsets.sensitivity) == 1.0) and offsets.dof == 2
    # its u: one set's offset (~1″) times √((1 − ¼)² + 3·(¼)²) = 0.866 for 2 + 2 sets
    assert 0.2 < float(offsets.value) < 2.0, offsets.value


def test_zero_offsets_do_not_move_the_decided_value():
    """The auditor's example in kind: the same readings with and without a zero that jumps
    between sets give the same measured half range (the offsets move whole sets) and, now,
    the same decided value and interval to within the Monte Carlo's noise (before: 0.43″
    against 1.10″, the interval's upper end below the truth)."""
    meta = CertificateMetadata.from_dict(METADATA)
    out = []
    for jump in (0.0, 1.0):
        result, truth = _analyse(ZeroJumpRig(jump_sd=jump), 3001)
        conformity = POLYGON.certificate_document(result, meta, "", {"grade": 3}).conformity
        out.append((conformity.value, conformity.interval_low, conformity.interval_high))
        true_half = 0.5 * float(np.ptp(truth))
        assert conformity.interval_low <= true_half <= conformity.interval_high, (
            jump, conformity.value, conformity.interval_low, conformity.interval_high,
            true_half)
    assert abs(out[0][0] - out[1][0]) < 0.05, out


def test_study_smoke_zero_jumps_24_faces():
    """A smoke of the study: 16 runs of 24 faces, 2 sets each way, zero jumps σ 1″. Before:
    the decided value 0.18″ low (median), a failing item "pass" in 15 of 60 runs."""
    c = cell("24f_jumps1.0", 16)
    assert c["hits"] >= 14, c
    assert abs(c["median_offset"]) < 0.08, c
    assert c["false_pass"] <= 1, c
    # per point: the points of a run share its offsets, so 16 runs count as a few more than
    # 16 (±5 % and more); 96.8 % over 150 runs (tests/models/polygon/
    # test_polygon_zero_offsets_seen.py). These 16: 91.3 % while the closures' noisy drift
    # estimate was counted again in the offsets' inputs, 88.3 % now; the same cell over 150
    # runs 96.5 % then, 95.7 % now (val77, /work/s77/val77/cells.py)
    assert c["point_coverage"] >= 0.875, c


def test_study_smoke_zero_drift_24_faces():
    """A steady drift of 0.02″ a reading with jumps (the audit's Z3): before, the decided
    value 0.39″ low (median) and its interval short of the truth."""
    c = cell("24f_jumps+rate", 16)
    assert c["hits"] >= 14, c
    assert abs(c["median_offset"]) < 0.08, c
    assert c["false_pass"] <= 1, c


def test_a_zero_that_moved_is_named():
    """The warning: the jumping run's sets' means within a direction scatter far beyond the
    readings' noise (1.2″ against 0.03″), the same readings without the jumps do not."""
    jumping, _ = _analyse(ZeroJumpRig(jump_sd=1.0), 3001)
    still, _ = _analyse(ZeroJumpRig(jump_sd=0.0), 3001)
    assert any("zero moved between the sets" in w for w in jumping.warnings), jumping.warnings
    assert not any("zero moved" in w for w in still.warnings), still.warnings


def test_the_noise_estimate_is_unbiased_whatever_the_offsets_and_drifts():
    """σ = 1 of an error; every set offset by N(0, 5″) and drifting by N(0, 0.3″) a reading
    along its own reading order (a forward set started at face 4 in the second case): the
    mean σ̂² over 400 tests is 1 within 5 % (its standard error is 1.2 %), with (m − 1)(n − 2)
    degrees of freedom per direction (one fewer where a set's reading order differs)."""
    from models.polygon.model import within_set_noise

    rng = np.random.default_rng(1)
    n, directions = 24, np.array([1, -1, 1, -1])
    index = np.array([np.arange(n) if d > 0 else (n - np.arange(n)) % n for d in directions],
                     dtype=float)
    shifted = index.copy()
    shifted[0] = (np.arange(n) - 3) % n
    for reading_index, dof in ((index, 44), (shifted, 43)):
        estimates = []
        for _ in range(400):
            values = (rng.normal(size=(4, n)) + rng.normal(0.0, 5.0, (4, 1))
                      + reading_index * rng.normal(0.0, 0.3, (4, 1)))
            sigma, nu = within_set_noise(values, directions, reading_index)
            estimates.append(sigma**2)
            assert nu == dof
        assert abs(float(np.mean(estimates)) - 1.0) < 0.05, np.mean(estimates)


def test_the_offsets_spread_holds_the_carried_drift_estimates_error_once():
    """The sets' means, a steady drift carried from set to set taken out, hold that estimate's
    own error as well (set s carries s times it, so the sets of a direction are put apart by
    it): with its covariance given it is taken out, and the spread is one set's offset again
    (σ_ζ 0.3″, the means' noise 0.03″, an estimate of σ 0.1″ a set: 2 sets each way; 4000
    draws, the mean of τ̂² within 5 % of σ_ζ² + 0.03², where it held 2·0.1² more)."""
    from models.polygon.model import set_offsets_spread

    rng = np.random.default_rng(11)
    directions = np.array([1, -1, 1, -1])
    steps = np.arange(4.0)
    sigma_zeta, noise, u_estimate = 0.3, 0.03, 0.1
    with_it, without = [], []
    for _ in range(4000):
        drift = rng.normal(0.0, 0.5)
        estimate = drift + rng.normal(0.0, u_estimate)
        # one error per position: the curve (the same in every set), each set's offset and
        # the drift it carries (−s·drift, eq 1 takes −x), and noise; the means' noise σ/√24
        values = (np.sin(np.arange(24.0))[None, :] + rng.normal(0.0, sigma_zeta, (4, 1))
                  - steps[:, None] * drift + rng.normal(0.0, noise * math.sqrt(24.0), (4, 24)))
        carried = -steps * estimate
        with_it.append(set_offsets_spread(values, directions, carried,
                                          np.outer(steps, steps) * u_estimate**2)[0] ** 2)
        without.append(set_offsets_spread(values, directions, carried)[0] ** 2)
    expected = sigma_zeta**2 + noise**2
    assert abs(float(np.mean(with_it)) / expected - 1.0) < 0.05, np.mean(with_it)
    assert float(np.mean(without)) > expected + 1.5 * u_estimate**2, np.mean(without)
