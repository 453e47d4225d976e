"""A document whose traceability is not established names the standard not listed
(assessment 72 L2: the fringe with only the ADC listed said "the standard for the other one
is not listed", 另一项, leaving the reader to guess that the phase or angle reference was
missing).

Each standard may state its role (``role``: reference, autocollimator or adc); where it
does not, the role is told from its other fields where they tell it (the only standard of a
one-standard measurand; a polygon's figure stated from face 1; a standard with its
certificate and no U behind the settings' inputs of one standard), and where they do not,
the reason says the details do not say which, naming the candidates. Files written before
the role existed load and are judged as before (every listed standard counted).

The workbenches' own lists of the standards that carry their measurand are used, as their
certificates use them."""

from __future__ import annotations

import pytest

from models.certificate.metadata import CertificateMetadata, MetadataError
from models.certificate.traceability import traceability_gaps
from models.fringe import MEASURAND_STANDARDS as FRINGE
from models.fringe import ROLES_STATED_ONLY as FRINGE_STATED_ONLY
from models.polygon import MEASURAND_STANDARDS as POLYGON

#: the fringe's inputs stated in the settings (its budget's names), every one
ALL_INPUTS = ("Phase reference", "ADC quantisation", "ADC offset", "ADC gain ratio",
              "ADC linearity")
ADC_INPUTS = ALL_INPUTS[1:]


def _meta(*standards: dict) -> CertificateMetadata:
    return CertificateMetadata.from_dict({"standards": list(standards)})


def _gaps(meta, roles, inputs=ALL_INPUTS) -> str:
    """The reason as the workbench of ``roles`` gives it (the fringe: its phase or angle
    reference only a standard stating its role carries)."""
    stated_only = FRINGE_STATED_ONLY if roles is FRINGE else ()
    return "; ".join(str(g) for g in traceability_gaps(meta, roles, inputs, stated_only))


#: the assessor's ADC: listed with its certificate and a U
ADC = {"description": "Data acquisition (16-bit ADC)", "certificate_no": "CAL-2026-33",
       "uncertainty": 0.02}
PHASE = {"description": "Reference angle encoder", "certificate_no": "NIM-2026-0999",
         "uncertainty": 0.05}


def test_the_adc_alone_named_by_its_role_names_the_phase_reference_missing():
    text = _gaps(_meta({**ADC, "role": "adc"}), FRINGE)
    assert "other one" not in text
    assert text.endswith("1 listed so (Data acquisition (16-bit ADC)): none is listed for a "
                         "phase or angle reference"), text


def test_the_phase_reference_alone_names_the_adc_missing():
    text = _gaps(_meta({**PHASE, "role": "reference"}), FRINGE)
    assert text.endswith("none is listed for the ADC (its figures stated in the settings)"), text


def test_a_role_told_by_the_fields_names_the_other():
    # the ADC listed with its certificate and no U, only the ADC's figures stated in the
    # settings: it stands behind them, so it is the ADC
    adc_by_settings = {"description": "DAQ", "certificate_no": "CAL-1"}
    text = _gaps(_meta(adc_by_settings), FRINGE, ADC_INPUTS)
    assert text.endswith("1 listed so (DAQ): none is listed for a phase or angle reference"), text
    # a polygon's certificate stating its deviations from face 1: the polygon
    polygon = {"description": "24-face polygon", "certificate_no": "NIM-1", "uncertainty": 0.2,
               "applies_to": "from face 1"}
    text = _gaps(_meta(polygon), POLYGON)
    assert text.endswith("1 listed so (24-face polygon): none is listed for the "
                         "autocollimator"), text


def test_with_no_role_told_the_reason_says_the_details_do_not_say_which():
    # the polygon's standards: the one of no role told may be either
    collimator = {"description": "autocollimator", "certificate_no": "N-2", "uncertainty": 0.1}
    text = _gaps(_meta(collimator), POLYGON)
    assert "other one" not in text
    assert ("no role stated for autocollimator: the standard for the polygon (its face "
            "deviations) or the autocollimator is not listed, and the details do not say "
            "which (state each standard's role)") in text, text
    # the fringe's ADC listed with a U and no role: not the phase reference (assessment 78 H1)
    text = _gaps(_meta(ADC), FRINGE)
    assert "other one" not in text
    assert ("none is listed for a phase or angle reference, as no role is stated for Data "
            "acquisition (16-bit ADC) and only a standard whose role says so is taken as a "
            "phase or angle reference") in text, text


def test_files_without_roles_are_judged_as_before():
    # two standards with no role: the two standards the measurand needs (traceable, as
    # until 0.8.21), as for a polygon with both listed — but not the fringe's phase or angle
    # reference, which only a standard stating its role is (assessment 78 H1)
    # without the fringe's rule, as before
    assert traceability_gaps(_meta(ADC, PHASE), FRINGE, ALL_INPUTS) == []
    polygon = {"description": "polygon", "certificate_no": "N-1", "uncertainty": 0.2}
    collimator = {"description": "autocollimator", "certificate_no": "N-2", "uncertainty": 0.1}
    assert _gaps(_meta(polygon, collimator), POLYGON) == ""
    # stated roles: two ADCs are not a phase reference
    text = _gaps(_meta({**ADC, "role": "adc"}, {**PHASE, "role": "adc"}), FRINGE)
    assert text.endswith("none is listed for a phase or angle reference"), text


def test_the_role_is_read_checked_and_written_back():
    meta = _meta({**ADC, "role": "adc"}, PHASE)
    assert [s.role for s in meta.standards] == ["adc", ""]
    written = meta.to_dict()["standards"]
    assert written[0]["role"] == "adc" and "role" not in written[1]  # an old file stays as it was
    assert CertificateMetadata.from_dict(meta.to_dict()) == meta
    with pytest.raises(MetadataError, match=r"standards\[1\]\.role"):
        _meta({**ADC, "role": "ADC of the rig"})


def test_a_fringe_standard_of_no_role_is_not_taken_as_the_phase_reference():
    """Assessment 78 H1: the fringe's "Angle reference" listed with its certificate and a U
    but no role, beside the ADC (role adc), was taken as the phase reference: the document a
    calibration certificate, "traceable … through the reference standards listed", and a
    verdict. A standard with a U and no role may be any instrument's (the sample's ADC
    certificate listed without its role is one): the reason names the phase reference as not
    listed and the role to state; stated, it is traceable."""
    adc = {**ADC, "role": "adc"}
    text = _gaps(_meta(PHASE, adc), FRINGE)
    assert text == (
        "the standards that carry the measurand are a phase or angle reference; the ADC (its "
        "figures stated in the settings), each to be listed with a calibration certificate and "
        "a stated uncertainty; 2 listed so (Data acquisition (16-bit ADC), Reference angle "
        "encoder): none is listed for a phase or angle reference, as no role is stated for "
        "Reference angle encoder and only a standard whose role says so is taken as a phase or "
        "angle reference (one with no role may be another instrument's, such as the ADC's): "
        "state the role \"reference\" of the one that is"), text
    assert _gaps(_meta({**PHASE, "role": "reference"}, adc), FRINGE) == ""
    # both of no role: the phase reference named as not listed, the ADC's role filled as before
    text = _gaps(_meta(ADC, PHASE), FRINGE)
    assert "none is listed for a phase or angle reference, as no role is stated for Data " \
        "acquisition (16-bit ADC), Reference angle encoder" in text, text
    assert "the details do not say which" not in text, text
    # the polygon's and the theodolite's roles are told as before (one standard, or from face 1)
    polygon = {"description": "polygon", "certificate_no": "N-1", "uncertainty": 0.2}
    collimator = {"description": "autocollimator", "certificate_no": "N-2", "uncertainty": 0.1}
    assert _gaps(_meta(polygon, collimator), POLYGON) == ""
