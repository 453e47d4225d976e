"""Results read in arcseconds, microradians or millidegrees (#19): the conversions are
checked against figures worked by hand, text keeps each figure's resolution, and what is
not an angle (nm, V, a quoted cell) is left alone."""

from __future__ import annotations

import math
import re

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

from models.display_units import (
    ANGLE_UNITS,
    angle_unit,
    figure_in_unit,
    figures_in_unit,
    header_in_unit,
    in_unit,
    table_in_unit,
    text_in_unit,
)
from models.messages import joined, message, rendered
from models.plots import PlotFigure, PlotSeries
from models.quantity import Quantity

URAD, MDEG, ARCSEC = ANGLE_UNITS["urad"], ANGLE_UNITS["mdeg"], ANGLE_UNITS["arcsec"]


def test_one_arcsecond_in_each_unit():
    # 1" = π / (180·3600) rad = 4.8481368 µrad; 3.6" = 1 mdeg
    assert URAD.per_arcsec == pytest.approx(4.8481368, rel=1e-8)
    assert MDEG.per_arcsec * 3.6 == pytest.approx(1.0)
    assert header_in_unit("error (\")", URAD) == ("error (µrad)", pytest.approx(4.8481368))
    header, factor = header_in_unit("A (urad)", MDEG)
    assert header == "A (mdeg)" and factor == pytest.approx(180 / math.pi * 1e-3)
    assert header_in_unit("signal (V)", URAD) == ("signal (V)", 1.0)
    assert header_in_unit("corrected_error_arcsec", MDEG) == ("corrected_error_mdeg",
                                                              pytest.approx(1 / 3.6))
    assert header_in_unit("arcsecond_count", MDEG)[1] == 1.0
    with pytest.raises(ValueError, match="urad"):
        angle_unit("gon")


def test_text_is_rewritten_with_its_resolution():
    line = 'Raw error -423.00" … +300.20" (peak-to-peak 723.20"), grade 3 (±1")'
    assert text_in_unit(line, MDEG) == ("Raw error -117.500 mdeg … +83.389 mdeg "
                                        "(peak-to-peak 200.889 mdeg), grade 3 (±0.278 mdeg)")
    assert text_in_unit("B = 6.062\"", URAD) == "B = 29.389 µrad"
    assert text_in_unit(line, ARCSEC) == line
    back = text_in_unit(text_in_unit("ψ = 480.0\" ± 0.01\"", URAD), ARCSEC)
    assert back == "ψ = 480.00\" ± 0.01000\""  # a digit more each way, never one less


def test_what_is_not_an_angle_is_left_alone():
    for text in ('cell "1.5" cannot be read', "drift 0.45 nm", "u = 1.2 V", "θ = 30°",
                 "column A(″)", "A5\" is a name", "L = 16384"):
        assert text_in_unit(text, URAD) == text


@given(st.floats(-1e5, 1e5, allow_nan=False), st.integers(0, 4),
       st.sampled_from(["urad", "mdeg"]))
def test_text_round_trip_keeps_the_figure_within_its_resolution(value, decimals, key):
    written = f"{value:+.{decimals}f}\""
    shown = text_in_unit(f"E = {written}", ANGLE_UNITS[key])
    number = re.search(r"[+\-]\d+(\.\d+)?", shown)
    assert number is not None and shown.endswith(ANGLE_UNITS[key].symbol)
    recovered = float(number.group(0)) / ANGLE_UNITS[key].per_arcsec
    assert abs(recovered - float(written[:-1])) <= 0.5 * 10.0 ** -decimals + 1e-9


def test_plots_scale_their_angles_and_nothing_else():
    band = np.array([0.1, 0.2])
    figure = PlotFigure("Errors", "θ (°)", "error (\")", (
        PlotSeries("raw", np.array([0.0, 1.0]), np.array([1.0, -2.0]), band=band),))
    shown = figure_in_unit(figure, URAD)
    assert shown.y_label == "error (µrad)"
    np.testing.assert_allclose(shown.series[0].y, np.array([1.0, -2.0]) * 4.8481368, rtol=1e-8)
    np.testing.assert_allclose(shown.series[0].band, band * 4.8481368, rtol=1e-8)
    np.testing.assert_array_equal(shown.series[0].x, [0.0, 1.0])
    volts = PlotFigure("Signals", "θ", "signal (V)", figure.series)
    assert figure_in_unit(volts, URAD) is volts


def test_tables_and_named_figures():
    header, rows = table_in_unit(("target (deg)", "x̄↑ (\")", "n↑"),
                                 [("10", "+3.600", "5"), ("20", "—", "5")], MDEG)
    assert header == ("target (deg)", "x̄↑ (mdeg)", "n↑")
    assert rows == [("10", "+1.0000", "5"), ("20", "—", "5")]
    assert figures_in_unit({"A (\")": 3.6, "runs": 5}, MDEG) == {"A (mdeg)": pytest.approx(1.0),
                                                                  "runs": 5}


# -- #32: a figure is converted from the typed arguments of its Message, never from the
# rendered text: D°M'S" is no number with a unit and survives every unit ------------------

def test_a_dms_reading_is_left_as_it_is():
    # the bug of #32: 56.7" inside 12°34'56.7" was taken for a figure and rewritten
    for unit in (URAD, MDEG, ARCSEC):
        assert text_in_unit("12°34'56.7\"", unit) == "12°34'56.7\""
        assert str(in_unit(message("reading {r}", r="12°34'56.7\""), unit)) == "reading 12°34'56.7\""
    shown = in_unit(message("reading {r}, error {e}", r="12°34'56.7\"",
                            e=Quantity(1.0, "arcsec", ".2f")), URAD)
    assert str(shown) == "reading 12°34'56.7\", error 4.85 µrad"


def test_a_message_is_converted_from_its_figures_and_stays_translatable():
    text = message("peak-to-peak {ptp}, drift {drift}", ptp=Quantity(3.6, "arcsec", ".2f"),
                   drift=Quantity(0.45, "nm", ".2f"))
    shown = in_unit(text, MDEG)
    assert str(shown) == "peak-to-peak 1.000 mdeg, drift 0.45 nm"
    assert shown.template == text.template  # translated as before, filled with the new figures
    assert rendered(shown, lambda t: t.replace("drift {", "漂移 {")) == \
        "peak-to-peak 1.000 mdeg, 漂移 0.45 nm"
    # a figure passed already formatted converts when it is one number with its unit
    assert str(in_unit(message("B = {b}", b="6.062\""), URAD)) == "B = 29.389 µrad"
    # parts are converted part by part; plain text parts are left as they are
    joined_text = joined([message("U = {u}", u=Quantity(1.0, "arcsec", ".2f")), "; 12°34'5\""])
    assert str(in_unit(joined_text, URAD)) == "U = 4.85 µrad; 12°34'5\""


_DMS = st.builds(lambda d, m, s, p: f"{d}°{m:02d}'{s:0{3 + p if p else 2}.{p}f}\"",
                 st.integers(0, 359), st.integers(0, 59),
                 st.floats(0, 59.9, allow_nan=False), st.integers(0, 3))


@given(_DMS, st.sampled_from(["urad", "mdeg", "arcsec"]), st.sampled_from(["", "reading ", "(",
                                                                            "θ = "]))
def test_any_dms_text_survives(dms, key, before):
    text = f"{before}{dms} at the face"
    assert text_in_unit(text, ANGLE_UNITS[key]) == text
    assert str(in_unit(message("{before}{r} at the face", before=before, r=dms),
                       ANGLE_UNITS[key])) == text


@given(st.floats(-1e5, 1e5, allow_nan=False), st.integers(0, 4),
       st.sampled_from(["urad", "mdeg"]))
def test_a_converted_quantity_round_trips(value, decimals, key):
    typed = Quantity(value, "arcsec", f"+.{decimals}f")
    there = typed.to(key)
    back = there.to("arcsec")
    assert back.value == pytest.approx(value, rel=1e-12, abs=1e-9)
    # and its text states the value at least as finely as the text it came from did
    shown = str(in_unit(message("E = {e}", e=typed), ANGLE_UNITS[key]))
    number = float(shown.split()[2])
    recovered = number / ANGLE_UNITS[key].per_arcsec
    assert abs(recovered - value) <= 0.5 * 10.0 ** -decimals + 1e-9


def test_a_plot_states_its_unit_as_data_and_is_converted_by_it():
    series = (PlotSeries("raw", np.array([0.0, 1.0]), np.array([3.6, -7.2])),)
    declared = PlotFigure("Errors", "θ (°)", "error (\")", series)
    assert declared.y_unit == "arcsec"  # read once from its title when it is declared
    shown = figure_in_unit(declared, MDEG)
    assert (shown.y_unit, shown.y_label) == ("mdeg", "error (mdeg)")
    np.testing.assert_allclose(shown.series[0].y, [1.0, -2.0])
    np.testing.assert_allclose(figure_in_unit(shown, ARCSEC).series[0].y, [3.6, -7.2])
    assert PlotFigure("Signals", "θ", "signal (V)", series).y_unit == ""
    assert PlotFigure("Interferometer", "θ", "error (nm)", series).y_unit == "nm"
    nm = PlotFigure("Interferometer", "θ", "error (nm)", series)
    assert figure_in_unit(nm, URAD) is nm  # nm stay nm
    # a unit given as data wins over a title that states none
    stated = PlotFigure("Errors", "θ (°)", "error", series, y_unit="urad")
    np.testing.assert_allclose(figure_in_unit(stated, URAD).series[0].y, [3.6, -7.2])
    np.testing.assert_allclose(figure_in_unit(stated, ARCSEC).series[0].y,
                               np.array([3.6, -7.2]) / 4.8481368, rtol=1e-8)
