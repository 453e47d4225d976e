"""How a declared figure (models/plots.py) is drawn, decided once for the window and the
certificate: each series' colour, line, dash and markers, which series the legend names,
and the order the series are drawn in. The window's renderer (widgets/figure_plot.py) and
the PDF writer (app/writers/certificate_pdf/plots.py) both draw from :func:`series_style`, so a
curve looks the same on screen and on paper.

A series with a ``role`` (the error plot's raw error, set-up model, corrected error and
residuals) is drawn in its role's colour, whatever colour it declares, and the set-up
model dashed; any other series in its own colour.
"""

from __future__ import annotations

from dataclasses import dataclass

from models.plots import PlotFigure, PlotSeries

__all__ = ["DEFAULT_WIDTH", "MARKER_SIZE", "ROLE_STYLES", "SeriesStyle", "drawing_order",
           "legend_series", "role_colour", "series_style"]

DEFAULT_WIDTH = 2.0  # px in the window
MARKER_SIZE = 6.0  # px in the window
BAND_ALPHA = 50  # of 255: a ±band's fill in the window (the PDF mixes it with white at 25 %)


@dataclass(frozen=True)
class SeriesStyle:
    colour: tuple[int, int, int]
    width: float = DEFAULT_WIDTH  # 0: markers only, no line
    dashed: bool = False
    symbol: str | None = None  # "o", "s" or None
    symbol_size: float = MARKER_SIZE


#: the error plot's roles: raw error red with dots, the set-up model grey and dashed, the
#: corrected error blue with squares, the residuals green
ROLE_STYLES = {
    "raw": SeriesStyle((0xC0, 0x39, 0x2B), symbol="o", symbol_size=5),
    "model": SeriesStyle((0x7F, 0x8C, 0x8D), dashed=True),
    "corrected": SeriesStyle((0x1F, 0x5F, 0xBF), symbol="s", symbol_size=5),
    "residual": SeriesStyle((0x2E, 0x8B, 0x57), width=1.5, symbol="o", symbol_size=4),
}


def role_colour(series: PlotSeries) -> tuple[int, int, int]:
    """The colour ``series`` is drawn in: its role's, else its own."""
    style = ROLE_STYLES.get(series.role)
    return style.colour if style is not None else series.color


def series_style(series: PlotSeries) -> SeriesStyle:
    """Colour, line, dash and markers of ``series`` in a figure drawn on one chart: its
    role's colour, dashed when its role is (the set-up model) or it says so, the width and
    markers (dots) it declares. (The window's three-panel error plot draws each role with
    all of its role's style, its markers too: FigureRenderer's ``role_markers``.)"""
    role = ROLE_STYLES.get(series.role)
    width = DEFAULT_WIDTH if series.width is None else series.width
    return SeriesStyle(role_colour(series), width, series.dashed or (role is not None and role.dashed),
                       "o" if series.markers else None,
                       MARKER_SIZE if series.marker_size is None else series.marker_size)


def legend_series(figure: PlotFigure) -> tuple[PlotSeries, ...]:
    """The series the legend names: every labelled one (an unlabelled series is the second
    line of a labelled pair, an envelope's lower edge or the cos channel's fit)."""
    return tuple(s for s in figure.series if s.label)


def drawing_order(figure: PlotFigure) -> tuple[PlotSeries, ...]:
    """The series in the order they are drawn: the set-up model first, under the raw error
    it explains; the others as declared."""
    return tuple(sorted(figure.series, key=lambda s: s.role != "model"))
