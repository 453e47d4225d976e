"""Cross-calibration of a polygon and an encoder against each other by the closure
principle: the model (solve.py) and the workbench (analysis.py).

Its key and title are given once, here: the analysis, the certificate and the window use them.
"""

from models.messages import QT_TR_NOOP

KEY = "crosscal"
TITLE = QT_TR_NOOP("Cross-calibration (polygon + encoder)")

#: the largest tilt of the polygon on the shaft the budget takes for a mounting without
#: vertical readings when none is stated (the setting ``tilt_bound_arcsec``, ″): printed as
#: the program's default, not as the laboratory's figure
DEFAULT_TILT_BOUND_ARCSEC = 60.0

#: The polygon's face deviation is signed actual − nominal, the sign its certificate feeds the
#: polygon workbench with (dev_i in b_i = (i−1)·360°/n + dev_i). A material measure indicates
#: its nominal value (VIM 3.6), so d_i = actual − indicated: the negative of an error
#: of indication, an exception to the other workbenches' sign stated as positioning states its
#: own. The encoder's error of the same run keeps error = indicated − reference.
POLYGON_SIGN_CONVENTION = "actual_minus_nominal"
POLYGON_SIGN_CONVENTION_TEXT = QT_TR_NOOP(
    "face deviation d_i = the face's angle − its nominal (actual − nominal), i.e. reference − "
    "indicated, as a material measure indicates its nominal value (VIM 3.6): the "
    "negative of an error of indication; the face's angle = nominal + d_i")
