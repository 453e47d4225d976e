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
(0 … n − 1, the closure reading t = n). δ_j is fitted for mountings that end
with a closure reading (the repeat of their first face), and for the others too
where the design determines their drift (every added drift a new rank, and a
degree of freedom left for the scatter when σ is not stated): the closure
readings fix the encoder's error over the turn, and a mounting's readings against
it show its drift; otherwise theirs is neither measured nor removed (a drift the
same way in every such mounting is a ramp over the encoder's steps:
models.crosscal.uncertainty.drift_effect_arcsec). The drift reported is −δ_j, the
polygon workbench's (c′ − c) − (a′ − a): an autocollimator that drifted by D gives D.

Drift (``drift``), as in the polygon workbench, from the closure reading:

* ``"fit"`` (the default): δ_j fitted with everything else, as above (least squares
  uses the closure reading with all the others);
* ``"spread"``: the closure drift H = (c′ − c) − (a′ − a) of the mounting's first
  face is taken as growing linearly from its first reading to its closure and removed
  from the readings (the polygon workbench's "spread"); the closure reading is then
  used up, and the covariance carries the two readings H came from (exact);
* ``"report"``: H is reported and judged against ``closure_limit_arcsec`` but not
  removed; the closure reading is left out of the fit. The drift left in the readings
  moves the results by −Σ_j H_j·G_j·(t/n) (the bias the budget carries:
  models.crosscal.uncertainty.reported_drift_bias_arcsec); σ, when taken from the
  residuals, is the readings' noise: from the fit with those drifts fitted, the closure
  readings used (``scatter_residuals_arcsec``), not swollen by the drift left in.

H itself (``closure_drift_arcsec``) is given in every mode.

Tilt: with vertical readings (``ac_y_arcsec``) each mounting's pyramidal tilt ψ, ω
is fitted on its faces' vertical readings and its horizontal effect removed, in the
frame the autocollimator is set to (``ac_alignment`` "levelled" or "polygon", a
measured roll ``roll_rad``), as the polygon workbench does it: the same exact 3-D
readings and fit (:func:`models.pyramidal.fit_tilt`), done for all mountings at
once by :mod:`models.crosscal.tilt` (tested to give fit_tilt's figures); θ is the
face's nominal angle (i − 1)·360°/n, face 1 the zero (the constant part is the
mounting's offset). The faces' own pyramidal errors — each face normal's elevation β_i,
fixed to the polygon, the same in every mounting — are fitted with the tilts, shared by all
mountings (:func:`models.crosscal.tilt.fit_tilts_and_faces`): β's mean over the faces
cannot be told from the vertical zero nor its first harmonic from a tilt common to all
mountings, so β is constrained to neither (each face relative to the faces' mean plane) and
reported as ``face_pyramidal_arcsec``; it enters the horizontal correction exactly (an
elevated normal read through a tilt). The scatter the vertical readings are judged by is
what is left after both. The tilt's own uncertainty is left to the residual scatter (its
correction is second order in ψ in a levelled set-up).

What the design cannot determine is found from the null space of the design
under the closure constraints, and named as harmonic orders of E and d (for
mountings all a multiple of g faces apart, with g dividing n, the harmonics h
with h·g ≡ 0 mod n are unseen); such values are not reported (``None``); the
part of E and d made of the determined harmonics is given instead, labelled.

The uncertainty is exact for the linear model: cov = σ²·Z(ZᵀXᵀXZ)⁺Zᵀ (X the design,
Z the closure constraints' null space), σ from the residual scatter with
ν = readings − rank (or stated, with its own ν), k from ν (GUM G.3, the house's
:func:`models.uncertainty.budget.coverage_factor`). With "spread" the estimate is
x = G·L·y (L the spread map), cov = σ²·G·L·Lᵀ·Gᵀ and σ² = ‖r‖²/tr(Lᵀ(I − H)L).
:mod:`models.crosscal.uncertainty` adds Estler's closed form, a design's expected u
and a Monte Carlo check.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any

import numpy as np

from models.messages import QT_TR_NOOP, Message, message
from models.uncertainty.budget import DEFAULT_COVERAGE_PROBABILITY, coverage_factor

if TYPE_CHECKING:
    from models.crosscal.tilt import FacePyramidalFit
    from models.pyramidal import TiltFit

__all__ = ["DRIFT_MODES", "CrossCalibration", "CrossCalibrationInputError", "harmonic_basis",
           "solve_crosscal"]

#: a reading further than this from its step is no reading of that step (fraction of a step)
STEP_TOLERANCE = 0.25

#: vertical readings scattering more than this many times the horizontal σ (+ 0.1″) about
#: their tilt curve are said to be suspect
VERTICAL_SCATTER_FACTOR = 10.0
#: a fitted tilt above this (1°) is no seating but wrong vertical readings
MAX_TILT_ARCSEC = 3600.0

#: how each mounting's drift is taken from its closure reading (see the module's text)
DRIFT_MODES = ("fit", "spread", "report")


class CrossCalibrationInputError(ValueError):
    """Readings that cannot be a cross-calibration; ``row`` is the 1-based data row (or None).
    The text is a :class:`models.messages.Message` (translated by the window)."""

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
    dof: float  # ν of sigma (inf when given without its own ν)
    coverage_factor: float
    offsets_arcsec: np.ndarray  # o_j per mounting (about their mean)
    #: per mounting (in ``mountings`` order): the drift used — fitted ("fit"), the closure
    #: drift H ("spread", "report"); nan without a closure reading
    drift_arcsec: np.ndarray
    residuals_arcsec: np.ndarray  # per row in the order given (closure rows included)
    rank_deficiency: int
    # --- added for the workbench (all with defaults) ---
    #: per mounting: H = (c′ − c) − (a′ − a) of its closure reading, as the polygon workbench
    #: computes it (tilt removed), nan without a closure reading
    closure_drift_arcsec: np.ndarray = field(default_factory=lambda: np.zeros(0))
    drift_mode: str = "fit"
    #: per mounting: models.pyramidal.TiltFit, or None (no vertical readings)
    tilts: tuple = ()
    ac_alignment: str = "levelled"
    #: per row: the tilt's horizontal effect removed from the reading, arcsec (zeros without)
    pyramidal_arcsec: np.ndarray = field(default_factory=lambda: np.zeros(0))
    #: per row: the encoder step k, the reading's order t in its mounting (closure: n), and
    #: whether it is a closure reading
    row_step: np.ndarray = field(default_factory=lambda: np.zeros(0, dtype=int))
    row_time: np.ndarray = field(default_factory=lambda: np.zeros(0, dtype=int))
    row_closure: np.ndarray = field(default_factory=lambda: np.zeros(0, dtype=bool))
    #: per row: its mounting j (as given)
    row_mounting: np.ndarray = field(default_factory=lambda: np.zeros(0, dtype=int))
    #: per row: whether the reading entered the least squares (closure readings in
    #: "spread"/"report" do not)
    row_used: np.ndarray = field(default_factory=lambda: np.zeros(0, dtype=bool))
    probability: float = DEFAULT_COVERAGE_PROBABILITY
    warnings: tuple = ()  # Messages (closure over its limit, no closure, no vertical readings)
    #: per face (1 … n): the face normal's own elevation β_i (its pyramidal error), arcsec, in
    #: the sense of the vertical reading, relative to the faces' mean plane (mean and first
    #: harmonic over the faces removed — they cannot be told from the autocollimator's
    #: vertical zero and a tilt common to all mountings); None without vertical readings of
    #: at least two mountings
    face_pyramidal_arcsec: np.ndarray | None = None
    #: standard uncertainty (k = 1) of each face_pyramidal_arcsec, from the vertical scatter
    face_pyramidal_u_arcsec: np.ndarray | None = None
    #: per mounting: RMS of its vertical readings about its tilt and the faces' pyramidal errors
    #: (their median over the mountings), arcsec — what the vertical readings are judged by;
    #: nan without vertical readings
    vertical_scatter_arcsec: np.ndarray = field(default_factory=lambda: np.zeros(0))
    #: (2n × rows): (E, d) = gain · y, y per row the reading the model sees, y = (a − a_start −
    #: k·360°/n)·3600 − c − tilt correction (closure rows included; zero where not used), so a
    #: systematic pattern δy in the readings moves the results by exactly gain · δy (a pattern
    #: δc in the autocollimator's readings by −gain · δc)
    gain: np.ndarray = field(default_factory=lambda: np.zeros((0, 0)))
    #: σ was stated (``noise_arcsec``), not taken from the residuals: the readings' scatter
    #: then holds nothing the model leaves out (a drift that differs between mountings and is
    #: neither fitted nor removed, say), so the budget must
    sigma_stated: bool = False
    #: per row: the residuals σ is judged by (outliers): ``residuals_arcsec``, but in the
    #: "report" mode (σ from the residuals) those of the fit with each closed mounting's drift
    #: fitted (:func:`_scatter_without_drift`), so a drift left in is not taken for outliers
    scatter_residuals_arcsec: np.ndarray = field(default_factory=lambda: np.zeros(0))

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

    @property
    def cross_covariance_arcsec2(self) -> np.ndarray:
        """cov(E_k, d_i), n × n (rows steps k, columns faces i), arcsec²."""
        n = self.faces
        return self.covariance_arcsec2[:n, n:]

    @property
    def max_cross_correlation(self) -> float:
        """The largest |r(E_k, d_i)| between the two result sets (0 for a full rosette)."""
        n = self.faces
        return float(np.abs(self.correlation[:n, n:]).max())

    @property
    def correlation_statement(self) -> Message:
        """What a certificate says of the correlation between the two result sets."""
        r = self.max_cross_correlation
        if r < 1e-6:
            return message(QT_TR_NOOP("the encoder's errors and the face deviations are "
                                      "uncorrelated (a full rosette)"))
        return message(QT_TR_NOOP("the encoder's errors and the face deviations are correlated: "
                                  "|r| up to {r}; use the covariance given when combining them"),
                       r=f"{r:.2f}")

    @property
    def face_pyramidal_statement(self) -> Message | None:
        """What the face pyramidal errors are relative to (None when not fitted)."""
        if self.face_pyramidal_arcsec is None or self.face_pyramidal_u_arcsec is None:
            return None  # (the two are fitted together: both or neither)
        return message(QT_TR_NOOP("face pyramidal errors: each face normal's elevation relative "
                                  "to the faces' mean plane (their mean and first harmonic over "
                                  "the faces are not determined: they cannot be told from the "
                                  "autocollimator's vertical zero and the polygon's tilt); "
                                  "largest {largest}, u up to {u}"),
                       largest=f"{np.abs(self.face_pyramidal_arcsec).max():.2f}\"",
                       u=f"{np.max(self.face_pyramidal_u_arcsec):.3f}\"")

    @property
    def undetermined_text(self) -> Message | None:
        """Why values are withheld (None when the design separates everything)."""
        if self.separable:
            return None
        return _undetermined_text(self.faces, self.mountings, self.undetermined_encoder_harmonics,
                                  self.undetermined_polygon_harmonics)


def _undetermined_text(n, mountings, bad_e, bad_d) -> Message:
    spacing = math.gcd(n, *(j - mountings[0] for j in mountings[1:]))
    orders = sorted(set(bad_e) | set(bad_d))
    return message(QT_TR_NOOP("mountings {mountings} are all a multiple of {spacing} faces apart: "
                              "harmonic orders {orders} of the encoder's error and of the face "
                              "deviations are not determined: the encoder's errors and the face "
                              "deviations are withheld (add a mounting that is not)"),
                   mountings=", ".join(map(str, mountings)), spacing=spacing,
                   orders=", ".join(map(str, orders)))


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


def _refuse(template: str, at: int | None = None, **figures) -> CrossCalibrationInputError:
    """The error for a refused input, its text a Message; ``at`` the 1-based row."""
    return CrossCalibrationInputError(message(template, **figures), at)


def _rows(mounting, position, encoder_deg, ac_x_arcsec, faces):
    mounting = np.asarray(mounting)
    position = np.asarray(position)
    a = np.asarray(encoder_deg, dtype=float)
    c = np.asarray(ac_x_arcsec, dtype=float)
    size = mounting.size
    if not (position.size == a.size == c.size == size):
        raise _refuse(QT_TR_NOOP("mounting, position, encoder and autocollimator columns differ "
                                 "in length"))
    for name, col in (("mounting", mounting), ("position", position)):
        try:
            values = col.astype(float)
        except (TypeError, ValueError):
            values = np.array([_number(v) for v in col])
        bad = np.flatnonzero(~np.isfinite(values) | (values != np.round(values)))
        if bad.size:
            r = int(bad[0]) + 1
            raise _refuse(QT_TR_NOOP("row {row}: {column} {value} is not a whole number"), r,
                          row=r, column=name, value=repr(col[r - 1]))
    for name, col in (("encoder_deg", a), ("ac_x_arcsec", c)):
        bad = np.flatnonzero(~np.isfinite(col))
        if bad.size:
            r = int(bad[0]) + 1
            raise _refuse(QT_TR_NOOP("row {row}: {column} is not a number"), r, row=r, column=name)
    mounting = mounting.astype(float).astype(int)
    position = position.astype(float).astype(int)
    order = list(dict.fromkeys(mounting.tolist()))  # mountings in the order first met
    if faces is None:
        faces = int(np.unique(position[mounting == order[0]]).size) if size else 0
    n = int(faces)
    if n < 3:
        raise _refuse(QT_TR_NOOP("{faces} faces: a polygon has at least 3"), faces=n)
    for r, (j, i) in enumerate(zip(mounting, position, strict=True), start=1):
        if not 1 <= i <= n:
            raise _refuse(QT_TR_NOOP("row {row}: face {face} is outside 1…{faces} (face count "
                                     "{faces})"), r, row=r, face=i, faces=n)
        if not 0 <= j < n:
            raise _refuse(QT_TR_NOOP("row {row}: mounting {mounting} is outside 0…{last}"), r,
                          row=r, mounting=j, last=n - 1)
    return mounting, position, a, c, order, n


def _sequence(mounting: np.ndarray, position: np.ndarray, order: Sequence[int], n: int
              ) -> tuple[np.ndarray, np.ndarray, dict[int, np.ndarray]]:
    """Reading order t per row (closure t = n), closure flags, each mounting's rows."""
    t = np.zeros(mounting.size, dtype=int)
    closure = np.zeros(mounting.size, dtype=bool)
    rows_of: dict[int, np.ndarray] = {}
    for j in order:
        rows = np.flatnonzero(mounting == j)
        rows_of[j] = rows
        seen: dict[int, int] = {}
        for idx, r in enumerate(map(int, rows)):
            i = int(position[r])
            if i in seen:
                if idx == rows.size - 1 and i == int(position[rows[0]]):
                    closure[r] = True
                    t[r] = n
                    continue
                raise _refuse(QT_TR_NOOP("row {row}: mounting {mounting}, face {face} repeats row "
                                         "{other} (a duplicate reading; only the closure reading, "
                                         "last, may repeat the first face)"), r + 1,
                              row=r + 1, mounting=j, face=i, other=seen[i] + 1)
            seen[i] = r
            t[r] = idx
        missing = sorted(set(range(1, n + 1)) - set(seen))
        if missing:
            raise _refuse(QT_TR_NOOP("mounting {mounting} (rows {first}…{last}): face(s) {faces} "
                                     "missing — every mounting reads all {count} faces"),
                          int(rows[-1]) + 1, mounting=j, first=rows[0] + 1, last=rows[-1] + 1,
                          faces=", ".join(map(str, missing)), count=n)
    return t, closure, rows_of


def _tilts(y: np.ndarray, ac_y: np.ndarray | None, position: np.ndarray, closure: np.ndarray,
           rows_of: dict[int, np.ndarray], order: Sequence[int], n: int, ac_alignment: str,
           roll_rad: float, warnings: list[Message]
           ) -> tuple[tuple[TiltFit | None, ...], np.ndarray, FacePyramidalFit | None, np.ndarray]:
    """Each mounting's tilt and the faces' own elevations fitted on the vertical readings
    and their horizontal effect removed from y (in place); (tilts per mounting, correction
    per row, the faces' FacePyramidalFit or None)."""
    from models.crosscal.tilt import fit_tilts_and_faces, pyramidal_corrections

    correction = np.zeros(y.size)
    if ac_y is None:
        warnings.append(message(QT_TR_NOOP("no vertical readings: the polygon's tilt on the shaft "
                                           "is neither identified nor removed")))
        return tuple(None for _ in order), correction, None, np.full(len(order), math.nan)
    read = []
    for j in order:
        faces_rows = rows_of[j][~closure[rows_of[j]]]
        if n >= 4 and np.all(np.isfinite(ac_y[faces_rows])):
            read.append(j)
        else:
            warnings.append(message(QT_TR_NOOP("mounting {mounting}: vertical readings missing: "
                                               "its tilt is neither identified nor removed"),
                                    mounting=j))
    tilts: dict[int, TiltFit] = {}
    faces_fit = None
    if read:
        face_rows = [rows_of[j][~closure[rows_of[j]]] for j in read]
        fits, faces_fit = fit_tilts_and_faces(np.array([position[r] - 1 for r in face_rows]), n,
                                              np.array([ac_y[r] for r in face_rows]), ac_alignment,
                                              roll_rad)
        table = pyramidal_corrections(fits, n, ac_alignment, roll_rad,
                                      None if faces_fit is None else faces_fit.elevation_arcsec)
        for q, j in enumerate(read):
            rows = rows_of[j]
            correction[rows] = table[q, position[rows] - 1]
            tilts[j] = fits[q]
    y -= correction
    scatter = {j: tilts[j].residual_rms_arcsec for j in tilts}
    if faces_fit is not None:
        scatter.update(zip(read, faces_fit.scatter_arcsec.tolist(), strict=True))
    return (tuple(tilts.get(j) for j in order), correction, faces_fit,
            np.array([scatter.get(j, math.nan) for j in order]))


@dataclass(frozen=True)
class _Fit:
    """The least squares of :func:`solve_crosscal` with drifts fitted for ``drifting``."""

    drifting: list[int]
    dindex: dict[int, int]
    p: int
    design_all: Any
    design: Any
    z: np.ndarray
    vec: np.ndarray
    seen: np.ndarray
    rank: int
    solver: np.ndarray
    x: np.ndarray


def _fit(y_data, used_index, mounting, k, position, t, order, mindex, drifting, n) -> _Fit:
    """Columns E (n), d (n), o (m), δ (``drifting``), solved under the closure constraints
    Σ E = 0 and Σ d = 0 (they also fix the offsets' level) on the constraints' null space."""
    from scipy import sparse

    m = len(order)
    dindex = {j: q for q, j in enumerate(drifting)}
    p = 2 * n + m + len(drifting)
    ar = np.arange(y_data.size)
    mcol = 2 * n + np.array([mindex[j] for j in mounting])
    dcol = np.array([dindex.get(int(j), -1) for j in mounting])
    cols = [k, n + position - 1, mcol]
    vals = [np.ones(y_data.size)] * 3
    has = dcol >= 0
    design_all = sparse.csr_matrix(
        (np.concatenate(vals + [t[has] / n]),
         (np.concatenate([ar] * 3 + [ar[has]]), np.concatenate(cols + [2 * n + m + dcol[has]]))),
        shape=(y_data.size, p))
    design = design_all[used_index]
    normal_full = (design.T @ design).toarray()
    constraint = np.zeros((2, p))
    constraint[0, :n] = 1.0
    constraint[1, n:2 * n] = 1.0
    _, _, vt = np.linalg.svd(constraint)
    z = vt[2:].T  # p × (p − 2), orthonormal, spans {x : C x = 0}
    normal = z.T @ normal_full @ z
    lam, vec = np.linalg.eigh(normal)
    tol = 1e-9 * max(float(lam[-1]), 1.0)
    seen = lam > tol
    rank = int(seen.sum())
    pinv_normal = (vec[:, seen] / lam[seen]) @ vec[:, seen].T
    solver = z @ pinv_normal @ z.T  # p × p: x = solver · Xᵀ y
    x = solver @ (design.T @ y_data[used_index])
    return _Fit(list(drifting), dindex, p, design_all, design, z, vec, seen, rank, solver, x)


def _scatter_without_drift(y, mounting, k, position, t, order, mindex, closed, n, rank: int,
                           sigma: float, dof: float, residuals: np.ndarray
                           ) -> tuple[float, float, np.ndarray]:
    """σ and ν of one reading in the "report" mode: from the residuals of the fit with each
    closed mounting's drift fitted (its closure reading used), as the "fit" mode has them.
    The drift is left in the results, and its bias is an input of the budget of its own
    (models.crosscal.uncertainty.reported_drift_bias_arcsec): the scatter of the readings
    about the report mode's fit would count the part of it the design does not take up
    again, as reading noise. Returns (σ, ν, the residuals per row it is taken from); the
    ones given when that fit leaves no degree of freedom or cannot determine every drift."""
    drifted = _fit(y, np.arange(y.size), mounting, k, position, t, order, mindex, closed, n)
    left = y.size - drifted.rank
    if left <= 0 or drifted.rank != rank + len(closed):
        return sigma, dof, residuals
    r = y - drifted.design_all @ drifted.x
    return float(math.sqrt(r @ r / left)), float(left), r


def solve_crosscal(mounting, position, encoder_deg, ac_x_arcsec, faces: int | None = None,
                   noise_arcsec: float | None = None, fit_drift: bool = True,
                   probability: float = DEFAULT_COVERAGE_PROBABILITY, *,
                   ac_y_arcsec=None, ac_alignment: str = "levelled", roll_rad: float = 0.0,
                   drift: str | None = None, closure_limit_arcsec: float = math.inf,
                   noise_dof: float = math.inf) -> CrossCalibration:
    """Encoder errors E_k and face deviations d_i from readings in the order measured.

    Rows: ``mounting`` j, ``position`` (face 1 … n at the autocollimator), encoder
    reading (deg) and autocollimator horizontal reading (″). Every mounting reads
    every face once, optionally ending with a closure reading of its first face.
    ``noise_arcsec``: a known σ of one reading (with its ``noise_dof``, ∞ unless
    stated); otherwise σ comes from the residuals with ν = readings − rank (refused
    when ν = 0). ``drift``: "fit", "spread" or "report" (module text; None: "fit",
    or "report" when ``fit_drift`` is False). ``ac_y_arcsec`` (nan where not read):
    each mounting's tilt fitted and removed in the ``ac_alignment`` frame. Rows that
    cannot be a cross-calibration raise :class:`CrossCalibrationInputError` naming
    the row.
    """
    from scipy import sparse

    from models.pyramidal import AC_ALIGNMENTS, closure_drift_arcsec

    mode = drift if drift is not None else ("fit" if fit_drift else "report")
    if mode not in DRIFT_MODES:
        raise _refuse(QT_TR_NOOP("drift must be one of {modes}, not {mode}"),
                      modes=", ".join(DRIFT_MODES), mode=repr(mode))
    if ac_alignment not in AC_ALIGNMENTS:
        raise _refuse(QT_TR_NOOP("ac_alignment must be one of {frames}, not {frame}"),
                      frames=", ".join(AC_ALIGNMENTS), frame=repr(ac_alignment))
    mounting, position, a, c, order, n = _rows(mounting, position, encoder_deg, ac_x_arcsec, faces)
    ac_y = None if ac_y_arcsec is None else np.asarray(ac_y_arcsec, dtype=float)
    if ac_y is not None and ac_y.size != a.size:
        raise _refuse(QT_TR_NOOP("the vertical readings ({count}) are not one per row ({rows})"),
                      count=ac_y.size, rows=a.size)
    if len(order) < 2:
        raise _refuse(QT_TR_NOOP("only mounting {mounting}: the faces and the encoder's steps are "
                                 "not connected — at least two mountings are needed"),
                      mounting=order[0] if order else "—")
    step = 360.0 / n
    t, closure, rows_of = _sequence(mounting, position, order, n)
    k = (position - 1 - mounting) % n
    first = order[0]
    start_rows = np.flatnonzero((mounting == first) & (k == 0) & ~closure)
    a_start = a[start_rows[0]]
    off = _wrap_deg(a - a_start - k * step)
    far = np.flatnonzero(np.abs(off) > STEP_TOLERANCE * step)
    if far.size:
        r = int(far[0])
        raise _refuse(QT_TR_NOOP("row {row}: encoder {encoder} is {offset} from step {step} "
                                 "({nominal}) where mounting {mounting} reads face {face}: a "
                                 "mounting that starts elsewhere, or a wrong mounting or face "
                                 "number"), r + 1, row=r + 1, encoder=f"{a[r]:.4f}°",
                      offset=f"{off[r]:+.4f}°", step=k[r], nominal=f"{a_start + k[r] * step:.4f}°",
                      mounting=mounting[r], face=position[r])
    y = off * 3600.0 - c
    warnings: list[Message] = []
    tilts, pyramidal, faces_fit, vertical_scatter = _tilts(y, ac_y, position, closure, rows_of, order,
                                                           n, ac_alignment, roll_rad, warnings)

    m = len(order)
    mindex = {j: q for q, j in enumerate(order)}
    closure_row = {j: int(rows_of[j][-1]) for j in order if closure[rows_of[j][-1]]}
    first_row = {j: int(rows_of[j][0]) for j in order}
    # H = (c′ − c) − (a′ − a) on the first face, tilt removed: −(y′ − y) (the same step)
    h_drift = np.full(m, np.nan)
    for j, r in closure_row.items():
        f = first_row[j]
        h_drift[mindex[j]] = closure_drift_arcsec(a[f], c[f] + pyramidal[f], a[r], c[r] + pyramidal[r])
    for j in order:
        if j in closure_row and abs(h_drift[mindex[j]]) > closure_limit_arcsec:
            warnings.append(message(QT_TR_NOOP("mounting {mounting}: closure drift {drift} exceeds "
                                               "the limit ±{limit}: repeat the mounting"),
                                    mounting=j, drift=f"{h_drift[mindex[j]]:+.3f}\"",
                                    limit=f"{closure_limit_arcsec:g}\""))

    # the linear map from the readings to the data the least squares sees (spread: each
    # mounting's rows less t/n of its closure drift; the closure reading is used up)
    used = ~closure if mode in ("spread", "report") else np.ones(y.size, dtype=bool)
    rows_n = int(used.sum())
    used_index = np.flatnonzero(used)
    y_data = y.copy()
    if mode == "spread":
        for j, r in closure_row.items():  # the closure reading itself becomes the first's
            rows = rows_of[j]
            y_data[rows] -= t[rows] / n * (y[r] - y[first_row[j]])

    # design: columns E (n), d (n), o (m), δ (mountings with closure, when fitted; and the
    # mountings without one where the design determines their drift through the others)
    closed = [j for j in order if j in closure_row] if mode == "fit" else []
    fit = _fit(y_data, used_index, mounting, k, position, t, order, mindex, closed, n)
    if closed and len(closed) < m:
        every = _fit(y_data, used_index, mounting, k, position, t, order, mindex, list(order), n)
        # each added drift determined, and (σ from the residuals) a degree of freedom left
        if every.rank == fit.rank + m - len(closed) and (noise_arcsec is not None
                                                         or rows_n > every.rank):
            fit = every
    drifting, dindex, p, design_all, design = (fit.drifting, fit.dindex, fit.p, fit.design_all,
                                               fit.design)
    z, vec, seen, rank = fit.z, fit.vec, fit.seen, fit.rank
    solver = fit.solver
    x = fit.x
    for j in order:
        if j in closure_row:
            continue
        if j in dindex:
            warnings.append(message(QT_TR_NOOP(
                "mounting {mounting}: no closure reading (its first face read again at the end): "
                "its drift fitted through the other mountings' closure readings"), mounting=j))
        else:
            warnings.append(message(QT_TR_NOOP("mounting {mounting}: no closure reading (its first "
                                               "face read again at the end): drift not checked"),
                                    mounting=j))
    residuals = y_data - design_all @ x
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
    mountings_text = ", ".join(map(str, order))
    if (np.linalg.norm(keep_e @ null_e) > 1e-6 or np.linalg.norm(keep_d @ null_d) > 1e-6
            or len(bad_e) == n // 2 or len(bad_d) == n // 2):
        raise _refuse(QT_TR_NOOP("mountings {mountings} do not connect the faces: no harmonic of "
                                 "the encoder's error or of the face deviations is determined"),
                      mountings=mountings_text)

    if mode == "spread" and closure_row:
        # exact: x = solver·Xᵀ·L·y, L the spread map; E‖r‖² = σ²·tr(Lᵀ(I − H)L)
        lrows, lcols, lvals = list(range(rows_n)), [int(c) for c in used_index], [1.0] * rows_n
        position_in_used = {int(r): u for u, r in enumerate(used_index)}
        for j, r in closure_row.items():
            for row in rows_of[j][1:-1]:
                u = position_in_used[int(row)]
                lrows += [u, u]
                lcols += [r, first_row[j]]
                lvals += [-t[row] / n, t[row] / n]
        spread_map = sparse.csr_matrix((lvals, (lrows, lcols)), shape=(rows_n, y.size))
        gain = (spread_map.T @ (design @ solver)).T  # p × all rows: x = gain · y
        design_map = (spread_map.T @ design).T.toarray()  # Xᵀ L
        scatter_trace = float(spread_map.multiply(spread_map).sum() - np.sum(gain * design_map))
        cov_unit = gain @ gain.T
    else:
        scatter_trace = float(rows_n - rank)
        cov_unit = solver
        gain = np.zeros((p, y.size))
        gain[:, used_index] = (design @ solver).T
    dof = float(rows_n - rank)
    scatter_residuals = residuals
    if noise_arcsec is not None:
        sigma, dof = float(noise_arcsec), float(noise_dof)
    elif dof <= 0:
        raise _refuse(QT_TR_NOOP("{readings} readings determine {unknowns} unknowns with none left "
                                 "over: the scatter of a reading cannot be evaluated — add a "
                                 "mounting, or state the autocollimator's σ"),
                      readings=rows_n, unknowns=rank)
    else:
        used_res = residuals[used_index]
        sigma = float(math.sqrt(used_res @ used_res / scatter_trace))
        if mode == "report" and closure_row:
            sigma, dof, scatter_residuals = _scatter_without_drift(
                y, mounting, k, position, t, order, mindex,
                [j for j in order if j in closure_row], n, rank, sigma, dof, scatter_residuals)
    cov_x = sigma**2 * cov_unit
    proj = np.zeros((2 * n, p))
    proj[:n, :n] = keep_e
    proj[n:, n:2 * n] = keep_d
    cov = proj @ cov_x @ proj.T
    e_det = keep_e @ x[:n]
    d_det = keep_d @ x[n:2 * n]
    drift_out = h_drift.copy()
    if mode == "fit":
        drift_out = np.full(m, np.nan)
        for j in drifting:
            drift_out[mindex[j]] = -x[2 * n + m + dindex[j]]
    offsets = x[2 * n:2 * n + m]
    # the same autocollimator reads both axes: vertical readings far off their tilt curve
    # are no tilt (a wrong column, a slipped face); their correction is then not to be trusted
    # (the scatter left after each mounting's tilt and the faces' own pyramidal errors)
    for j, tilt, rms in zip(order, tilts, vertical_scatter, strict=True):
        if tilt is not None and rms > VERTICAL_SCATTER_FACTOR * sigma + 0.1:
            warnings.append(message(QT_TR_NOOP("mounting {mounting}: the vertical readings scatter "
                                               "{rms} RMS about the tilt fitted, far more than the "
                                               "horizontal ones ({sigma}): check them; the tilt "
                                               "correction rests on them"),
                                    mounting=j, rms=f"{rms:.3f}\"",
                                    sigma=f"{sigma:.3f}\""))
        elif tilt is not None and tilt.psi_arcsec > MAX_TILT_ARCSEC:
            warnings.append(message(QT_TR_NOOP("mounting {mounting}: a tilt of {psi} was fitted — "
                                               "no polygon sits that far off its seat: check the "
                                               "vertical readings"),
                                    mounting=j, psi=f"{tilt.psi_arcsec:.0f}\""))
    if bad_e or bad_d:
        warnings.append(_undetermined_text(n, tuple(order), bad_e, bad_d))
    return CrossCalibration(
        faces=n, mountings=tuple(order),
        encoder_error_arcsec=None if bad_e else e_det,
        polygon_deviation_arcsec=None if bad_d else d_det,
        undetermined_encoder_harmonics=bad_e, undetermined_polygon_harmonics=bad_d,
        encoder_error_determined_arcsec=e_det, polygon_deviation_determined_arcsec=d_det,
        covariance_arcsec2=cov, sigma_arcsec=sigma, dof=dof,
        coverage_factor=coverage_factor(dof, probability),
        offsets_arcsec=offsets - offsets.mean(), drift_arcsec=drift_out,
        residuals_arcsec=residuals, rank_deficiency=deficiency,
        closure_drift_arcsec=h_drift, drift_mode=mode, tilts=tilts, ac_alignment=ac_alignment,
        pyramidal_arcsec=pyramidal, row_step=k, row_time=t, row_closure=closure, row_used=used,
        row_mounting=mounting,
        probability=probability, warnings=tuple(warnings),
        face_pyramidal_arcsec=None if faces_fit is None else faces_fit.elevation_arcsec,
        face_pyramidal_u_arcsec=None if faces_fit is None else faces_fit.u_arcsec,
        vertical_scatter_arcsec=vertical_scatter, gain=proj @ gain,
        sigma_stated=noise_arcsec is not None, scatter_residuals_arcsec=scatter_residuals)
