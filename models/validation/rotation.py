"""Rotations for the test rigs: numpy only, nothing from the code under test."""

from __future__ import annotations

import numpy as np

ARCSEC = np.pi / (180.0 * 3600.0)  # one arcsecond in radians


def rotate(vectors: np.ndarray, axis: np.ndarray, angle_rad: float) -> np.ndarray:
    """Rotate column vectors (3, m) about a unit ``axis`` by ``angle_rad`` (right-handed),
    by building the rotation matrix from the axis' cross-product matrix (Rodrigues)."""
    kx, ky, kz = axis
    cross = np.array([[0.0, -kz, ky], [kz, 0.0, -kx], [-ky, kx, 0.0]])
    matrix = np.eye(3) + np.sin(angle_rad) * cross + (1.0 - np.cos(angle_rad)) * (cross @ cross)
    return matrix @ vectors
