"""Simulation panel of the polygon workbench (the seed's Figs 3–6): the induced
horizontal error ε_x and the vertical reading ε_y over the circle for a family of
tilt directions or sizes, in seed 001's frame (its figures) or on a levelled bench."""

from __future__ import annotations

import numpy as np

from models.polygon.model import frame_readings_arcsec
from widgets.family_simulation import FamilySimulation
from widgets.i18n import tr
from widgets.settings_form import SettingsForm


def _family(p: dict) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    theta = np.linspace(0.0, 360.0, 361)
    eps_x, eps_y = frame_readings_arcsec(theta, p["psi_arcsec"], p["omega_deg"],
                                         p.get("ac_alignment", "polygon"))
    return theta, eps_x, eps_y


class PolygonSimulation(FamilySimulation):
    """``top_curves``: ε_x (") per swept value; ``bottom_curves``: ε_y (")."""

    def __init__(self, parent=None) -> None:
        form = SettingsForm()
        form.add_float("psi_arcsec", tr("tilt ψ"), 0, 7200, 1, "\"", 30)
        form.add_float("omega_deg", tr("direction ω"), 0, 360, 1, "°", 15)
        form.add_choice("sweep", tr("sweep"), [("omega_deg", tr("direction ω (Fig 3)")),
                                               ("psi_arcsec", tr("tilt ψ (Fig 4)"))])
        form.add_choice("ac_alignment", tr("autocollimator set-up"),
                        [("polygon", tr("polygon's axis (seed 001's frame)")),
                         ("levelled", tr("levelled (AC and rotary axis levelled)"))])
        form.set_values({"psi_arcsec": 300, "omega_deg": 90})
        super().__init__(form, {"omega_deg": ("ω", "°"), "psi_arcsec": ("ψ", "\"")},
                         "0, 45, 90, 135, 180", _family,
                         (tr("θ (deg)"), tr("ε_x induced error (\")"), tr("ε_y vertical (\")")), parent)
