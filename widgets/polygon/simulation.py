"""Simulation panel of the polygon workbench (the curves of Figs 3 and 4 of Tian et al.
2015): the induced horizontal error ε_x and the vertical reading ε_y over the circle for a
family of tilt directions or sizes, on a levelled bench (the main set-up's default, where
the panel starts) or with the autocollimator's vertical along the polygon's axis (the
paper's frame)."""

from __future__ import annotations

import numpy as np

from models.polygon.model import frame_readings_arcsec
from widgets.family_simulation import FamilySimulation
from widgets.i18n import tr
from widgets.settings_form import SettingsForm


def _family(p: dict) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    theta = np.linspace(0.0, 360.0, 361)
    eps_x, eps_y = frame_readings_arcsec(theta, p["psi_arcsec"], p["omega_deg"],
                                         p.get("ac_alignment", "levelled"))
    return theta, eps_x, eps_y


class PolygonSimulation(FamilySimulation):
    """``top_curves``: ε_x (") per swept value; ``bottom_curves``: ε_y (")."""

    def __init__(self, parent=None) -> None:
        form = SettingsForm()
        form.add_float("psi_arcsec", tr("tilt ψ"), 0, 7200, 1, "\"", 30)
        form.add_float("omega_deg", tr("direction ω"), 0, 360, 1, "°", 15)
        form.add_choice("sweep", tr("sweep"), [("omega_deg", tr("direction ω")),
                                               ("psi_arcsec", tr("tilt ψ"))],
                        tr("The parameter drawn as a family of curves: the tilt's direction ω "
                           "(as in Fig. 3 of Tian et al. 2015, the polygon method's paper) or "
                           "its size ψ (as in its Fig. 4)"))
        # the same set-up as the workbench's own default (levelled), the paper's frame second
        form.add_choice("ac_alignment", tr("autocollimator set-up"),
                        [("levelled", tr("levelled with the rotary axis")),
                         ("polygon", tr("vertical along the polygon's axis (rolled with the "
                                        "tilt)"))])
        form.set_values({"psi_arcsec": 300, "omega_deg": 90, "ac_alignment": "levelled"})
        super().__init__(form, {"omega_deg": ("ω", "°"), "psi_arcsec": ("ψ", "\"")},
                         "0, 45, 90, 135, 180", _family,
                         (tr("θ (deg)"), tr("ε_x induced error (\")"), tr("ε_y vertical (\")")), parent)
