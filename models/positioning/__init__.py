"""Positioning of an axis against a reference: ISO 230-2, VDI/DGQ 3441, compensation.

Its key and title are given once, here: the analysis, the certificate and the window use them.
"""

from models.messages import QT_TR_NOOP

KEY = "positioning"
TITLE = QT_TR_NOOP("Positioning (axis)")
