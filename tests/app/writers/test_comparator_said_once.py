"""Assessment 78 L7: the cross-calibration's standards table printed the encoder sample's
"Photoelectric autocollimator (comparator)" as "Photoelectric autocollimator (comparator)
(comparator)": the table marks each instrument a comparator (no reference standard is used:
the closure of the circle is the reference), and the description already said so. It is
said once; a description that does not say so is still marked."""

from __future__ import annotations

import dataclasses

from app.writers.certificate_pdf.traceability import _standards_table
from tests.app.test_crosscal_cmc_from_first import KIND, _analysed, _metadata


def test_a_comparator_is_named_one_once():
    result, settings = _analysed(certificate_of="encoder")
    metadata = _metadata("certificate_crosscal_encoder.json")
    assert metadata.standards[0].description == "Photoelectric autocollimator (comparator)"
    document = KIND.certificate_document(result, metadata, "crosscal_sample.csv", settings)
    assert document.traceability_basis  # the closure of the circle: every standard a comparator
    assert str(_standards_table(document).rows[0][0]) == \
        "Photoelectric autocollimator (comparator)"
    plain = dataclasses.replace(metadata, standards=(dataclasses.replace(
        metadata.standards[0], description="Photoelectric autocollimator"),))
    document = KIND.certificate_document(result, plain, "crosscal_sample.csv", settings)
    assert str(_standards_table(document).rows[0][0]) == \
        "Photoelectric autocollimator (comparator)"
