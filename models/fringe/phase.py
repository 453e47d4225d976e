"""The phase of a fringe record from its two channels alone (no phase reference).

Heydemann's correction (Appl. Opt. 20, 1981): with an offset, unequal
amplitudes and a quadrature error the Lissajous figure of (u_sin, u_cos) is an
ellipse,

    u_sin = p + a·sin φ,    u_cos = q + b·cos(φ + α),

so an ellipse fitted to the samples gives the offsets p, q, the amplitude ratio
b/a and the quadrature error α, and then each sample's phase φ, whatever the
speed, stops or reversals of the motion. The fit is the direct least-squares
ellipse of Fitzgibbon et al. (1999) in the numerically stable form of Halír &
Flusser (1998). ``α`` here is the quadrature error as the fringe workbench
reports it: (phase of the cos channel's fundamental − that of the sin channel)
− 90°.

What cannot be seen without a phase reference: a distortion that moves the
phase without bending the figure (a pure phase error of the grating) leaves
the Lissajous figure round, and no analysis of the two channels can find it.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from models.messages import QT_TR_NOOP, message

__all__ = ["EllipseFit", "fit_ellipse", "unwrapped"]

_BLOCK = 1 << 16  # samples a block when the scatter matrix is summed


@dataclass(frozen=True)
class EllipseFit:
    """Heydemann's parameters: offsets (V), amplitudes (V), quadrature error (rad)."""

    offset_sin: float
    offset_cos: float
    amplitude_sin: float
    amplitude_cos: float
    quadrature_rad: float

    @property
    def amplitude_ratio(self) -> float:
        """b/a: the cos channel's fundamental over the sin channel's."""
        return self.amplitude_cos / self.amplitude_sin

    def _corrected(self, u_sin, u_cos) -> tuple[np.ndarray, np.ndarray]:
        """The signals with the offsets, amplitudes and quadrature error taken out: (sin φ,
        cos φ) times the sample's radius. In two new buffers: a million samples'
        temporaries cost as much as their arithmetic."""
        s = np.subtract(u_sin, self.offset_sin, dtype=float)
        s /= self.amplitude_sin
        c = np.subtract(u_cos, self.offset_cos, dtype=float)
        c /= self.amplitude_cos
        c += s * math.sin(self.quadrature_rad)
        c /= math.cos(self.quadrature_rad)
        return s, c

    def phase_and_phasor(self, u_sin, u_cos) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """Each sample's phase φ (rad, in (−π, π]) and its (sin φ, cos φ): the corrected
        signals over their norm (a sample at the centre has phase 0)."""
        s, c = self._corrected(u_sin, u_cos)
        phase = np.arctan2(s, c)
        norm = np.multiply(s, s)
        norm += c * c
        np.sqrt(norm, out=norm)
        centre = norm == 0.0
        if np.any(centre):
            s[centre], c[centre], norm[centre] = 0.0, 1.0, 1.0
        s /= norm
        c /= norm
        return phase, s, c

    def radius(self, u_sin, u_cos) -> np.ndarray:
        """The corrected samples' distance from the centre: 1 on the ellipse."""
        s, c = self._corrected(u_sin, u_cos)
        np.multiply(s, s, out=s)
        np.multiply(c, c, out=c)
        s += c
        return np.sqrt(s, out=s)


def unwrapped(phase_rad) -> np.ndarray:
    """A phase in (−π, π] made continuous: a step of more than π between two samples is
    a wrap, and whole turns (an exact multiple of 2π each) are added from there on."""
    phase = np.asarray(phase_rad, dtype=float)
    if phase.size < 2:
        return phase.copy()
    step = np.diff(phase)
    turns = np.cumsum((step < -math.pi).view(np.int8), dtype=np.int64)
    turns -= np.cumsum((step > math.pi).view(np.int8), dtype=np.int64)
    out = np.empty_like(phase)
    out[0] = phase[0]
    np.multiply(turns, 2.0 * math.pi, out=out[1:])
    out[1:] += phase[1:]
    return out


def fit_ellipse(u_sin, u_cos) -> EllipseFit:
    """The ellipse through the samples (x = u_sin, y = u_cos) by direct least squares.

    Raises ValueError when the samples do not make an ellipse.
    """
    x = np.asarray(u_sin, dtype=float)
    y = np.asarray(u_cos, dtype=float)
    # centre and scale first: the conic's coefficients are then of one size
    cx, cy = float(np.mean(x)), float(np.mean(y))
    scale = float(max(np.std(x), np.std(y)))
    if not scale > 0:
        raise ValueError(message(
            QT_TR_NOOP("the signals do not move")))
    # the scatter matrix of the monomials (x², xy, y², x, y, 1), a block of samples at a
    # time in one small buffer, cut into Halír & Flusser's blocks S1, S2, S3
    block = min(x.size, _BLOCK)
    monomials = np.empty((6, block))
    monomials[5] = 1.0
    scatter = np.zeros((6, 6))
    for start in range(0, x.size, block):
        m = monomials[:, :min(block, x.size - start)]
        xs, ys = m[3], m[4]
        np.subtract(x[start:start + block], cx, out=xs)
        xs /= scale
        np.subtract(y[start:start + block], cy, out=ys)
        ys /= scale
        np.multiply(xs, xs, out=m[0])
        np.multiply(xs, ys, out=m[1])
        np.multiply(ys, ys, out=m[2])
        scatter += m @ m.T
    s1, s2, s3 = scatter[:3, :3], scatter[:3, 3:], scatter[3:, 3:]
    try:
        t = -np.linalg.solve(s3, s2.T)
    except np.linalg.LinAlgError:
        raise ValueError(message(
            QT_TR_NOOP("the samples do not make an ellipse (degenerate)"))) from None
    m = s1 + s2 @ t
    m = np.array([m[2] / 2.0, -m[1], m[0] / 2.0])  # C1⁻¹·M with C1 the ellipse constraint
    values, vectors = np.linalg.eig(m)
    vectors = np.real(vectors)
    condition = 4.0 * vectors[0] * vectors[2] - vectors[1] ** 2
    candidates = np.nonzero(condition > 0)[0]
    if candidates.size == 0:
        raise ValueError(message(
            QT_TR_NOOP("the samples do not make an ellipse")))
    a1 = vectors[:, candidates[0]]
    a2 = t @ a1
    big_a, big_b, big_c = a1
    big_d, big_e, big_f = a2
    # centre of the conic in the scaled frame
    det = 4.0 * big_a * big_c - big_b**2
    px = (big_b * big_e - 2.0 * big_c * big_d) / det
    qy = (big_b * big_d - 2.0 * big_a * big_e) / det
    f0 = big_a * px**2 + big_b * px * qy + big_c * qy**2 + big_d * px + big_e * qy + big_f
    if not f0 < 0 and not f0 > 0:
        raise ValueError(message(
            QT_TR_NOOP("the samples do not make an ellipse")))
    # A X² + B XY + C Y² = 1 after moving to the centre
    aa, bb, cc = -big_a / f0, -big_b / f0, -big_c / f0
    if not (aa > 0 and cc > 0):
        raise ValueError(message(
            QT_TR_NOOP("the samples do not make an ellipse")))
    sin_q = bb / (2.0 * math.sqrt(aa * cc))
    if not abs(sin_q) < 1.0:
        raise ValueError(message(
            QT_TR_NOOP("the samples do not make an ellipse")))
    cos_q = math.sqrt(1.0 - sin_q * sin_q)
    a = 1.0 / (math.sqrt(aa) * cos_q)
    b = 1.0 / (math.sqrt(cc) * cos_q)
    return EllipseFit(cx + scale * px, cy + scale * qy, scale * a, scale * b, math.asin(sin_q))
