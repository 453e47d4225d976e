"""What a certificate says of its figures agrees with what the code computes (day review 66
F8): the fringe's decided half range is the fitted model's, of an error given with its mean
removed (it was "as-found interpolation error (fitted model, whole period): 0.4861″ as
measured" beside the samples' "peak-to-peak 0.991″", and no word of the mean); the
positioning budget takes the bundled sample's laser rotary calibrator's U for the deviation
itself (c = 1, its U stated per angle), as its statement says (a standard stated per reading
takes √2: tests/models/positioning/test_reference_standard_sensitivity.py)."""

from __future__ import annotations

import json

import numpy as np

from models.certificate.metadata import CertificateMetadata
from models.readings.sheet import ReadingsSheet
from models.readings.tabular_import import map_columns, read_table


def _sample(kind, samples_dir):
    rows = map_columns(read_table(samples_dir / kind.sample_file), kind.columns)
    result = kind.analyze(ReadingsSheet(kind.columns, rows).parse(),
                          kind.settings_with_defaults({}))
    details = json.loads((samples_dir / f"certificate_{kind.key}.json").read_text("utf-8"))
    return result, CertificateMetadata.from_dict({**details, "example": False})


def test_the_fringe_says_its_half_range_is_the_models_of_an_error_its_mean_removed(
        samples_dir):
    from models.fringe.analysis import FRINGE
    from models.fringe.report import fringe_certificate

    result, metadata = _sample(FRINGE, samples_dir)
    document = fringe_certificate(result, metadata)
    statement = str(document.conformity.statement)
    assert "fitted model" in statement and "its mean removed" in statement, statement
    assert "not the sampled readings' peak-to-peak" in statement, statement
    assert "its mean over the period removed" in str(document.method)
    # as the code computes it: the as-found error's mean is 0 (the JSON's, each sample)
    assert abs(float(np.mean(result.raw_error))) < 1e-9


def test_the_positioning_samples_calibrator_takes_its_u_per_angle_as_its_statement_says(
        samples_dir):
    from models.positioning.analysis import POSITIONING
    from models.positioning.report import positioning_budget, positioning_certificate

    result, metadata = _sample(POSITIONING, samples_dir)
    laser = next(c for c in positioning_budget(result, metadata).components
                 if str(c.name) == "Laser rotary calibrator")
    # a rotary calibrator's U is stated for a position from its own datum: the deviation
    # itself (c = 1); a standard stated per reading takes √2 (test_reference_standard_
    # sensitivity)
    assert np.all(np.asarray(laser.sensitivity) == 1.0)
    assert "per angle between two readings" in str(laser.note)
    statements = " ".join(str(s) for s in positioning_certificate(result, metadata).statements)
    assert "that of the deviation itself" in statements
    assert "per reading (a theodolite, an autocollimator)" in statements
    assert "sensitivity √2" in statements, statements
