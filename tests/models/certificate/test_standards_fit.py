"""#41: reference standards per workbench in the lab's defaults, and a standard that does
not fit the workbench refused (another kind of quantity) or warned of (as large as the
tolerance) before it enters a budget."""

from __future__ import annotations

from models.certificate.metadata import CertificateMetadata
from models.certificate.standards_fit import (
    STANDARDS_BY_WORKBENCH,
    standards_fit,
    standards_for,
    with_workbench_standards,
)

THEODOLITE_STD = {"description": "Autocollimating theodolite", "uncertainty": 0.5,
                  "uncertainty_unit": "arcsec"}
POLYGON_STD = {"description": "24-face polygon", "uncertainty": 0.1, "uncertainty_unit": "arcsec"}
GAUGE = {"description": "Gauge block", "uncertainty": 0.2, "uncertainty_unit": "um"}


def _meta(*standards, tolerance=None, unit="arcsec"):
    data = {"standards": list(standards)}
    if tolerance is not None:
        data |= {"tolerance": tolerance, "tolerance_unit": unit}
    return CertificateMetadata.from_dict(data)


def test_an_angle_standard_in_a_length_budget_is_refused():
    refusals, warnings = standards_fit(_meta(THEODOLITE_STD, GAUGE), "um")
    assert len(refusals) == 1 and "Autocollimating theodolite" in refusals[0]
    assert "another kind" in refusals[0] and warnings == []
    refusals, _ = standards_fit(_meta(THEODOLITE_STD, GAUGE), "arcsec")
    assert len(refusals) == 1 and "Gauge block" in refusals[0]
    # the same kind in another unit fits: 0.5" = 2.42 µrad
    assert standards_fit(_meta(THEODOLITE_STD), "urad") == ([], [])


def test_a_standard_as_large_as_the_tolerance_is_warned_of():
    # the fringe case: the theodolite's 0.5" against a ±0.3" tolerance
    refusals, warnings = standards_fit(_meta(THEODOLITE_STD, POLYGON_STD, tolerance=0.3), "arcsec")
    assert refusals == [] and len(warnings) == 1
    assert "Autocollimating theodolite" in warnings[0] and "0.5\"" in warnings[0]
    # compared in the errors' unit: ±2 µrad = 0.41" < 0.5"; ±3 µrad = 0.62" > 0.5"
    assert len(standards_fit(_meta(THEODOLITE_STD, tolerance=2.0, unit="urad"), "arcsec")[1]) == 1
    assert standards_fit(_meta(THEODOLITE_STD, tolerance=3.0, unit="urad"), "arcsec") == ([], [])
    assert standards_fit(_meta(THEODOLITE_STD), "arcsec") == ([], [])  # no tolerance: no test


def test_lab_defaults_keep_standards_per_workbench():
    legacy = {"lab_name": "Angle Lab", "standards": [THEODOLITE_STD]}
    # saved before: the lab-wide list is offered while no workbench has its own
    assert standards_for(legacy, "fringe") == [THEODOLITE_STD]
    saved = with_workbench_standards(legacy, {"lab_name": "Angle Lab", "operator": "Li",
                                              "standards": [THEODOLITE_STD]}, "theodolite")
    assert saved["standards"] == [THEODOLITE_STD]  # the older key kept as it was
    assert saved[STANDARDS_BY_WORKBENCH] == {"theodolite": [THEODOLITE_STD]}
    assert saved["operator"] == "Li"
    assert standards_for(saved, "theodolite") == [THEODOLITE_STD]
    assert standards_for(saved, "fringe") is None  # #41: never the theodolite's
    assert standards_for(saved, "polygon") is None
    saved = with_workbench_standards(saved, {"standards": [POLYGON_STD]}, "polygon")
    assert standards_for(saved, "polygon") == [POLYGON_STD]
    assert standards_for(saved, "theodolite") == [THEODOLITE_STD]
    # a workbench saved with no standard has none
    saved = with_workbench_standards(saved, {"standards": []}, "fringe")
    assert standards_for(saved, "fringe") == []
