"""A phase reference's per-sample errors carried through the fit to the fitted curve.

The decided half range is the half peak-to-peak of the fitted model's error curve
atan2(S, C) − θ over the whole period (models.fringe.report.model_error_curve). A reference
whose error δ_i at each sample is independent from sample to sample (a standard stated per
reading, the sampling's timing) moves each reading as a phase error would:
u_s(θ_i + δ_i) ≈ S(θ_i) + S'(θ_i) δ_i, and the same δ_i in the cos channel through C'(θ_i).
The least-squares fit takes these as it takes noise: the parameters move by
β_s = (XᵀX)⁻¹ Xᵀ (S' ∘ δ) and β_c = (XᵀX)⁻¹ Xᵀ (C' ∘ δ), correlated between the channels
(one δ for both), and the curve's phase at θ by C/R² · x(θ)ᵀβ_s − S/R² · x(θ)ᵀβ_c.

With δ independent, of standard uncertainty u, the joint covariance of (β_s, β_c) is u²
times the 2p × 2p matrix [[A Aᵀ, A Bᵀ], [B Aᵀ, B Bᵀ]] (A = (XᵀX)⁻¹ Xᵀ diag(S'), B the
same with C'), worked out in O(n p²) without forming A. Its eigenvectors, each scaled by
the root of its eigenvalue, carried to the curve, are the independent directions a draw
of the reference's errors moves the curve in (one value each per trial, as the fitted
parameters' own directions, :func:`models.fringe.model.model_signal_modes`). A δ the same at
every sample (a common shift) moves the curve by δ everywhere and cancels in the half
range; independent ones do not: their share of the curve is about u·√(2p/n), not 0 (the
assessment 76 M3: a per-sample u of 0.001″ to 2″ stated left the decided interval
unchanged, "pass" every time).
"""

from __future__ import annotations

import numpy as np

from models.fringe.model import fit_design, model_signal, model_slope

__all__ = ["reference_curve_modes"]


def reference_curve_modes(result, theta_rad: np.ndarray) -> np.ndarray:
    """(len(theta_rad), 2p) changes of the fitted model's phase error at ``theta_rad`` per
    unit standard uncertainty of an independent per-sample phase error of the reference (a
    draw ξ ~ N(0, I) gives the curve's change u · (modes @ ξ), in u's unit), one column per
    independent direction."""
    theta_fit = np.asarray(result.theta_rad, dtype=float)
    fits = (result.sin_fit, result.cos_fit)
    designs = [fit_design(theta_fit, fit.orders) for fit in fits]
    slopes = [model_slope(theta_fit, fit) for fit in fits]
    inverses = [np.linalg.pinv(x.T @ x) for x in designs]
    # A Aᵀ, A Bᵀ, B Bᵀ: (XᵀX)⁻¹ Xᵀ diag(a b) X (XᵀX)⁻¹
    blocks = [[inverses[i] @ ((designs[i] * (slopes[i] * slopes[j])[:, None]).T @ designs[j])
               @ inverses[j] for j in range(2)] for i in range(2)]
    joint = np.block(blocks)
    values, vectors = np.linalg.eigh(0.5 * (joint + joint.T))
    scaled = vectors * np.sqrt(np.clip(values, 0.0, None))
    theta = np.asarray(theta_rad, dtype=float)
    s, c = model_signal(theta, fits[0]), model_signal(theta, fits[1])
    r2 = s**2 + c**2
    along = np.hstack([(c / r2)[:, None] * fit_design(theta, fits[0].orders),
                       (-s / r2)[:, None] * fit_design(theta, fits[1].orders)])
    return along @ scaled
