"""A figure the data cannot determine: the certificate is refused, naming why.

Raised where a budget's input would come from nothing (a reading noise with no degrees of
freedom, say): printing a U without it would state a coverage it does not have. It is a
:class:`~models.certificate.metadata.MetadataError`, so the command line and the window
refuse the certificate with its message as they refuse bad details.
"""

from __future__ import annotations

from models.certificate.metadata import MetadataError

__all__ = ["UncertaintyWithheld"]


class UncertaintyWithheld(MetadataError):
    """No honest U can be given for these readings; the message says why and what helps."""
