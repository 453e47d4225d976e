"""A cross-calibration certificate says what was done of each mounting's drift, and the JSON
names the certified item's CMC and why the encoder's U is withheld (assessment 70, M8, L7,
L9).

* M8: a run with no closure reading printed "Closure drift — fitted linearly over each
  mounting by least squares and removed", a method saying "Each mounting ends with a closure
  reading", and "The encoder was calibrated in the same run" beside the encoder's U
  withheld. Since a mounting without a closure reading may have its drift fitted through the
  others' closure readings (where the design determines it), the row says it per mounting:
  fitted through the others, or not measured.
* L7: the encoder's certificate with both CMCs set gave the polygon's CMC as the JSON's
  primary ``laboratory_cmc``.
* L9: with the encoder's U withheld, the JSON's ``uncertainty_withheld`` was absent.

The readings are the geometric bench's (tests/crosscal_simulator.py, numpy only)."""

from __future__ import annotations

from models.certificate.uncertainty_json import workbench_uncertainty_json
from tests.models.crosscal.test_crosscal_unchecked_drift import KIND, analyze, bench, details

MOUNTINGS = (0, 1, 5)


def _drift_row(document) -> tuple[str, str]:
    row = next(r for r in document.parameters.rows if str(r[0]) == "Closure drift")
    return str(row[1]), str(row[2])


def _said(document) -> str:
    return " ".join([str(document.method), *map(str, document.statements)])


def test_no_closure_reading_anywhere_the_drift_is_said_not_measured():
    rows = bench(4, noise_arcsec=0.05, drift_arcsec=0.3, drift_common=True).rows(
        MOUNTINGS, closure=False)
    document = KIND.certificate(analyze(rows), details())  # the polygon's certificate
    value, note = _drift_row(document)
    assert value == "not measured (no closure readings)", value
    assert "fitted" not in value and "removed" not in value
    said = _said(document)
    assert "Each mounting ends with a closure reading" not in said
    assert "Where a mounting ends with a closure reading" in said
    # the encoder's U is withheld: it is not called calibrated
    assert "The encoder was calibrated in the same run" not in said
    assert "the encoder is not calibrated: its U is withheld" in said


def test_a_mounting_without_closure_has_its_drift_said_fitted_or_not_measured():
    # a closure reading in mounting 0 only: mountings 1 and 5 fitted through it (the design
    # determines them); with two mountings and one closure the other's is not measured
    b = bench(6, noise_arcsec=0.005, drift_arcsec=0.3)
    fitted = KIND.certificate(analyze(b.rows(MOUNTINGS, closure={0})), details())
    value, note = _drift_row(fitted)
    assert value == "fitted linearly over each mounting by least squares and removed"
    assert note == ("no closure reading in mounting(s) 1, 5: their drift fitted through the "
                    "other mountings' closure readings"), note
    assert "the encoder is not calibrated" not in _said(fitted)
    assert "The encoder was calibrated in the same run" in _said(fitted)
    two = bench(7, noise_arcsec=0.02, drift_arcsec=0.3)
    # (a drift bound stated: mounting 1's drift alone moves the face deviations, so without
    # one their U is withheld too: test_crosscal_drift_left_in.py)
    unfitted = KIND.certificate(analyze(two.rows((0, 1), closure={0}), noise_arcsec=0.02,
                                        drift_bound_arcsec=0.3), details())
    value, note = _drift_row(unfitted)
    assert note == "no closure reading in mounting(s) 1: their drift not measured", note
    assert "Where a mounting ends with a closure reading" in _said(unfitted)


def test_with_every_closure_reading_the_method_and_the_row_are_as_before():
    rows = bench(5, noise_arcsec=0.05, drift_arcsec=0.3, drift_common=True).rows(MOUNTINGS)
    document = KIND.certificate(analyze(rows), details())
    assert _drift_row(document) == (
        "fitted linearly over each mounting by least squares and removed", "")
    assert "Each mounting ends with a closure reading" in _said(document)


def test_the_encoders_certificate_states_the_encoders_cmc_first():
    rows = bench(5, noise_arcsec=0.05, drift_arcsec=0.3, drift_common=True).rows(MOUNTINGS)
    # the settings analyze() analyses with (tests/crosscal_drift_bench.py: the tilt fitted
    # from the bench's vertical readings, the default bound unused)
    settings = {**KIND.default_settings, "ac_scale_pct": 0.0, "certificate_of": "encoder",
                "cmc_encoder_arcsec": 0.05, "cmc_arcsec": 0.04}
    result = analyze(rows, **{k: settings[k] for k in ("certificate_of", "cmc_encoder_arcsec",
                                                       "cmc_arcsec")})
    cmc = workbench_uncertainty_json(KIND, result, details(), settings)["laboratory_cmc"]
    assert cmc["setting"] == "cmc_encoder_arcsec" and cmc["value"] == 0.05, cmc
    assert [c["setting"] for c in cmc["other_quantities"]] == ["cmc_arcsec"]
    polygon = analyze(rows, cmc_encoder_arcsec=0.05, cmc_arcsec=0.04)
    cmc = workbench_uncertainty_json(KIND, polygon, details(),
                                     {**settings, "certificate_of": "polygon"})["laboratory_cmc"]
    assert cmc["setting"] == "cmc_arcsec", cmc


def test_the_encoders_u_withheld_is_said_in_uncertainty_withheld():
    rows = bench(4, noise_arcsec=0.05, drift_arcsec=0.3, drift_common=True).rows(
        MOUNTINGS, closure=False)
    for item in ("encoder", "polygon"):
        extra = workbench_uncertainty_json(KIND, analyze(rows, certificate_of=item),
                                           details(), None)
        assert extra["expanded_uncertainty_encoder_error_arcsec"] is None
        assert "the encoder's U is withheld" in str(extra.get("uncertainty_withheld")), item
    # with closure readings nothing is withheld, and the key is absent
    closed = bench(5, noise_arcsec=0.05, drift_arcsec=0.3).rows(MOUNTINGS)
    assert "uncertainty_withheld" not in workbench_uncertainty_json(
        KIND, analyze(closed, certificate_of="encoder"), details(), None)


def test_the_json_says_why_a_mountings_closure_and_drift_are_null():
    """Assessment 73 M3: with no closure reading, the JSON's ``closure_arcsec`` and
    ``drift_arcsec`` were null at every mounting with no reason; each now has its reason
    beside it naming the mountings, and none where every value is given."""
    rows = bench(4, noise_arcsec=0.05, drift_arcsec=0.3, drift_common=True).rows(
        MOUNTINGS, closure=False)
    data = KIND.to_json(analyze(rows))
    assert all(_null(v) for v in data["closure_arcsec"])  # (NaN: null once written)
    assert all(_null(v) for v in data["drift_arcsec"])
    for key in ("closure_arcsec_reason", "drift_arcsec_reason"):
        said = str(data[key] or "")
        assert all(str(j) in said for j in MOUNTINGS) and "closure reading" in said, key
    full = KIND.to_json(analyze(bench(6, noise_arcsec=0.005, drift_arcsec=0.3).rows(MOUNTINGS)))
    assert not any(_null(v) for v in full["closure_arcsec"])
    assert full["closure_arcsec_reason"] is None
    assert (full["drift_arcsec_reason"] is None) == (not any(_null(v)
                                                             for v in full["drift_arcsec"]))


def _null(value) -> bool:
    return value is None or value != value
