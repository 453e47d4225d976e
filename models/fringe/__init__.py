"""The fringe workbench: a grating's sine and cosine signals, their interpolation error
and its correction table (Gao et al. 2013).

Its key and title are given once, here: the analysis, the certificate and the window use them.
"""

from models.messages import QT_TR_NOOP

KEY = "fringe"
TITLE = QT_TR_NOOP("Fringe signal analysis")
