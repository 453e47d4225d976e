"""A DCC AngleBench issues, read back as a reference standard's certificate (*Read from
DCC…*), gives the U of the standard's errors of indication, not of a fitted set-up parameter
(0.8.11: a theodolite's DCC gave 59", its tilt direction α's U; a fringe's 5157", its
signal phase c5's). Every expected figure is recomputed here from the file with lxml: the
largest U/k among the quantities PTB's refType basic_measurementError marks."""

from __future__ import annotations

import math
from pathlib import Path

import pytest
from lxml import etree

from models.dcc import vocabulary as v
from models.dcc.reader import polygon_standard, read_polygon_dcc, read_standard_dcc
from tests.app.test_dcc_out import NS, SCHEMA

pytestmark = pytest.mark.slow  # each case prints a certificate

#: arcseconds per D-SI unit, written out here (not the reader's table)
_ARCSEC = {r"\arcsecond": 1.0, r"\degree": 3600.0, r"\radian": 180.0 * 3600.0 / math.pi}
_CASES = ("theodolite", "polygon", "fringe", "positioning", "crosscal")


@pytest.fixture(scope="module")
def dccs(issued_samples) -> dict[str, Path]:
    """Each sample's DCC as issued (tests/conftest.py's ``issued_samples``, shared with the
    other DCC tests)."""
    found = {}
    for case in _CASES:
        code, said, _, xml, _, _ = issued_samples[case]
        assert code == 0, said
        found[case] = xml
    return found


def _largest(quantities) -> tuple[float, float, str]:
    """(U in arcseconds, k, quantity's name) of the largest U/k among ``quantities`` that
    carry an expanded U (si:real or si:realListXMLList)."""
    best = (0.0, 1.0, "")
    for q in quantities:
        for real, value, unit, k in (
                ("si:realListXMLList", "si:valueExpandedMUXMLList", "si:unitXMLList",
                 "si:coverageFactorXMLList"),
                ("si:real", "si:valueExpandedMU", "si:unit", "si:coverageFactor")):
            element = q.find(real, NS)
            if element is None or element.find(f".//{value}", NS) is None:
                continue
            us = [float(x) for x in element.find(f".//{value}", NS).text.split()]
            ks = [float(x) for x in element.find(f".//{k}", NS).text.split()]
            ks = ks * len(us) if len(ks) == 1 else ks
            factor = _ARCSEC.get(element.findtext(unit, namespaces=NS).strip())
            if factor is None:  # a signal parameter in volts
                continue
            name = q.findtext("dcc:name/dcc:content", namespaces=NS)
            for u, kk in zip(us, ks, strict=True):
                if u * factor / kk > best[0] / best[1]:
                    best = (u * factor, kk, name)
    return best


def _errors(tree) -> tuple[float, float, str]:
    """The largest U/k among the results' quantities marked basic_measurementError."""
    return _largest(q for q in tree.iterfind(".//dcc:results//dcc:quantity", NS)
                    if v.PTB_MEASUREMENT_ERROR in (q.get("refType") or "").split())


def _setup(tree) -> tuple[float, float, str]:
    """The largest U/k among the set-up parameters."""
    return _largest(tree.iterfind(f".//dcc:result[@refType='{v.REFTYPE_SETUP_PARAMETERS}']"
                                  "//dcc:quantity", NS))


@pytest.mark.parametrize("case", _CASES)
def test_a_dcc_read_as_a_standard_gives_the_u_of_its_errors(dccs, case):
    tree = etree.parse(str(dccs[case])).getroot()
    u, k, name = _errors(tree)
    assert u > 0, case
    got = read_standard_dcc(dccs[case], SCHEMA)
    assert got.unit == "arcsec"
    assert got.uncertainty == pytest.approx(u, rel=1e-12) and got.coverage_factor == k
    said = got.notes[-1]
    assert "U is that of “" in said and f"{name}”" in said, said
    assert "the largest of its results that are measurement errors or deviations" in said
    # the set-up parameters' U (what 0.8.11 took when larger) is named as not used
    setup = _setup(tree)
    if setup[0]:
        title = tree.find(f".//dcc:result[@refType='{v.REFTYPE_SETUP_PARAMETERS}']"
                          "/dcc:name/dcc:content", NS).text
        assert "not used: " in said and title in said.split("not used: ")[1], said


def test_the_figures_0_8_11_read_from_a_fitted_parameter_are_gone(dccs):
    """What the set-up parameters' largest U/k was, and what is read now."""
    theodolite = etree.parse(str(dccs["theodolite"])).getroot()
    setup = _setup(theodolite)
    # α's U as printed, 0.017° (59″ until its U was printed in the value's degrees:
    # assessment 78 L3)
    assert setup[0] == pytest.approx(0.017 * 3600, rel=1e-5) and setup[2] == "Tilt direction α"
    got = read_standard_dcc(dccs["theodolite"], SCHEMA)
    assert got.uncertainty < 2.0  # the corrected error's U, 1.44" (was 59")
    fringe = read_standard_dcc(dccs["fringe"], SCHEMA)
    assert fringe.uncertainty < 0.1  # the compensated error's U, 0.014" (was 5157")
    assert "Signal parameters identified" in fringe.notes[-1]
    polygon = read_standard_dcc(dccs["polygon"], SCHEMA)
    assert polygon.uncertainty < 1.0  # the corrected error's U, 0.42" (was ω's 8.64")
    # the reference polygon's face deviations in it are the reference's, not the item's
    assert "Reference polygon face deviations" in polygon.notes[-1].split("not used: ")[1]


def test_a_polygons_dcc_gives_the_same_u_read_as_a_polygon_and_as_a_standard(dccs):
    """*Load polygon certificate…* (the face-deviation reader) and *Read from DCC…* under
    the standards table put the same figure in the standards table for the same file."""
    reference = read_polygon_dcc(dccs["crosscal"], SCHEMA)
    as_polygon = polygon_standard(reference)
    as_standard = read_standard_dcc(dccs["crosscal"], SCHEMA).as_standard()
    assert as_standard["uncertainty"] == as_polygon["uncertainty"]
    assert as_standard["basis"] == as_polygon["basis"]
    # and what it is per, one rule for both (dccin74 F3: the dialog kept the row's)
    assert as_standard["applies_to"] == as_polygon["applies_to"] == "from face 1"
    assert as_standard["uncertainty"] == pytest.approx(
        max(reference.expanded_uncertainty.values()) / reference.coverage_factor, rel=1e-12)
    # the face deviations restate the errors from face 1: not named as "not used"
    assert "not used" not in read_standard_dcc(dccs["crosscal"], SCHEMA).notes[-1]


def test_the_window_fills_the_standards_u_of_the_errors(dccs, qtbot):
    """The certificate details' *Read from DCC…* with the theodolite's DCC: the standard's
    u is the corrected error's U/k, and the note under the table says whose it is."""
    from models.certificate.metadata import CertificateMetadata
    from widgets.certificate_dialog import CertificateDialog

    tree = etree.parse(str(dccs["theodolite"])).getroot()
    u, k, name = _errors(tree)
    dialog = CertificateDialog(CertificateMetadata())
    qtbot.addWidget(dialog)
    assert dialog.read_standard_dcc(str(dccs["theodolite"]), str(SCHEMA or ""))
    standard = dialog.metadata().standards[0]
    assert standard.basis == "u" and standard.uncertainty_unit == "arcsec"
    assert standard.uncertainty == pytest.approx(u / k, rel=1e-5)  # the cell's 6 digits
    assert name in dialog.error_label.text()
    assert "Set-up parameters identified" in dialog.error_label.text()
