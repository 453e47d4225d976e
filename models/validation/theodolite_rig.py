"""A limited-rotation axis seen by an autocollimating theodolite, by 3-D rotation.

Frame of ../shared/SPEC.md §1: OZ plumb down, OX the azimuth zero. The axis is tilted by
ψ towards α, ``P = [−sinψ cosα, −sinψ sinα, cosψ]``; the mirror normal at the
axis' zero is ``[cosβ, 0, −sinβ]``. The axis turns the mirror by its true
rotation (right-handed about P); the theodolite reads the normal's azimuth
atan2(y, x) and elevation asin(z). Nothing here comes from ``models``.
"""

from __future__ import annotations

import numpy as np

from models.validation.rotation import rotate


def theodolite_readings(true_rotation_deg, psi_deg: float, alpha_deg: float,
                        beta_deg: float) -> tuple[np.ndarray, np.ndarray]:
    """Azimuth and elevation (deg) of the mirror normal at each true rotation."""
    psi, alpha, beta = np.radians([psi_deg, alpha_deg, beta_deg])
    axis = np.array([-np.sin(psi) * np.cos(alpha), -np.sin(psi) * np.sin(alpha), np.cos(psi)])
    normal = np.array([[np.cos(beta)], [0.0], [-np.sin(beta)]])
    az, el = [], []
    for phi in np.radians(np.atleast_1d(np.asarray(true_rotation_deg, dtype=float))):
        x, y, z = rotate(normal, axis, phi)[:, 0]
        az.append(np.degrees(np.arctan2(y, x)))
        el.append(np.degrees(np.arcsin(z)))
    return np.array(az), np.array(el)
