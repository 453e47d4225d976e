"""How every workbench signs its errors (VIM 4.1): indicated − reference; a correction is the
negative of an error. Its own module so that the workbench seam (models.workbench) and the
certificate (models.certificate.document) both name it without importing each other."""

from models.messages import QT_TR_NOOP

__all__ = ["SIGN_CONVENTION", "SIGN_CONVENTION_TEXT"]

# the JSON's ``sign_convention``
SIGN_CONVENTION = "indicated_minus_reference"
#: the certificate's sentence
SIGN_CONVENTION_TEXT = QT_TR_NOOP("error = indicated − reference (VIM); correction = −error")
