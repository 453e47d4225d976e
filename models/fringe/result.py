"""The result of a fringe signal analysis: what the window, the command line, the
certificate and the table export read (its own module, so that none of them needs the
analysis to know its shape)."""

from __future__ import annotations

import functools
import math
from dataclasses import dataclass, field

import numpy as np

from models.fringe.model import ChannelFit, CorrectionTable
from models.fringe.phase import EllipseFit
from models.fringe.rounding_at_phases import (
    RoundingAtPhases,
    phase_groups,
    rounding_at_phases,
)

__all__ = ["FringeResult"]


@dataclass
class FringeResult:
    theta_rad: np.ndarray  # the phase each sample was analysed at
    u_sin: np.ndarray
    u_cos: np.ndarray
    sin_fit: ChannelFit
    cos_fit: ChannelFit
    raw_error: np.ndarray  # as found, in ``unit``
    compensated_error: np.ndarray
    table: CorrectionTable
    lines_per_rev: int
    samples_per_period: int  # 0 when the phase came from θ or was estimated
    method: str
    sin_periods: np.ndarray
    cos_periods: np.ndarray
    phase_source: str = "samples_per_period"
    unit: str = "arcsec"  # or "nm"
    period_length: float = 79.1015625  # one period in ``unit``
    ellipse: EllipseFit | None = None
    table_zero: str = "mean"
    reversals: int = 0
    pso_seconds: float | None = None
    # the particle swarm's: (sin, cos) residual RMS (V) of the least-squares fit of the same
    # readings over the whole record, to set the swarm's beside (empty: fitted by least squares)
    least_squares_residual_rms: tuple[float, ...] = ()
    warnings: list[str] = field(default_factory=list)
    # orders the signals hold that the fit leaves out (the particle swarm's fixed orders):
    # the error between the samples is then not determined (unmodelled_harmonics)
    unmodelled_orders: tuple[int, ...] = ()
    # (order, fitted order) pairs: an order not fitted that the sampled phases fold into a
    # fitted order's amplitude (0: the offset), 5 into 3 at N = 8 (folded_orders): the
    # amplitude is the two together, and the error between the samples not determined
    folded_orders: tuple[tuple[int, int], ...] = ()
    # the budget's inputs the signals cannot show, as set (analysis.BUDGET_INPUTS; 0: not stated)
    inputs: dict[str, float] = field(default_factory=dict)

    @property
    def unit_symbol(self) -> str:
        return "\"" if self.unit == "arcsec" else " nm"

    # read by the summary, the verdict, the figures and the certificate: one pass over a
    # million samples each, not one per reader
    @functools.cached_property
    def raw_range(self) -> tuple[float, float]:
        """(lowest, highest) error as found, in ``unit``."""
        return float(np.min(self.raw_error)), float(np.max(self.raw_error))

    @functools.cached_property
    def compensated_range(self) -> tuple[float, float]:
        return float(np.min(self.compensated_error)), float(np.max(self.compensated_error))

    @functools.cached_property
    def rounding(self) -> tuple[RoundingAtPhases, RoundingAtPhases]:
        """(sin, cos): each channel's rounding (the ADC's LSB stated, else the step its
        readings come in) and its part in the fitted parameters (rounding_at_phases)."""
        per_period = self.samples_per_period if self.phase_source == "samples_per_period" else 0
        stated = 1e-3 * float((self.inputs or {}).get("adc_lsb_mv", 0.0) or 0.0)
        groups = phase_groups(self.theta_rad, per_period)

        def of(u: np.ndarray, fit: ChannelFit) -> RoundingAtPhases:
            dof = max(u.size - (1 + 2 * len(fit.orders)), 1)
            return rounding_at_phases(self.theta_rad, u, fit.orders, per_period, stated,
                                      fit.offset, fit.u_offset, fit.cost / dof, groups)

        return of(self.u_sin, self.sin_fit), of(self.u_cos, self.cos_fit)

    @property
    def raw_peak_to_peak(self) -> float:
        low, high = self.raw_range
        return high - low

    @property
    def compensated_peak_to_peak(self) -> float:
        low, high = self.compensated_range
        return high - low

    @property
    def quadrature_error_deg(self) -> float:
        """(phase of the cos channel's fundamental − the sin channel's) − 90°."""
        d = self.cos_fit.phase[1] - self.sin_fit.phase[1]
        return math.degrees((d - math.pi / 2 + math.pi) % (2 * math.pi) - math.pi)

    @property
    def amplitude_ratio(self) -> float:
        """The cos channel's fundamental over the sin channel's."""
        return self.cos_fit.amplitude[1] / self.sin_fit.amplitude[1]
