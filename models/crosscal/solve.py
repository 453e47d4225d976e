"""Polygon and encoder calibrated together, by the closure principle (least squares).

Sign conventions (errors of indication, as the polygon workbench states them):

* ``E_k`` — the **encoder's error** at its step k (k = 0 … n−1, the steps of
  360°/n from the encoder reading at which every mounting starts): indicated −
  true angle, arcsec. Closure: Σ_k E_k = 0 (the steps of a full turn close at
  360°), so E is stated about its mean; differences E_k − E_0 are the polygon
  workbench's common-zero errors.
* ``d_i`` — the **polygon's face deviation** of face i (1 … n): the face's true
  angle from face 1, in the encoder's counting sense, minus its nominal
  (i − 1)·360°/n — what a polygon certificate states. Closure: Σ_i d_i = 0.
* ``mounting`` j — how many faces the polygon was turned on the shaft, in the
  encoder's counting sense, from mounting 0 (0 ≤ j < n). In mounting j the face
  at the autocollimator at encoder step k is i = (k + j) mod n + 1; face
  numbers rise in the encoder's counting sense.
* The autocollimator's horizontal reading ``c`` rises when the shaft turns on
  past the face (as in the polygon workbench: a shaft that overshoots raises it).

Each reading gives ``y = (a − a_start − k·360°/n)·3600 − c`` (a wrapped to the
step), and the model is ``y = E_k + d_i + o_j + δ_j·t/n + noise``, with o_j a
per-mounting offset (the autocollimator's zero and the mounting's error) and
δ_j a per-mounting linear drift in time, t the reading's order in its mounting
(0 … n − 1, the closure reading t = n). δ_j is fitted only for mountings that
end with a closure reading (the repeat of their first face); the drift reported
is −δ_j, the polygon workbench's (c′ − c) − (a′ − a): an autocollimator that
drifted by D gives D.

What the design cannot determine is found from the null space of the design
under the closure constraints, and named as harmonic orders of E and d (for
mountings all a multiple of g faces apart, with g dividing n, the harmonics h
with h·g ≡ 0 mod n are unseen); such values are not reported (``None``); the
part of E and d made of the determined harmonics is given instead, labelled.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from models.uncertainty.budget import DEFAULT_COVERAGE_PROBABILITY, coverage_factor

__all__ = ["CrossCalibration", "CrossCalibrationInputError", "harmonic_basis", "solve_crosscal"]

#: a reading further than this from its step is no reading of that step (fraction of a step)
STEP_TOLERANCE = 0.25


class CrossCalibrationInputError(ValueError):
    """Readings that cannot be a cross-calibration; ``row`` is the 1-based data row (or None)."""

    def __init__(self, text: str, row: int | None = None) -> None:
        super().__init__(text)
        self.row = row


@dataclass(frozen=True)
class CrossCalibration:
    faces: int
    mountings: tuple[int, ...]
    #: E_k at steps k = 0 … n−1 (first step first), Σ = 0; None when not determined
    encoder_error_arcsec: np.ndarray | None
    #: d_i for faces 1 … n, Σ = 0; None when not determined
    polygon_deviation_arcsec: np.ndarray | None
    #: harmonic orders of E and of d the design cannot see (empty when all are determined)
    undetermined_encoder_harmonics: tuple[int, ...]
    undetermined_polygon_harmonics: tuple[int, ...]
    #: E and d with the undetermined harmonics removed (equal to the results when none is)
    encoder_error_determined_arcsec: np.ndarray
    polygon_deviation_determined_arcsec: np.ndarray
    #: covariance of (E, d) — of their determined parts — arcsec², 2n × 2n
    covariance_arcsec2: np.ndarray
    sigma_arcsec: float  # standard deviation of one reading (from the residuals, or as given)
    dof: float  # ν of sigma (inf when given)
    coverage_factor: float
    offsets_arcsec: np.ndarray  # o_j per mounting (about their mean)
    drift_arcsec: np.ndarray  # per mounting, (c′ − c) − (a′ − a) fitted; nan without closure
    residuals_arcsec: np.ndarray  # per row in the order given
    rank_deficiency: int

    @property
    def separable(self) -> bool:
        return not (self.undetermined_encoder_harmonics or self.undetermined_polygon_harmonics)

    def _u(self, block: slice) -> np.ndarray:
        return np.sqrt(np.clip(np.diag(self.covariance_arcsec2)[block], 0.0, None))

    @property
    def encoder_error_u_arcsec(self) -> np.ndarray:
        return self._u(slice(0, self.faces))

    @property
    def polygon_deviation_u_arcsec(self) -> np.ndarray:
        return self._u(slice(self.faces, 2 * self.faces))

    @property
    def encoder_error_expanded_arcsec(self) -> np.ndarray:
        return self.coverage_factor * self.encoder_error_u_arcsec

    @property
    def polygon_deviation_expanded_arcsec(self) -> np.ndarray:
        return self.coverage_factor * self.polygon_deviation_u_arcsec

    @property
    def correlation(self) -> np.ndarray:
        """Correlation matrix of (E_0 … E_{n−1}, d_1 … d_n); the block [:n, n:] relates
        the two result sets (zero for a full rosette)."""
        u = np.sqrt(np.clip(np.diag(self.covariance_arcsec2), 0.0, None))
        with np.errstate(divide="ignore", invalid="ignore"):
            r = self.covariance_arcsec2 / np.outer(u, u)
        return np.where(np.outer(u, u) > 0, r, 0.0)


def harmonic_basis(n: int) -> list[tuple[int, np.ndarray]]:
    """Orthonormal real Fourier basis of R^n, grouped by harmonic order h = 0 … n//2:
    (h, n × 1 or n × 2 matrix)."""
    k = np.arange(n)
    out = [(0, np.ones((n, 1)) / math.sqrt(n))]
    for h in range(1, n // 2 + 1):
        c = np.cos(2 * np.pi * h * k / n)
        if 2 * h == n:
            out.append((h, (c / np.linalg.norm(c))[:, None]))
        else:
            s = np.sin(2 * np.pi * h * k / n)
            out.append((h, np.column_stack([c, s]) / math.sqrt(n / 2)))
    return out


def _wrap_deg(x):
    return (np.asarray(x, dtype=float) + 180.0) % 360.0 - 180.0


def _number(v) -> float:
    try:
        return float(v)
    except (TypeError, ValueError):
        return math.nan


def _rows(mounting, position, encoder_deg, ac_x_arcsec, faces):
    mounting = np.asarray(mounting)
    position = np.asarray(position)
    a = np.asarray(encoder_deg, dtype=float)
    c = np.asarray(ac_x_arcsec, dtype=float)
    size = mounting.size
    if not (position.size == a.size == c.size == size):
        raise CrossCalibrationInputError("mounting, position, encoder and autocollimator columns "
                                         "differ in length")
    for name, col in (("mounting", mounting), ("position", position)):
        try:
            values = col.astype(float)
        except (TypeError, ValueError):
            values = np.array([_number(v) for v in col])
        bad = np.flatnonzero(~np.isfinite(values) | (values != np.round(values)))
        if bad.size:
            r = int(bad[0]) + 1
            raise CrossCalibrationInputError(f"row {r}: {name} {col[r - 1]!r} is not a whole number", r)
    for name, col in (("encoder_deg", a), ("ac_x_arcsec", c)):
        bad = np.flatnonzero(~np.isfinite(col))
        if bad.size:
            r = int(bad[0]) + 1
            raise CrossCalibrationInputError(f"row {r}: {name} is not a number", r)
    mounting = mounting.astype(float).astype(int)
    position = position.astype(float).astype(int)
    order = list(dict.fromkeys(mounting.tolist()))  # mountings in the order first met
    if faces is None:
        faces = int(np.unique(position[mounting == order[0]]).size) if size else 0
    n = int(faces)
    if n < 3:
        raise CrossCalibrationInputError(f"{n} faces: a polygon has at least 3")
    for r, (j, i) in enumerate(zip(mounting, position, strict=True), start=1):
        if not 1 <= i <= n:
            raise CrossCalibrationInputError(f"row {r}: face {i} is outside 1…{n} (face count {n})", r)
        if not 0 <= j < n:
            raise CrossCalibrationInputError(f"row {r}: mounting {j} is outside 0…{n - 1}", r)
    return mounting, position, a, c, order, n


def solve_crosscal(mounting, position, encoder_deg, ac_x_arcsec, faces: int | None = None,
                   noise_arcsec: float | None = None, fit_drift: bool = True,
                   probability: float = DEFAULT_COVERAGE_PROBABILITY) -> CrossCalibration:
    """Encoder errors E_k and face deviations d_i from readings in the order measured.

    Rows: ``mounting`` j, ``position`` (face 1 … n at the autocollimator), encoder
    reading (deg) and autocollimator horizontal reading (″). Every mounting reads
    every face once, optionally ending with a closure reading of its first face.
    ``noise_arcsec``: a known σ of one reading (ν = ∞); otherwise σ comes from the
    residuals with ν = readings − rank (refused when ν = 0). Rows that cannot be a
    cross-calibration raise :class:`CrossCalibrationInputError` naming the row.
    """
    mounting, position, a, c, order, n = _rows(mounting, position, encoder_deg, ac_x_arcsec, faces)
    if len(order) < 2:
        raise CrossCalibrationInputError(
            f"only mounting {order[0] if order else '—'}: the faces and the encoder's steps are not "
            "connected — at least two mountings are needed")
    step = 360.0 / n
    # reading order t in each mounting; the closure row (repeat of the first face, last) gets t = n
    t = np.zeros(mounting.size, dtype=int)
    closure = np.zeros(mounting.size, dtype=bool)
    has_closure = {}
    for j in order:
        rows = np.flatnonzero(mounting == j)
        seen: dict[int, int] = {}
        for idx, r in enumerate(rows):
            i = int(position[r])
            if i in seen:
                if idx == rows.size - 1 and i == int(position[rows[0]]):
                    closure[r] = True
                    t[r] = n
                    continue
                raise CrossCalibrationInputError(
                    f"row {r + 1}: mounting {j}, face {i} repeats row {seen[i] + 1} "
                    "(a duplicate reading; only the closure reading, last, may repeat the first face)",
                    r + 1)
            seen[i] = r
            t[r] = idx
        missing = sorted(set(range(1, n + 1)) - set(seen))
        if missing:
            raise CrossCalibrationInputError(
                f"mounting {j} (rows {rows[0] + 1}…{rows[-1] + 1}): face(s) "
                f"{', '.join(map(str, missing))} missing — every mounting reads all {n} faces",
                int(rows[-1]) + 1)
        has_closure[j] = bool(closure[rows].any())
    k = (position - 1 - mounting) % n
    first = order[0]
    start_rows = np.flatnonzero((mounting == first) & (k == 0) & ~closure)
    a_start = a[start_rows[0]]
    off = _wrap_deg(a - a_start - k * step)
    far = np.flatnonzero(np.abs(off) > STEP_TOLERANCE * step)
    if far.size:
        r = int(far[0])
        raise CrossCalibrationInputError(
            f"row {r + 1}: encoder {a[r]:.4f}° is {off[r]:+.4f}° from step {k[r]} "
            f"({a_start + k[r] * step:.4f}°) where mounting {mounting[r]} reads face {position[r]}: "
            "a mounting that starts elsewhere, or a wrong mounting or face number", r + 1)
    y = off * 3600.0 - c

    # design: columns E (n), d (n), o (m), δ (mountings with closure, when fitted)
    m = len(order)
    mindex = {j: q for q, j in enumerate(order)}
    drifting = [j for j in order if has_closure[j]] if fit_drift else []
    dindex = {j: q for q, j in enumerate(drifting)}
    p = 2 * n + m + len(drifting)
    rows_n = mounting.size
    design = np.zeros((rows_n, p))
    ar = np.arange(rows_n)
    design[ar, k] = 1.0
    design[ar, n + position - 1] = 1.0
    design[ar, 2 * n + np.array([mindex[j] for j in mounting])] = 1.0
    drift_col = np.array([dindex.get(int(j), -1) for j in mounting])
    has = drift_col >= 0
    design[ar[has], 2 * n + m + drift_col[has]] = t[has] / n
    # closure constraints Σ E = 0 and Σ d = 0 (they also fix the offsets' level); without
    # the drift term (fit_drift False) a closure reading is one more reading of its face.
    # Solved on the constraints' null space.
    constraint = np.zeros((2, p))
    constraint[0, :n] = 1.0
    constraint[1, n:2 * n] = 1.0
    _, _, vt = np.linalg.svd(constraint)
    z = vt[2:].T  # p × (p − 2), orthonormal, spans {x : C x = 0}
    # normal equations on the constraints' null space (p − 2 unknowns; fast for 72 faces)
    zat = (design @ z).T
    normal = zat @ zat.T
    lam, vec = np.linalg.eigh(normal)
    tol = 1e-9 * max(float(lam[-1]), 1.0)
    seen = lam > tol
    rank = int(seen.sum())
    pinv_normal = (vec[:, seen] / lam[seen]) @ vec[:, seen].T
    x = z @ (pinv_normal @ (zat @ y))
    residuals = y - design @ x
    null = z @ vec[:, ~seen]  # p × deficiency, orthonormal
    deficiency = p - 2 - rank

    basis = harmonic_basis(n)

    def unseen(block: np.ndarray) -> tuple[tuple[int, ...], np.ndarray]:
        orders, keep = [], np.eye(n)
        for h, b in basis:
            if h and np.linalg.norm(b.T @ block) > 1e-6:
                orders.append(h)
                keep = keep - b @ b.T
        return tuple(orders), keep

    null_e, null_d = null[:n], null[n:2 * n]
    bad_e, keep_e = unseen(null_e)
    bad_d, keep_d = unseen(null_d)
    if np.linalg.norm(keep_e @ null_e) > 1e-6 or np.linalg.norm(keep_d @ null_d) > 1e-6:
        raise CrossCalibrationInputError(
            "the mountings do not determine the encoder's errors and the face deviations "
            "(not even in part): they do not connect the faces")
    if len(bad_e) == n // 2 or len(bad_d) == n // 2:
        raise CrossCalibrationInputError(
            f"mountings {', '.join(map(str, order))} do not connect the faces: no harmonic of the "
            "encoder's error or of the face deviations is determined")

    dof = float(rows_n - rank)
    if noise_arcsec is not None:
        sigma, dof = float(noise_arcsec), math.inf
    elif dof <= 0:
        raise CrossCalibrationInputError(
            f"{rows_n} readings determine {rank} unknowns with none left over: the scatter of a reading "
            "cannot be evaluated — add a mounting, or state the autocollimator's σ")
    else:
        sigma = float(math.sqrt(residuals @ residuals / dof))
    cov_x = sigma**2 * (z @ pinv_normal @ z.T)
    proj = np.zeros((2 * n, p))
    proj[:n, :n] = keep_e
    proj[n:, n:2 * n] = keep_d
    cov = proj @ cov_x @ proj.T
    e_det = keep_e @ x[:n]
    d_det = keep_d @ x[n:2 * n]
    drift = np.full(m, np.nan)
    for j in drifting:
        drift[mindex[j]] = -x[2 * n + m + dindex[j]]
    offsets = x[2 * n:2 * n + m]
    return CrossCalibration(
        faces=n, mountings=tuple(order),
        encoder_error_arcsec=None if bad_e else e_det,
        polygon_deviation_arcsec=None if bad_d else d_det,
        undetermined_encoder_harmonics=bad_e, undetermined_polygon_harmonics=bad_d,
        encoder_error_determined_arcsec=e_det, polygon_deviation_determined_arcsec=d_det,
        covariance_arcsec2=cov, sigma_arcsec=sigma, dof=dof,
        coverage_factor=coverage_factor(dof, probability),
        offsets_arcsec=offsets - offsets.mean(), drift_arcsec=drift,
        residuals_arcsec=residuals, rank_deficiency=deficiency)
