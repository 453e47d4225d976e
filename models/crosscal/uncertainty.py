"""Uncertainty of a cross-calibration beyond the least squares' own covariance.

* :func:`estler_full_rosette` — the closed form for the full rosette (every face at
  every step once, one reading each): u²(Ê_k) = u²(d̂_i) = σ²(n − 1)/n², covariance
  −σ²/n² within a set, 0 between the sets, ν = (n − 1)(n − 2) (Estler, "Uncertainty
  analysis for angle calibrations using circle closure", J. Res. NIST 103 (1998) 141).
* :func:`design_uncertainty` — what a planned design will give, before measuring: the
  standard uncertainty of each value for a reading σ (for Gaussian readings this is the
  design's Cramér–Rao bound, which the least squares attains).
* :func:`monte_carlo_check` — the stated uncertainty checked by simulation on the
  measured design: readings drawn about the fitted model with the fitted σ, solved
  again; the scatter of the results against the stated u, and how often U covers.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from models.crosscal.solve import CrossCalibration, solve_crosscal

__all__ = ["MonteCarloCheck", "design_uncertainty", "drift_effect_arcsec", "drift_pattern_arcsec",
           "estler_full_rosette", "monte_carlo_check", "own_drift_effect_arcsec",
           "reported_drift_bias_arcsec", "scale_effect_arcsec", "tilt_effect_arcsec",
           "tilt_fit_effect_arcsec", "unchecked_drift_mountings"]


def estler_full_rosette(n: int, sigma_arcsec: float) -> tuple[float, float, int]:
    """(u of each E_k and d_i, their covariance within a set, ν) for the full rosette."""
    return sigma_arcsec * math.sqrt(n - 1) / n, -sigma_arcsec**2 / n**2, (n - 1) * (n - 2)


def design_readings(n: int, mountings, closure: bool = True
                    ) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """Noise-free readings of a perfect polygon on a perfect encoder for a design:
    (mounting, position, encoder_deg, ac_x_arcsec), every mounting from 0°."""
    rows = []
    for j in mountings:
        faces = [(j + k) % n + 1 for k in range(n)] + ([j + 1] if closure else [])
        rows += [(j, face, (t * 360.0 / n) % 360.0, 0.0) for t, face in enumerate(faces)]
    mounting, position, encoder_deg, ac_x_arcsec = (np.array(col) for col in zip(*rows, strict=True))
    return mounting, position, encoder_deg, ac_x_arcsec


def design_uncertainty(n: int, mountings, sigma_arcsec: float, closure: bool = True,
                       drift: str = "fit") -> CrossCalibration:
    """The result a design gives for readings of σ (its covariance and u per value; the
    values themselves are zeros): the uncertainty to expect before measuring."""
    return solve_crosscal(*design_readings(n, mountings, closure), faces=n,
                          noise_arcsec=sigma_arcsec, drift=drift)


@dataclass(frozen=True)
class MonteCarloCheck:
    runs: int
    #: standard deviation of the simulated results per value, and the u stated (k = 1)
    encoder_u_mc_arcsec: np.ndarray
    polygon_u_mc_arcsec: np.ndarray
    encoder_u_stated_arcsec: np.ndarray
    polygon_u_stated_arcsec: np.ndarray
    #: fraction of values whose own U (each run's σ, ν and k) covers the simulation's truth
    coverage: float
    probability: float  # the coverage probability U is stated for
    dof: float = math.inf  # ν of the σ the readings gave

    @property
    def ratio(self) -> float:
        """RMS of the simulated scatter over RMS of the stated u (1 when they agree)."""
        mc = np.concatenate([self.encoder_u_mc_arcsec, self.polygon_u_mc_arcsec])
        stated = np.concatenate([self.encoder_u_stated_arcsec, self.polygon_u_stated_arcsec])
        return float(np.sqrt(np.mean(mc**2) / np.mean(stated**2)))


def monte_carlo_check(mounting, position, encoder_deg, ac_x_arcsec, runs: int = 200, seed: int = 0,
                      **solve_kwargs) -> MonteCarloCheck:
    """Solve the readings, then ``runs`` times: horizontal readings drawn about the fitted
    model with the fitted σ (normal), solved with the same settings. Compares only the
    determined parts when the design leaves harmonics unseen."""
    ac_x = np.asarray(ac_x_arcsec, dtype=float)
    reference = solve_crosscal(mounting, position, encoder_deg, ac_x, **solve_kwargs)
    sigma = reference.sigma_arcsec
    rng = np.random.default_rng(seed)
    n = reference.faces
    fitted = ac_x + reference.residuals_arcsec  # y = … − c: these readings fit exactly
    truth = np.concatenate([reference.encoder_error_determined_arcsec,
                            reference.polygon_deviation_determined_arcsec])
    values = np.empty((runs, 2 * n))
    covered = 0
    for q in range(runs):
        run = solve_crosscal(mounting, position, encoder_deg, fitted + rng.normal(0.0, sigma, ac_x.size),
                             **solve_kwargs)
        values[q] = np.concatenate([run.encoder_error_determined_arcsec,
                                    run.polygon_deviation_determined_arcsec])
        u = np.concatenate([run.encoder_error_expanded_arcsec, run.polygon_deviation_expanded_arcsec])
        covered += int(np.sum(np.abs(values[q] - truth) <= u))
    scatter = np.sqrt(np.mean((values - truth) ** 2, axis=0))
    return MonteCarloCheck(runs, scatter[:n], scatter[n:], reference.encoder_error_u_arcsec,
                           reference.polygon_deviation_u_arcsec, covered / (runs * 2 * n),
                           reference.probability, reference.dof)


def _gain(solution: CrossCalibration, combine) -> np.ndarray:
    """G, or ``combine``·G for combinations of the results (differences from face 1, say)."""
    return solution.gain if combine is None else np.asarray(combine, dtype=float) @ solution.gain


def scale_effect_arcsec(solution: CrossCalibration, ac_x_arcsec, combine=None) -> np.ndarray:
    """|(G·c)| per value of (E, d) (2n): the results' change per unit relative scale error s of
    the autocollimator, whose readings c become (1 + s)·c: δy = −s·c, δ(E, d) = −s·G·c exactly
    (G = ``solution.gain``; a constant zero offset cancels in each mounting's offset); of
    ``combine``·(E, d) when given."""
    c = np.asarray(ac_x_arcsec, dtype=float)
    return np.abs(_gain(solution, combine) @ c)


def roll_pattern_arcsec(solution: CrossCalibration, ac_y_arcsec, combine=None) -> np.ndarray:
    """G·y per value of (E, d) (2n): the results' change per radian of the autocollimator's
    roll ρ about its line of sight, which turns ρ·y of each vertical reading y into the
    horizontal one: δ(E, d) = ρ·G·y exactly (a constant part of y cancels in each mounting's
    offset); 0 without vertical readings (a reading not made is taken as 0: the tilt bound
    then holds that mounting). Of ``combine``·(E, d) when given."""
    gain = _gain(solution, combine)
    if ac_y_arcsec is None:
        return np.zeros(gain.shape[0])
    return gain @ np.nan_to_num(np.asarray(ac_y_arcsec, dtype=float))


def roll_effect_arcsec(solution: CrossCalibration, ac_y_arcsec, combine=None) -> np.ndarray:
    """|:func:`roll_pattern_arcsec`|: the half-width per radian of roll bound."""
    return np.abs(roll_pattern_arcsec(solution, ac_y_arcsec, combine))


def unchecked_drift_mountings(solution: CrossCalibration) -> tuple[int, ...]:
    """The mountings whose autocollimator drift is neither measured nor fitted: no closure
    reading of their own (the drift over a mounting is seen only by reading its first face
    again at the end, at the same encoder step), and not fitted through the other mountings'
    closure readings (solve_crosscal fits it, in the "fit" mode, where the design determines
    it: the other mountings' closure readings fix the encoder's error over the turn, and the
    mounting's readings against it then show its drift)."""
    drift = np.asarray(solution.drift_arcsec, dtype=float)
    return tuple(j for j, d in zip(solution.mountings, drift, strict=True) if not np.isfinite(d))


def drift_effect_arcsec(solution: CrossCalibration, combine=None) -> np.ndarray:
    """Half-width per value of (E, d) (2n) — of ``combine``·(E, d) when given — of the results'
    change per 1″ of autocollimator drift over a mounting (a full turn), the same in every
    mounting with no closure reading and linear in the reading's order t: δy = −D·t/n on
    those mountings' rows, δ(E, d) = −D·Σ_j G_j·(t/n) exactly (|:func:`drift_pattern_arcsec`|).
    Every mounting starts at step 0 and reads in step order, so t is the step k: a drift of
    one sign in every mounting is exactly a ramp over the encoder's steps, which no reading
    but a closure (step 0 read again after the turn) can tell from the encoder's error. Where
    the mountings drift differently, the difference is seen by the design (with three
    mountings or more the drifts are determined but for their common part) and, σ taken from
    the residuals, is in the reading scatter; the common part is what this bounds (σ stated,
    the difference is bounded too: :func:`own_drift_effect_arcsec`). A constant part cancels
    in each mounting's offset. Zero for the face deviations of such a drift (it follows the
    steps)."""
    return np.abs(drift_pattern_arcsec(solution, combine))


def own_drift_effect_arcsec(solution: CrossCalibration, combine=None) -> np.ndarray:
    """Half-width per value of (E, d) (2n) — of ``combine``·(E, d) when given — per 1″ of
    drift over a mounting, that the mountings with no closure reading add when each drifts
    its own way, beyond :func:`drift_effect_arcsec` (the same drift in all of them); zeros
    unless σ was stated (taken from the residuals, the scatter holds what differs between
    the mountings), and with one such mounting (its drift is the one that bounds).

    Each such mounting j moves the results by −D_j·P_j (P_j = G_j·(t/n) on its rows,
    exactly). The bound says |D_j| ≤ B for each, not how the D_j go together: from the same
    in every mounting (correlation 1: half-width B·|Σ_j P_j|) to independent (B·√Σ_j P_j²)
    — any mix of the two lies between them (the variance is linear in the correlation), so
    the larger is taken point by point. This gives the part beyond the common one,
    √max(0, Σ_j P_j² − (Σ_j P_j)²), so that the two rows in quadrature are that larger one:
    where the same drift in every mounting moves a value most, nothing is added. (Drifts
    that go against each other from mounting to mounting — the same autocollimator, the
    same day — are not taken.)"""
    patterns = _drift_patterns(solution, combine)[1:]
    if not solution.sigma_stated or patterns.shape[0] == 0:
        return np.zeros(_gain(solution, combine).shape[0])
    common = np.sum(patterns, axis=0)
    return np.sqrt(np.clip(np.sum(patterns**2, axis=0) - common**2, 0.0, None))


def reported_drift_bias_arcsec(solution: CrossCalibration, combine=None) -> np.ndarray:
    """The bias per value of (E, d) (2n) — of ``combine``·(E, d) when given — that the
    closure drifts left in the readings make in the "report" mode (zeros in the others, which
    remove them): each mounting j with a closure reading drifted by its H_j over the turn,
    linear in the reading's order t, and nothing removed it, so the results carry
    b = −Σ_j H_j·P_j exactly (P_j = G_j·(t/n) on its rows; the closure reading itself is not
    used). Each H_j is the difference of two readings (noise 2σ²), so b is known to
    v = 2σ²·Σ_j P_j²: it is taken beyond that noise, point by point, sign(b)·√max(0, b² − v)
    (b² − v unbiased for the square of the bias, as the polygon workbench takes its
    closures). Signed, point by point."""
    gain = _gain(solution, combine)
    if solution.drift_mode != "report":
        return np.zeros(gain.shape[0])
    t = np.asarray(solution.row_time, dtype=float)
    mounting = np.asarray(solution.row_mounting)
    bias, noise = np.zeros(gain.shape[0]), np.zeros(gain.shape[0])
    for j, h in zip(solution.mountings, np.asarray(solution.closure_drift_arcsec, dtype=float),
                    strict=True):
        if not np.isfinite(h):
            continue
        rows = np.flatnonzero(mounting == j)
        pattern = gain[:, rows] @ (t[rows] / solution.faces)
        bias -= h * pattern
        noise += 2.0 * float(solution.sigma_arcsec) ** 2 * pattern**2
    return np.sign(bias) * np.sqrt(np.clip(bias**2 - noise, 0.0, None))


def drift_pattern_arcsec(solution: CrossCalibration, combine=None) -> np.ndarray:
    """G·(t/n) summed over the mountings with no closure reading, per value of (E, d) (2n):
    the results' change per 1″ of drift over a mounting the same in every such mounting
    (its sign, point by point, is the ramp's over the encoder's steps)."""
    return np.sum(_drift_patterns(solution, combine), axis=0)


def _drift_patterns(solution: CrossCalibration, combine=None) -> np.ndarray:
    """(mountings with no closure reading × values): G_j·(t/n) of each such mounting."""
    gain = _gain(solution, combine)
    t = np.asarray(solution.row_time, dtype=float)
    mounting = np.asarray(solution.row_mounting)
    out = [np.zeros(gain.shape[0])]
    for j in unchecked_drift_mountings(solution):
        rows = np.flatnonzero(mounting == j)
        out.append(gain[:, rows] @ (t[rows] / solution.faces))
    return np.array(out)


def tilt_effect_arcsec(solution: CrossCalibration, mounting, position, bound_arcsec: float,
                       directions: int = 72, combine=None) -> np.ndarray:
    """Half-width per value of (E, d) (2n) of the results' change that an unmeasured tilt of
    the polygon on the shaft up to ``bound_arcsec`` causes: per mounting, the exact horizontal
    effect of a tilt ψ = bound towards the worst direction ω (``models.pyramidal``, in the
    set-up's frame) through the design, |G_j · ε_j(ω)| at its largest over ω; the mountings'
    tilts are independent, so their half-widths add in quadrature (each rectangular). Mountings
    whose tilt was fitted from vertical readings are left out. Of ``combine``·(E, d) when
    given."""
    gain = _gain(solution, combine)
    total = np.zeros(gain.shape[0])
    if not bound_arcsec > 0:
        return total
    for rows, patterns in _tilt_patterns(solution, mounting, position, bound_arcsec,
                                         directions):
        g = gain[:, rows]
        worst = np.zeros(gain.shape[0])
        for eps in patterns:
            worst = np.maximum(worst, np.abs(g @ eps))
        total += worst**2
    return np.sqrt(total)


def _tilt_patterns(solution: CrossCalibration, mounting, position, bound_arcsec: float,
                   directions: int) -> list[tuple[np.ndarray, list[np.ndarray]]]:
    """Per mounting whose tilt was not fitted: (its rows, the readings' change ε(ω) of a
    tilt ``bound_arcsec`` towards each of ``directions`` directions ω), the part of
    :func:`tilt_effect_arcsec` that neither the item nor ``combine`` changes. Kept with
    ``solution``: an edit's window and a certificate ask for it five times (each item's
    budget with and without the certificate details, the values from the first), and each
    was 4300 evaluations of models.pyramidal (~0.05 s)."""
    from models.pyramidal import pyramidal_correction_arcsec

    mounting = np.asarray(mounting)
    position = np.asarray(position, dtype=int)
    key = (mounting.dtype.str, mounting.tobytes(), position.tobytes(), float(bound_arcsec),
           int(directions))
    cache = solution.__dict__.setdefault("_tilt_patterns", {})  # frozen: no attribute set
    if key not in cache:
        theta = (position - 1) * 360.0 / solution.faces
        out = []
        for j, tilt in zip(solution.mountings,
                           solution.tilts or (None,) * len(solution.mountings), strict=True):
            if tilt is not None:  # fitted and removed
                continue
            rows = np.flatnonzero(mounting == j)
            out.append((rows, [pyramidal_correction_arcsec(theta[rows], bound_arcsec, omega,
                                                           0.0, solution.ac_alignment)
                               for omega in np.arange(directions) * 360.0 / directions]))
        cache[key] = out
    return cache[key]


def tilt_fit_effect_arcsec(solution: CrossCalibration, mounting, position) -> np.ndarray:
    """Standard uncertainty per value of (E, d) (2n) that the fitted tilts' own uncertainty
    u(ψ), u(ω) leaves in the results through their removed correction (first order, through
    the design); zeros without vertical readings."""
    from models.pyramidal import pyramidal_correction_arcsec

    n = solution.faces
    mounting = np.asarray(mounting)
    theta = (np.asarray(position, dtype=int) - 1) * 360.0 / n
    total = np.zeros(2 * n)
    for j, t in zip(solution.mountings, solution.tilts or (), strict=False):
        if t is None:
            continue
        rows = np.flatnonzero(mounting == j)
        g = solution.gain[:, rows]

        def eps(psi, omega, th=theta[rows], g=g):
            return g @ pyramidal_correction_arcsec(th, psi, omega, 0.0, solution.ac_alignment)

        d_psi = (eps(t.psi_arcsec + 0.01, t.omega_deg) - eps(t.psi_arcsec - 0.01, t.omega_deg)) / 0.02
        d_om = (eps(t.psi_arcsec, t.omega_deg + 1e-3) - eps(t.psi_arcsec, t.omega_deg - 1e-3)) / 2e-3
        cov = t.cov_psi_omega if t.cov_psi_omega is not None else np.diag(
            [t.u_psi_arcsec**2, t.u_omega_deg**2])
        grad = np.column_stack([d_psi, d_om])
        total += np.clip(np.einsum("ij,jk,ik->i", grad, cov, grad), 0.0, None)
    return np.sqrt(total)
