"""The theodolite workbench: a theodolite's errors against a turntable (Tian et al. 2017).

Its key and title are given once, here: the analysis, the certificate and the window use them.
"""

from models.messages import QT_TR_NOOP

KEY = "theodolite"
TITLE = QT_TR_NOOP("Theodolite run")
