"""The standard uncertainty of each identified signal parameter: the fit's scatter, and the
ADC's stated errors and the stated noise of each sample's phase where they act on it beyond
that scatter, or none where the data cannot give it.

A fitted parameter's u from the least-squares covariance (:class:`ChannelFit`'s ``u_*``) is
the scatter of the digitised record alone. The ADC's offset and gain are each one unknown
value for the whole record (drawn once per run, not per sample), which the scatter cannot
show and which the parameters carry whole: an audit (69, finding 2a) found the offsets'
U covering 5–7 of 40 runs with an ADC offset u of 1 mV stated and 0 of 40 at 2 mV ("8.43 ±
0.02 mV" where the read head's was 10.00 mV), the cosine amplitude 23/40 and 0/40 with a
gain-ratio u of 0.1 % and 0.3 %. So, with the figures the settings state:

* the ADC offset u (each channel's) on that channel's offset A₀;
* the ADC gain-ratio u (of the ratio of the channels' gains) on the amplitude ratio, and,
  relative, on every amplitude A_k and the offset of each channel: the ratio's error may
  sit in either channel's gain, so each is given the whole of it (a gain common to both
  channels moves no phase, and its uncertainty is not stated: it is not in these U);
* neither on a harmonic's phase c_k nor the quadrature error (a gain or an offset moves no
  zero crossing of a harmonic's own phasor);
* the noise of each sample's phase (the phase reference u stated: with N equal steps the
  sampling's timing, with a θ column its reference's, or the noise the column shows if
  larger) on each harmonic's phase c_k, as much as it leaves there beyond the fit's scatter
  (:mod:`models.fringe.sampling_phase_noise`: the scatter holds its mean, but it is largest
  where the fundamental's phase moves the signal most, so c1 scattered up to √1.5 × the
  fit's u; two audits' cos c1 at 36/40 and 37/40 were the draw, 1902 and 1906 of 2000 runs
  covered, tests/benchmarks/fringe_phase_study.py); it is common to both channels (one
  clock), so the quadrature error, their difference, keeps the fit's u of each (which
  holds the part of it that does not cancel).

A harmonic's phase: its U is not the linearised k·u_A/A where the amplitude is a few of its
U (audit 69 finding 2c: c5 covered 144 of 158 runs, floor 146; a rig of the tests' with
harmonics of 2–4 σ, 89–91 %). The fitted phasor is the true one plus a normal error of σ
across it and along it; the error across, σ⊥ = u(c)·Â, is normal whatever the amplitude, so
the true phase lies within arcsin(k·σ⊥/A) of the estimate's at the probability of k. The
amplitude there is not the fitted Â, biased high by the noise (Rice: E[Â²] = A² + σ∥² +
σ⊥²), and a phase is printed only where Â is large, which selects noise that lengthened it:
A is taken as √(Â² − 2(σ∥² + σ⊥²)), twice the bias removed, and the phase is stated only
where that exceeds k·σ⊥ (the arcsine defined). Measured on the exact phasor distribution
(k = 2, 400 000 draws a point): the runs printed covered 95.4 % at A = 2σ, 96.5–97.2 % at
2.5–4σ, 95.6 % at 20σ (the linearised U, printed above U: 92.4 %, 94.0 %, 94.8 % at 2, 2.5,
3σ); at A = 1.5σ, printed in 14 % of runs, 93 %.

The readings' rounding (the ADC's LSB stated, else the step the readings come in: the last
digit typed) is in the fit's scatter only while the noise dithers it: below about δ/2 a
phase rounds alike in every period, and averaging the periods leaves it whole (a rig of the
tests' with no noise: the parameters' U covering 39–54 % of 1000 records, the worst 33–39 %). What repeats at
the phases beyond the scatter is added, and the rounding's own variance floors each u (the
scatter showed 10⁻¹⁷ V for readings typed from a noise-free signal):
:mod:`models.fringe.rounding_at_phases`.

The ADC's integral nonlinearity stated (±b a channel): a transfer error of unknown shape, the
same at the same voltage in every period, so neither the scatter nor averaging shows it (an
audit, 71 finding 1: at ±3 mV the 3rd harmonic's A3 and c3 covered 1–2 of 40 runs, U/oracle
0.02–0.06). Its bound on each parameter, b through the parameter's weights over the
readings (the offset's b, a harmonic's ≈ 4b/π), enters rectangular (B/√3) on that
channel's offset, amplitudes and phases, and, each channel's INL its own, on the amplitude
ratio and the quadrature error from both channels' bounds as independent:
:mod:`models.fringe.linearity_in_parameters`.

With the phase estimated from the signals (no θ column, no N), the parameters are those of
the estimated phase's frame, which the harmonics shift: any distortion of the phase that
leaves the Lissajous figure round is taken into the frame, and the ellipse fit is biased by
the harmonics (the audit's finding 2b: quadrature error +1.386° ± 0.052° where the truth
was +1.000°, sin A1, A3, cos c1 covered 0 of 20). The bias is not observable from the
signals, so it cannot be corrected: no parameter's U is stated then (:data:`ESTIMATED_REASON`),
the values are.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

from models.fringe.linearity_in_parameters import linearity_bounds
from models.fringe.rounding_at_phases import RoundingAtPhases, parameter_variances, phase_groups
from models.fringe.sampling_phase_noise import phase_excess_variance, phase_noise_rad
from models.messages import QT_TR_NOOP, Message, listed, message

__all__ = ["ESTIMATED_REASON", "INCOMPLETE_REASON", "PSO_REASON", "ParameterUncertainty",
           "incomplete_reason", "parameter_uncertainty", "phase_expanded",
           "sample_phase_u_rad"]

#: why no parameter has a U when the phase was estimated from the signals
ESTIMATED_REASON = QT_TR_NOOP(
    "no U is stated for the signal parameters: the phase was estimated from the signals, so "
    "they are identified in the estimated phase's frame, which the signals' harmonics shift "
    "(a distortion of the phase that leaves the Lissajous figure round is not observable); "
    "the bias is not determined, and a U from the fit would not cover it")

#: why no parameter has a U when a particle swarm identified them (assessment 76 H1b: the
#: offsets printed a U of the ADC's figures alone, the rest "—")
PSO_REASON = QT_TR_NOOP(
    "no U is stated for the signal parameters: they were identified by particle swarm (kept "
    "for comparison), which gives no covariance; least squares gives their U")


#: why the parameters' U stated are incomplete: a figure that acts on them not stated
#: (assessment 70 M7: the bundled record's offsets printed "U 0.00018 V" with no word of it
#: beside the table, 5.5 times less than with the ADC's figures stated)
INCOMPLETE_REASON = QT_TR_NOOP(
    "The U of {parameters} is incomplete: {inputs} not stated, so not in it (what it leaves "
    "in these parameters the fit's scatter does not show; stated, it may make these U "
    "several times larger).")
#: the parameters each ADC figure acts on (:func:`parameter_uncertainty`), as named there
_ACTS_ON = {"adc_offset_u_mv": (QT_TR_NOOP("ADC offset"), (QT_TR_NOOP("the offsets A₀"),)),
            "adc_gain_u_pct": (QT_TR_NOOP("ADC gain ratio"),
                               (QT_TR_NOOP("the offsets A₀"), QT_TR_NOOP("the amplitudes A"),
                                QT_TR_NOOP("the amplitude ratio"))),
            # with N equal steps the sampling's timing (sample_phase_u_rad): on the phases
            "phase_reference_u": (QT_TR_NOOP("Phase reference"),
                                  (QT_TR_NOOP("the harmonics' phases c"),)),
            # the integral nonlinearity: on every parameter (linearity_in_parameters)
            "adc_linearity_mv": (QT_TR_NOOP("ADC linearity"),
                                 (QT_TR_NOOP("the offsets A₀"), QT_TR_NOOP("the amplitudes A"),
                                  QT_TR_NOOP("the harmonics' phases c"),
                                  QT_TR_NOOP("the amplitude ratio"),
                                  QT_TR_NOOP("the quadrature error")))}


@dataclass(frozen=True)
class ParameterUncertainty:
    """Standard uncertainties of the parameters: ``channels["sin"]["A0"]`` and so on for
    every key of :meth:`ChannelFit.as_dict` (V, or rad for a phase), the amplitude ratio's
    (a ratio) and the quadrature error's (rad); all empty and ``withheld`` the reason where
    the data cannot give them."""

    channels: dict[str, dict[str, float]] = field(default_factory=dict)
    ratio: float = math.nan
    quadrature_rad: float = math.nan
    withheld: str = ""
    #: whether an ADC figure (offset or gain ratio) is in the U (their ν is infinite: the
    #: effective degrees of freedom are then above the fit's)
    adc_stated: bool = False
    #: the settings' keys of the figures that act on a parameter and are not stated (not in
    #: these U): "adc_offset_u_mv", "adc_gain_u_pct", with N equal steps
    #: "phase_reference_u" (the sampling's timing, on the phases c_k), "adc_linearity_mv"
    not_stated: tuple[str, ...] = ()
    #: each channel's amplitudes' u from the fit's scatter and the readings' rounding alone
    #: (V, by order: the error along a harmonic's phasor, which :func:`phase_expanded` takes
    #: the noise bias with; without the ADC gain's share of the amplitude's U)
    amplitude_scatter: dict[str, dict[int, float]] = field(default_factory=dict)


def parameter_uncertainty(result) -> ParameterUncertainty:
    """The parameters' standard uncertainties of a fringe ``result`` (its fits and the ADC
    figures in its ``inputs``). Kept on the result for the inputs it was worked out from:
    the summary, the JSON, the certificate's tables and its DCC each read it (a θ column of
    10⁶ phases with a linearity stated takes about a second a pass)."""
    key = tuple(sorted((result.inputs or {}).items()))
    kept = result.__dict__.get("_parameter_uncertainty")
    if kept is not None and kept[0] == key:
        return kept[1]
    value = _worked_out(result)
    result.__dict__["_parameter_uncertainty"] = (key, value)
    return value


def _worked_out(result) -> ParameterUncertainty:
    """:func:`parameter_uncertainty`, worked out."""
    if result.phase_source == "estimated":
        return ParameterUncertainty(withheld=ESTIMATED_REASON)
    if getattr(result, "method", "lsq") == "pso":
        return ParameterUncertainty(withheld=PSO_REASON)
    inputs = result.inputs or {}
    offset_v = float(inputs.get("adc_offset_u_mv", 0.0) or 0.0) * 1e-3
    gain = float(inputs.get("adc_gain_u_pct", 0.0) or 0.0) / 100.0
    linearity_v = float(inputs.get("adc_linearity_mv", 0.0) or 0.0) * 1e-3
    fits = (result.sin_fit, result.cos_fit)
    # the INL's bound on each parameter, rectangular (models.fringe.linearity_in_parameters)
    groups = phase_groups(result.theta_rad, result.samples_per_period
                          if result.phase_source == "samples_per_period" else 0) \
        if linearity_v > 0.0 else None
    inl = {label: ({key: (b / math.sqrt(3.0)) ** 2 for key, b in
                    linearity_bounds(groups, fit, linearity_v).items()}
                   if groups is not None else {})
           for label, fit in zip(("sin", "cos"), fits, strict=True)}
    excess = phase_excess_variance(result.theta_rad, result.samples_per_period, fits,
                                   sample_phase_u_rad(result))
    channels: dict[str, dict[str, float]] = {}
    scatter: dict[str, dict[str, float]] = {}  # the fit's and the rounding's, per channel
    for label, fit, extra, rounding in zip(("sin", "cos"), fits, excess, result.rounding,
                                           strict=True):
        both = _with_rounding(fit, rounding)
        scatter[label] = both
        v_inl = inl[label]
        u = {"A0": math.sqrt(both["A0"] + offset_v ** 2 + (fit.offset * gain) ** 2
                             + v_inl.get("A0", 0.0))}
        for k in fit.orders:
            u[f"A{k}"] = math.sqrt(both[f"A{k}"] + (fit.amplitude[k] * gain) ** 2
                                   + v_inl.get(f"A{k}", 0.0))
            u[f"c{k}"] = math.sqrt(both[f"c{k}"] + extra.get(k, 0.0) + v_inl.get(f"c{k}", 0.0))
        channels[label] = u
    s, c = result.sin_fit, result.cos_fit
    ratio = c.amplitude[1] / s.amplitude[1]
    # each channel's INL its own: their parts in the ratio and the quadrature independent
    u_ratio = abs(ratio) * math.sqrt(
        (scatter["sin"]["A1"] + inl["sin"].get("A1", 0.0)) / s.amplitude[1] ** 2
        + (scatter["cos"]["A1"] + inl["cos"].get("A1", 0.0)) / c.amplitude[1] ** 2
        + gain ** 2)
    quadrature = math.sqrt(scatter["sin"]["c1"] + scatter["cos"]["c1"]
                           + inl["sin"].get("c1", 0.0) + inl["cos"].get("c1", 0.0))
    return ParameterUncertainty(channels, u_ratio, quadrature, "",
                                amplitude_scatter={
                                    label: {k: math.sqrt(both[f"A{k}"]) for k in fit.orders}
                                    for (label, both), fit in zip(scatter.items(), fits,
                                                                  strict=True)},
                                adc_stated=bool(offset_v or gain or linearity_v),
                                not_stated=tuple(
                                    key for key in _ACTS_ON if not inputs.get(key) and (
                                        key != "phase_reference_u"
                                        or result.phase_source == "samples_per_period")))


def _with_rounding(fit, rounding: RoundingAtPhases) -> dict[str, float]:
    """Each parameter's variance from the fit's scatter and the readings' rounding
    (:mod:`models.fringe.rounding_at_phases`): the rounding repeated at the phases beyond
    what the scatter shows added, and the rounding's own variance a floor under it."""
    fitted = {"A0": fit.u_offset ** 2}
    for k in fit.orders:
        fitted[f"A{k}"] = fit.u_amplitude.get(k, math.nan) ** 2
        fitted[f"c{k}"] = fit.u_phase.get(k, math.nan) ** 2
    out = {key: value * max(1.0, rounding.fit_floor) for key, value in fitted.items()}
    for excess, floor in rounding.cases:  # each correlation at half a period considered
        added = parameter_variances(fit, excess)
        least = parameter_variances(fit, floor)
        out = {key: max(out[key], fitted[key] + added[key], least[key]) for key in out}
    return out


def incomplete_reason(stated: ParameterUncertainty) -> Message | str:
    """Why the U stated are incomplete (:data:`INCOMPLETE_REASON`, naming the parameters
    and the figures not stated), "" where every figure acting on them is stated or no U is
    stated at all."""
    if stated.withheld or not stated.not_stated:
        return ""
    names = [_ACTS_ON[key][0] for key in stated.not_stated]
    parameters = list(dict.fromkeys(p for key in stated.not_stated for p in _ACTS_ON[key][1]))
    return message(INCOMPLETE_REASON, parameters=listed(message(p) for p in parameters),
                   inputs=listed(message(n) for n in names))


def sample_phase_u_rad(result) -> float:
    """The standard uncertainty of each sample's phase (rad) of a fringe ``result``: the
    phase reference u stated (with N equal steps the sampling's timing), and with a θ column
    the noise its phases show if larger (as the analysis holds the column to)."""
    stated = math.radians(float((result.inputs or {}).get("phase_reference_u", 0.0) or 0.0))
    if result.phase_source == "theta_column":
        return max(stated, phase_noise_rad(result.theta_rad))
    return stated if result.phase_source == "samples_per_period" else 0.0


def phase_expanded(amplitude: float, u_amplitude: float, u_phase: float, k: float) -> float:
    """U of a harmonic's phase (rad) from the fit's amplitude ``amplitude`` and its standard
    uncertainties of the amplitude and of the phase (linearised), at the coverage factor
    ``k``: arcsin(k·σ⊥ / A'), A' the amplitude with twice its noise bias removed; NaN where
    the phase is not stated (A' ≤ k·σ⊥, or the figures not finite)."""
    perp = u_phase * abs(amplitude)
    reduced = amplitude ** 2 - 2.0 * (u_amplitude ** 2 + perp ** 2)
    if not (math.isfinite(reduced) and math.isfinite(perp)) or reduced <= (k * perp) ** 2:
        return math.nan
    return math.asin(k * perp / math.sqrt(reduced))
