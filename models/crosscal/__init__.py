"""Cross-calibration of a polygon and an encoder against each other by the closure
principle: the model (solve.py) and the workbench (analysis.py).

Its key and title are given once, here: the analysis, the certificate and the window use them.
"""

from models.messages import QT_TR_NOOP

KEY = "crosscal"
TITLE = QT_TR_NOOP("Cross-calibration (polygon + encoder)")
