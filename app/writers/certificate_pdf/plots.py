"""Vector plots on the page: the error curves with their bands, ticks, labels and legend,
styled as the window draws them (models/plot_style.py)."""

from __future__ import annotations

import math

import numpy as np
from fpdf.enums import XPos, YPos

from app.writers.certificate_pdf.fonts import FONT
from app.writers.certificate_pdf.page import GREY, INK, PageFrame
from app.writers.certificate_pdf.wording import _chinese_then_english
from models.certificate.document import PlotFigure
from models.messages import QT_TR_NOOP
from models.plot_style import drawing_order, legend_series, series_style


class PlotDrawing(PageFrame):
    """The page with its vector plots."""

    def _plot_words(self, text) -> str:
        """A plot's title, axis label or series name in the certificate's language; on a
        bilingual certificate its Chinese, then its English on the one line (zh81: English
        only)."""
        if self.language == "zh+en" and text:
            return " ".join(_chinese_then_english(text))
        return self.say(text)

    def plot(self, figure: PlotFigure, height: float = 62.0) -> None:
        if self.will_page_break(height + 12):
            self.add_page()
        self.set_font(FONT, "B", 9)
        self.cell(0, 5, self._plot_words(figure.title), new_x=XPos.LMARGIN, new_y=YPos.NEXT)
        x0, y0 = self.l_margin + 14, self.get_y() + 2
        w, h = self.epw - 16, height - 14
        xs = np.concatenate([s.x for s in figure.series if s.x.size])
        ys = np.concatenate([s.y for s in figure.series if s.y.size]
                            + [s.y + sign * s.band for s in figure.series if s.band is not None
                               for sign in (-1.0, 1.0)])
        xs = np.concatenate([xs] + [s.x for s in figure.series if s.band is not None
                                    for _ in (0, 1)])
        finite = np.isfinite(xs) & np.isfinite(ys)
        if not finite.any():
            self.paragraph(QT_TR_NOOP("(no data)"))
            return
        x_ticks = _nice_ticks(float(xs[finite].min()), float(xs[finite].max()))
        if xs[finite].min() >= 0 and 270 < xs[finite].max() <= 360:  # a turn: 0…360°, not 400°
            x_ticks = [float(v) for v in range(0, 361, 45)]
            x_lo, x_hi = 0.0, 360.0
        else:
            x_lo, x_hi = _data_ends(x_ticks, float(xs[finite].min()), float(xs[finite].max()))
        y_ticks = _nice_ticks(float(ys[finite].min()), float(ys[finite].max()))
        if (float(ys[finite].max()) - y_ticks[0]) > 0.85 * (y_ticks[-1] - y_ticks[0]):
            # headroom for the legend, which is drawn inside the top of the frame: a band or
            # curve reaching the top would be hidden under it
            y_ticks.append(round(y_ticks[-1] + y_ticks[-1] - y_ticks[-2], 12))
        xlo, xhi, ylo, yhi = x_lo, x_hi, y_ticks[0], y_ticks[-1]
        x_ticks = [t for t in x_ticks if xlo - 1e-9 * (xhi - xlo) <= t <= xhi + 1e-9 * (xhi - xlo)]

        def px(v):
            return x0 + (np.asarray(v) - xlo) / (xhi - xlo) * w

        def py(v):
            return y0 + h - (np.asarray(v) - ylo) / (yhi - ylo) * h

        self.set_line_width(0.1)
        self.set_draw_color(220, 220, 220)
        self.set_font(FONT, "", 6.5)
        for t in y_ticks:
            self.line(x0, float(py(t)), x0 + w, float(py(t)))
            self.text(x0 - 1.2 - self.get_string_width(_tick(t, y_ticks)), float(py(t)) + 1.0,
                      _tick(t, y_ticks))
        for t in x_ticks:
            self.line(float(px(t)), y0, float(px(t)), y0 + h)
            label = _tick(t, x_ticks)
            self.text(float(px(t)) - self.get_string_width(label) / 2, y0 + h + 3.2, label)
        self.set_draw_color(*GREY)
        self.set_line_width(0.25)
        self.rect(x0, y0, w, h)
        if ylo < 0 < yhi:
            self.set_draw_color(120, 120, 120)
            self.line(x0, float(py(0.0)), x0 + w, float(py(0.0)))
        for s in figure.series:
            if s.band is None:
                continue
            ok = np.isfinite(s.x) & np.isfinite(s.y) & np.isfinite(s.band)
            upper = list(zip(px(s.x[ok]).tolist(), py((s.y + s.band)[ok]).tolist(), strict=True))
            lower = list(zip(px(s.x[ok]).tolist(), py((s.y - s.band)[ok]).tolist(), strict=True))
            if len(upper) >= 2:
                colour = series_style(s).colour
                self.set_fill_color(*[int(255 - (255 - c) * 0.25) for c in colour])
                self.polygon(upper + lower[::-1], style="F")
        # drawn as in the window (models/plot_style.py): the set-up model, dashed, first,
        # under the raw error it explains
        for s in drawing_order(figure):
            ok = np.isfinite(s.x) & np.isfinite(s.y)
            pts = list(zip(px(s.x[ok]).tolist(), py(s.y[ok]).tolist(), strict=True))
            style = series_style(s)
            colour = style.colour
            self.set_draw_color(*colour)
            self.set_line_width(0.3)
            if len(pts) >= 2:
                with self.local_context():
                    if style.dashed:
                        self.set_dash_pattern(dash=1.2, gap=0.8)
                    self.polyline(pts)
            if s.markers and len(pts) <= 400:
                self.set_fill_color(*colour)
                for x, y in pts:
                    self.circle(x, y, 0.45, style="F")
        x_label, y_label = self._plot_words(figure.x_label), self._plot_words(figure.y_label)
        self.mixed_text(x0 + w / 2 - self.text_width(x_label, 7) / 2, y0 + h + 7, x_label, 7)
        with self.rotation(90, self.l_margin + 1.5, y0 + h / 2):
            self.mixed_text(self.l_margin + 1.5 - self.text_width(y_label, 7) / 2,
                            y0 + h / 2, y_label, 7)
        lx = x0 + 2
        for s in legend_series(figure):
            self.set_draw_color(*series_style(s).colour)
            self.set_line_width(0.6)
            self.line(lx, y0 + 3, lx + 5, y0 + 3)
            name = self._plot_words(s.label)
            self.mixed_text(lx + 6, y0 + 4, name, 7)
            lx += 9 + self.text_width(name, 7)
        self.set_line_width(0.2)
        self.set_draw_color(*INK)
        self.set_y(y0 + h + 9)


#: the share of the axis a tick may reach past the data before the axis ends at the data
#: instead (day review 69 F6: the fringe plots' x axis ran to 80 periods for 64 of data)
PAST_DATA = 0.1


def _data_ends(ticks: list[float], lo: float, hi: float) -> tuple[float, float]:
    """The x axis's ends: the outer ticks, or the data's own end where the tick beyond it
    lies more than :data:`PAST_DATA` of the axis past it."""
    span = ticks[-1] - ticks[0]
    if not hi - lo > 1e-9 * max(span, 1e-300):
        return ticks[0], ticks[-1]
    low = lo if lo - ticks[0] > PAST_DATA * span else ticks[0]
    high = hi if ticks[-1] - hi > PAST_DATA * span else ticks[-1]
    return low, high


def _nice_ticks(lo: float, hi: float, count: int = 6) -> list[float]:
    if not math.isfinite(lo) or not math.isfinite(hi):
        return [0.0, 1.0]
    if hi - lo < 1e-12:
        pad = max(abs(lo) * 0.1, 1e-3)
        lo, hi = lo - pad, hi + pad
    raw = (hi - lo) / count
    mag = 10 ** math.floor(math.log10(raw))
    step = next(m * mag for m in (1, 2, 2.5, 5, 10) if m * mag >= raw)
    start = math.floor(lo / step) * step
    ticks = []
    v = start
    while not ticks or ticks[-1] < hi - 1e-9 * step:
        ticks.append(round(v, 12))
        v += step
        if len(ticks) > 50:
            break
    if len(ticks) < 2:
        ticks.append(ticks[-1] + step)
    return ticks


def _tick(value: float, ticks: list[float]) -> str:
    step = ticks[1] - ticks[0]
    if abs(value) < 1e-9 * step:
        value = 0.0  # no "-0.0"
    decimals = max(0, -int(math.floor(math.log10(step))) + (1 if step / 10 ** math.floor(
        math.log10(step)) == 2.5 else 0))
    return f"{value:.{decimals}f}"
