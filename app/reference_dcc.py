"""``anglebench analyze polygon FILE --reference-dcc POLY.xml``: the polygon's digital
calibration certificate as the reference. Its face deviations replace the readings'
polygon-deviation column (a warning when that column held other values), and the polygon,
with its U, takes its place among the certificate's standards (so its U enters the budget as
a polygon certificate's does). Refused, with the reason, as models/dcc/reader refuses: the
schema (with --dcc-schema or ANGLEBENCH_DCC_SCHEMA), a unit that is no angle, a face count
that differs, a signature that does not verify (or none where a trusted certificate is set),
a calibration due before the date of calibration (the details' date, else today) or dated
after it, and a DCC of another polygon than the details list (its serial)."""

from __future__ import annotations

import datetime as dt
from typing import Any

from models.certificate.metadata import CertificateMetadata
from models.dcc.reader import (
    PolygonReference,
    place_polygon_standard,
    polygon_standard,
    read_polygon_dcc,
    replace_face_deviations,
)
from models.messages import QT_TR_NOOP, message

__all__ = ["placed_reference", "reference_rows", "with_reference"]


def reference_rows(path: str, kind, rows: list[list[str]], settings: dict[str, Any],
                   calibration_date: str, schema_dir: str = ""
                   ) -> tuple[list[list[str]], PolygonReference, list[str]]:
    """The readings' rows with the DCC's deviations in place, the reference, and what to
    say (the column's other values replaced, the reader's notes). DccError / SigningError
    for a DCC refused."""
    from models.dcc.reader import DccError
    from models.dcc.signature import signature_demanded, trusted_certificate
    from models.register.location import register_url
    from models.register.read_in import own_dcc_refusal_at

    # this register's own DCC: as issued and current only (hostile78 F4)
    refused = own_dcc_refusal_at(register_url(), path)
    if refused is not None:
        raise DccError(refused)
    columns = [c.key for c in kind.columns]
    faces = int(settings.get("faces") or 0) or None
    reference = read_polygon_dcc(path, schema_dir or None,
                                 measurement_date=calibration_date or dt.date.today(),
                                 faces=faces, trusted_cert=trusted_certificate(),
                                 trust_named=signature_demanded())
    out, differed = replace_face_deviations(rows, columns.index("position"),
                                            columns.index("polygon_dev_arcsec"), reference)
    said = list(reference.notes)
    if differed:
        said.insert(0, message(QT_TR_NOOP(
            "the deviation column held other values: they were replaced by those of "
            "certificate {id} ({path})"), id=reference.certificate_id, path=path))
    return out, reference, said


def with_reference(metadata: CertificateMetadata, reference: PolygonReference | None
                   ) -> CertificateMetadata:
    """The details with the polygon of ``reference`` among the standards (in place of the
    polygon they list); unchanged without a reference. DccError when the DCC is another
    polygon's (models/dcc/reader.item_notes)."""
    return placed_reference(metadata, reference)[0]


def placed_reference(metadata: CertificateMetadata, reference: PolygonReference | None
                     ) -> tuple[CertificateMetadata, tuple]:
    """:func:`with_reference` and what to say (a serial taken from the DCC, or none in it to
    compare). DccError for another polygon's DCC, MetadataError for a standard the details
    cannot take."""
    if reference is None:
        return metadata, ()
    data = metadata.to_dict()
    data["standards"], said = place_polygon_standard(data["standards"],
                                                     polygon_standard(reference), reference)
    return CertificateMetadata.from_dict(data), said
