"""The polygon's zero reading: which figure is zero by definition, and its U (issue 39).

Every error is taken from one reading, face z of set 1 (the zero reading). Set 1's error
there is that reading against itself: 0 in every run, so its U is 0. Another set's error
there is its own reading against the zero reading, and the mean over the sets at position z
takes those in: they scatter from run to run, and their U must cover that scatter. Before,
the JSON gave set 1's zero reading the same U as the other sets' (0.138″ on the sample),
each other set at face z only one reading's noise (U / 2·scatter ≈ 0.8), and the mean of
3 or 4 sets at position z the noise of σ²/m instead of σ²(1 − w₁² m_eff) + (1 − w₁)²σ²
(0.79 and 0.68 of its scatter); the certificate said "U is zero at face 1 of set 1" beside a
position 1 with U = 0.098″.

The readings come from the exact 3-D rig (models/validation/polygon_rig.py imports nothing
from the code it checks), noise σ on both autocollimator readings, no drift.
"""

from __future__ import annotations

import json
import math
import re

import numpy as np
import pytest
from pypdf import PdfReader

from app.main import main
from models.certificate.metadata import CertificateMetadata
from models.polygon.analysis import POLYGON
from models.polygon.report import (
    OTHER_SET,
    ZERO_READING,
    mean_zero_share,
    polygon_json_budgets,
    zero_reading_statement,
)
from models.readings.sheet import ReadingsSheet
from models.validation.polygon_rig import PolygonRig

FACES, SIGMA = 12, 0.1
THETA = np.radians(np.arange(FACES) * 360.0 / FACES)
TRUTH = 1.5 * np.sin(THETA + 0.3) + 0.4 * np.sin(2 * THETA)
SETTINGS = {"grade": 5, "ac_roll_arcmin": 0.0}


def _run(directions: tuple[int, ...], rng: np.random.Generator):
    rig = PolygonRig(FACES, TRUTH, psi_arcsec=60.0, omega_deg=70.0, noise_arcsec=SIGMA,
                     rng=rng)
    rows = []
    for k, d in enumerate(directions):
        rows += rig.set_rows(k + 1, reverse=d < 0, start_face=1 if d > 0 else 7)
    # one set cannot evaluate its reading noise: the lab states it (the rig's)
    settings = {**SETTINGS, "reading_noise_arcsec": SIGMA} if len(directions) == 1 else SETTINGS
    result = POLYGON.analyze(ReadingsSheet(POLYGON.columns, rows).parse(), settings)
    return result, polygon_json_budgets(result, CertificateMetadata()), rig.truth_arcsec()


def _study(directions: tuple[int, ...], runs: int, seed: int):
    """Per run: each set's corrected error − truth and its JSON U (set after set), the mean's
    − truth and its U."""
    rng = np.random.default_rng(seed)
    per, u_per, mean, u_mean, raw, u_raw = [], [], [], [], [], []
    for _ in range(runs):
        result, budgets, truth = _run(directions, rng)
        per.append(np.concatenate([s.corrected_error_arcsec - truth for s in result.sets]))
        raw.append(np.concatenate([s.error_arcsec for s in result.sets]))
        u_per.append(budgets["corrected_error_arcsec"].expanded)
        u_raw.append(budgets["error_arcsec"].expanded)
        mean.append(result.mean_corrected_arcsec - truth)
        u_mean.append(budgets["mean_corrected_error_arcsec"].expanded)
    return tuple(np.array(a) for a in (per, u_per, mean, u_mean, raw, u_raw))


@pytest.mark.slow
@pytest.mark.parametrize("directions", [(1, 1, 1), (1, -1, 1, -1)])
def test_only_the_zero_reading_has_u_zero_and_the_others_at_its_face_are_covered(directions):
    """120 runs each (about 5 s): the scatter's standard deviation is known to about 7 %;
    U / (2 × scatter) is 1.0–1.2 at every other face, and must be so at face 1 too (up to
    1.6 at a later set's face 1: with no drift in this rig, the zero drift the closures
    could carry from set to set still enters, as far as their noise leaves it possible)."""
    m = len(directions)
    per, u_per, mean, u_mean, raw, u_raw = _study(directions, 120, 39)
    # set 1 at face 1: the zero reading against itself, 0 in every run: U = 0
    assert np.all(raw[:, 0] == 0.0) and np.all(per[:, 0] == 0.0)
    assert np.all(u_per[:, 0] == 0.0) and np.all(u_raw[:, 0] == 0.0)
    # every other set at face 1: its own reading against the zero reading, noise √2·σ
    later = np.arange(1, m) * FACES
    scatter = per[:, later].std(axis=0, ddof=1)
    assert np.all(np.abs(scatter / (SIGMA * math.sqrt(2.0)) - 1.0) < 0.2), scatter
    ratio = u_per[:, later].mean() / (2.0 * math.sqrt(np.mean(scatter**2)))
    assert 0.92 <= ratio <= 1.6, ratio
    assert np.mean(np.abs(per[:, later]) <= u_per[:, later]) >= 0.93
    assert np.all(u_raw[:, later] > 0)
    # the mean at position 1 takes those in: not zero by definition, and its U covers it
    assert np.std(mean[:, 0]) > 0.2 * SIGMA
    ratio = u_mean[:, 0].mean() / (2.0 * mean[:, 0].std(ddof=1))
    assert 0.92 <= ratio <= 1.6, ratio
    assert np.mean(np.abs(mean[:, 0]) <= u_mean[:, 0]) >= 0.93
    # and it is made the same way as at the other faces (the same ratio, within the noise)
    others = np.median(u_mean[:, 1:].mean(axis=0) / (2.0 * mean[:, 1:].std(axis=0, ddof=1)))
    assert abs(ratio / others - 1.0) < 0.2, (ratio, others)


def test_one_set_its_position_of_the_zero_is_the_reference_point():
    result, budgets, _ = _run((1,), np.random.default_rng(3))
    assert result.mean_corrected_arcsec[0] == 0.0
    for name in ("error_arcsec", "corrected_error_arcsec", "mean_corrected_error_arcsec"):
        u = np.asarray(budgets[name].expanded)
        assert u[0] == 0.0 and np.all(u[1:] > 0), name


def test_one_set_read_n_times_a_face_keeps_its_reference_point():
    """With n readings at each face averaged and one set, the readings' s/√n entered at
    every face with sensitivity 1, the zero face too: the certificate's reference point
    (error 0 by definition) got U = 0.126″ here. The zero reading's s/√n is in every other
    face's U, not in its own."""
    n, rng = 3, np.random.default_rng(1)
    rig = PolygonRig(FACES, TRUTH, psi_arcsec=60.0, omega_deg=70.0, rng=rng)
    rows = []
    for row in rig.set_rows(1):
        for _ in range(n):  # columns: position, encoder, dev, ac_x, ac_y, set, direction
            rows.append(row[:3] + [repr(float(row[3]) + rng.normal(0.0, SIGMA)),
                                   repr(float(row[4]) + rng.normal(0.0, SIGMA))] + row[5:])
    result = POLYGON.analyze(ReadingsSheet(POLYGON.columns, rows).parse(),
                             {**SETTINGS, "readings_per_point": n, "reading_noise_arcsec": SIGMA})
    budgets = polygon_json_budgets(result, CertificateMetadata())
    full = budgets["mean_corrected_error_arcsec"]
    assert any(str(c.name).startswith("Repeated readings") for c in full.components)
    assert result.mean_corrected_arcsec[0] == 0.0
    assert full.expanded[0] == 0.0 and np.all(full.expanded[1:] > 0.1)
    assert budgets["corrected_error_arcsec"].expanded[0] == 0.0


@pytest.mark.parametrize(("directions", "own", "zero", "drift"), [
    ((1,), 0.0, 0.0, 0.0),
    ((1, -1), math.sqrt(0.5), 0.5, math.sqrt(0.5)),  # σ²/2 in all, as before
    ((1, 1, 1), math.sqrt(2.0 / 3.0), 2.0 / 3.0, math.sqrt(2.0 / 3.0)),
    # weights ¼: the other sets σ²·3/16, the zero reading (¾)²σ², of σ²/4 per u² input
    ((1, -1, 1, -1), math.sqrt(0.75), 0.75, math.sqrt(0.75)),
    # weights ½ (the one forward set, set 1), ¼, ¼: σ²/8 of the other two, (½)²σ²
    ((1, -1, -1), math.sqrt(1.0 - 0.25 * 4.0 / (1.0 + 0.5)), 0.5, math.sqrt(2.0 / 3.0)),
])
def test_the_mean_at_the_zero_face_by_hand(directions, own, zero, drift):
    share = mean_zero_share(directions)
    assert (share.own, share.zero, share.drift) == pytest.approx((own, zero, drift), abs=1e-12)
    assert (ZERO_READING.own, ZERO_READING.zero, ZERO_READING.drift) == (0.0, 0.0, 0.0)
    assert (OTHER_SET.own, OTHER_SET.zero, OTHER_SET.drift) == (1.0, 1.0, 1.0)


def test_one_set_and_several_say_which_figure_is_zero():
    one, _, _ = _run((1,), np.random.default_rng(4))
    text = zero_reading_statement(one)
    assert "zero reading, face 1" in text and "position 1 is zero by definition" in text
    several, _, _ = _run((1, -1), np.random.default_rng(4))
    text = zero_reading_statement(several)
    assert "face 1 of set 1" in text and "set 1's own error there is zero by definition" in text
    assert "Position 1 of the results is the mean over the 2 sets" in text
    assert "its error and its U are not zero" in text


@pytest.mark.slow
def test_sample_json_and_certificate_agree_at_the_zero_reading(capsys, samples_dir, tmp_path):
    """The assessor's finding on the 0.6.0 sample: the JSON, the results table and the
    statement now say the same thing."""
    pdf = tmp_path / "polygon.pdf"
    code = main(["analyze", "polygon", str(samples_dir / "polygon_sample.csv"), "--json",
                 "--metadata", str(samples_dir / "certificate_polygon.json"),
                 "--certificate", str(pdf)])
    data = json.loads(capsys.readouterr().out)
    assert code == 0
    faces = data["faces"]
    for name in ("error_arcsec", "corrected_error_arcsec"):
        errors, u = np.array(data[name]), np.array(data[f"expanded_uncertainty_{name}"])
        assert errors[0] == 0.0 and u[0] == 0.0, name  # the zero reading
        assert errors[faces] != 0.0 and u[faces] > 0.0, name  # set 2 at face 1
        # set 2 at face 1: its reading and the zero reading, each ≥ the other faces' noise
        assert u[faces] > 0.13, name
    mean = np.array(data["mean_corrected_error_arcsec"])
    u_mean = np.array(data["expanded_uncertainty_mean_corrected_error_arcsec"])
    # U 0.076 before 0.8.0; 0.119 since the zero's drift carried from set 2's start (set 1's
    # closure +0.12″, half of it in the mean there) is an input: set 2's error at face 1 is
    # −0.20″, as a zero 0.12″ further on predicts; 0.118 since 0.8.5 (the reading noise from
    # the two sets' vertical residuals face by face, 0.027″: about the fits alone, 0.032″, it
    # held the faces' own pyramidal errors); 0.126 since the noise of an error is the forward
    # set's minus the reverse set's about their mean reversal (0.049″ a reading: the
    # encoder's own noise too, which the vertical readings never hold; audit s67)
    assert mean[0] == pytest.approx(-0.100, abs=5e-4) and u_mean[0] == pytest.approx(0.126,
                                                                                     abs=5e-4)
    # the certificate: position 1 the mean, −0.10 with its U; the statement says so
    text = re.sub(r"\s+", " ", "\n".join(page.extract_text() for page in PdfReader(pdf).pages))
    assert "U is zero at face 1 of set 1" not in text
    assert "U is zero only at the zero reading, face 1 of set 1" in text
    assert "its error and its U are not zero" in text
    # U to two significant digits and the error to the same decimal (GUM 7.2.6); a zero
    # correction unsigned (assessment 76 L6)
    assert re.search(r"\b1 0\.000 -0\.10 0\.00 -0\.10 0\.13\b", text), text
