"""The fringe workbench: a grating's sine and cosine signals, their interpolation error
and its correction table (Gao et al. 2013).

Its key and title are given once, here: the analysis, the certificate and the window use them.
"""

from models.messages import QT_TR_NOOP

KEY = "fringe"
TITLE = QT_TR_NOOP("Fringe signal analysis")

#: the standards that carry the measurand (a calibration certificate states traceability
#: only when each is listed with a certificate and a stated U; the statement of conformity
#: is withheld while one is not): the workbench's and its certificate's one list, each by
#: its role (models.certificate.metadata.STANDARD_ROLES) and name
MEASURAND_STANDARDS = (("reference", QT_TR_NOOP("a phase or angle reference")),
                       ("adc", QT_TR_NOOP("the ADC (its figures stated in the settings)")))
#: the roles only a standard stating its role carries: a standard listed with a U and no role
#: may be the ADC's certificate (or any other), so it is never taken as the phase or angle
#: reference (assessment 78 H1: such a standard made the document a traceable calibration
#: certificate); the reason names the role to state
ROLES_STATED_ONLY = ("reference",)
