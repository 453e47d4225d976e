"""Positioning of an axis against a reference: ISO 230-2, VDI/DGQ 3441, compensation.

Its key and title are given once, here: the analysis, the certificate and the window use them.
"""

from models.messages import QT_TR_NOOP

KEY = "positioning"
TITLE = QT_TR_NOOP("Positioning (axis)")

#: the standards that carry the measurand (a calibration certificate states traceability
#: only when each is listed with a certificate and a stated U; the statement of conformity
#: is withheld while one is not): the workbench's and its certificate's one list, each by
#: its role (models.certificate.metadata.STANDARD_ROLES) and name
MEASURAND_STANDARDS = (("reference", QT_TR_NOOP("the reference measuring system")),)
