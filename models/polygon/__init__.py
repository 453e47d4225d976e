"""The polygon workbench: an encoder tested against a polygon and an autocollimator
(Tian et al. 2015).

Its key and title are given once, here: the analysis, the certificate and the window use them.
"""

from models.messages import QT_TR_NOOP

KEY = "polygon"
TITLE = QT_TR_NOOP("Polygon encoder test")
