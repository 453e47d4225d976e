"""Simulation panel of the theodolite workbench (the seed's Figs 3–6): ζ(θ) and E(θ)
for ψ, α, β with one of them swept."""

from __future__ import annotations

import numpy as np

from models.theodolite.model import forward_readings, induced_error_arcsec
from widgets.family_simulation import FamilySimulation
from widgets.i18n import tr
from widgets.settings_form import SettingsForm


def _family(p: dict) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    theta = np.linspace(-p["half_range_deg"], p["half_range_deg"], 241)
    args = (p["psi_deg"], p["alpha_deg"], p["beta_deg"])
    return theta, induced_error_arcsec(theta, *args), forward_readings(theta, *args)[1]


class TheodoliteSimulation(FamilySimulation):
    """``top_curves``: ζ (") per swept value; ``bottom_curves``: E (deg)."""

    def __init__(self, parent=None) -> None:
        form = SettingsForm()
        form.add_float("psi_deg", tr("axis tilt ψ"), -10, 10, 4, "°", 0.5)
        form.add_float("alpha_deg", tr("tilt direction α"), 0, 360, 3, "°", 15)
        form.add_float("beta_deg", tr("mirror normal β"), -10, 10, 4, "°", 0.5)
        form.add_float("half_range_deg", tr("θ range ±"), 1, 180, 1, "°", 5)
        form.add_choice("sweep", tr("sweep"), [("beta_deg", tr("mirror normal β")),
                                               ("alpha_deg", tr("tilt direction α")),
                                               ("psi_deg", tr("axis tilt ψ"))],
                        tr("The parameter drawn as a family of curves, as in the figures of "
                           "Tian et al. 2017 (the theodolite method's paper): β as in its Figs. "
                           "3 and 4, α as in its Fig. 5, ψ as in its Fig. 6"))
        form.set_values({"psi_deg": 3, "alpha_deg": 45, "beta_deg": 2, "half_range_deg": 20})
        super().__init__(form, {"beta_deg": ("β", "°"), "alpha_deg": ("α", "°"),
                                "psi_deg": ("ψ", "°")},
                         "-2, -1, 0, 1, 2", _family, (tr("θ (deg)"), tr("ζ (\")"), tr("E (deg)")), parent)
