"""Validating a DCC against PTB's schema set, offline.

The laboratory points AngleBench to a folder holding PTB's ``dcc.xsd`` (3.3.0) with the
D-SI 2.2.1 ``si/SI_Format.xsd``, its QUDT helper ``si/qudt/quantitykind.xsd`` and the W3C
XML-DSig schema ``d-sig/xmldsig-core-schema.xsd`` (PTB publishes them at
https://ptb.de/dcc/v3.3.0/ and https://ptb.de/si/v2.2.1/). Nothing is fetched: the
network is off for the parser, and the one URL ``SI_Format.xsd`` imports the QUDT helper
from is mapped to the local file.
"""

from __future__ import annotations

import functools
from pathlib import Path

from lxml import etree

from models.messages import QT_TR_NOOP, message

__all__ = ["DccSchemaError", "load_schema", "validate"]

QUDT_URLS = ("https://www.ptb.de/si/v2.2.1/qudt/quantitykind.xsd",
             "https://ptb.de/si/v2.2.1/qudt/quantitykind.xsd")
QUDT_LOCAL = Path("si") / "qudt" / "quantitykind.xsd"


class DccSchemaError(ValueError):
    """The schema folder cannot be used (a file missing, not a schema); names the folder."""


class _LocalQudt(etree.Resolver):
    def __init__(self, folder: Path) -> None:
        super().__init__()
        self.folder = folder

    def resolve(self, url, pubid, context):
        if url in QUDT_URLS:
            return self.resolve_filename(str(self.folder / QUDT_LOCAL), context)
        return None


@functools.lru_cache(maxsize=4)
def _schema(folder: str) -> etree.XMLSchema:
    root = Path(folder)
    main = root / "dcc.xsd"
    for needed in (main, root / QUDT_LOCAL):
        if not needed.is_file():
            raise DccSchemaError(message(QT_TR_NOOP(
                "DCC schema folder {folder}: {file} is missing (PTB's DCC 3.3.0 schema set is "
                "needed: dcc.xsd, si/SI_Format.xsd, si/qudt/quantitykind.xsd, "
                "d-sig/xmldsig-core-schema.xsd)"), folder=folder, file=needed.name))
    parser = etree.XMLParser(no_network=True, resolve_entities=False, load_dtd=False)
    parser.resolvers.add(_LocalQudt(root))
    try:
        return etree.XMLSchema(etree.parse(str(main), parser))
    except (etree.XMLSchemaParseError, etree.XMLSyntaxError, OSError) as exc:
        raise DccSchemaError(message(QT_TR_NOOP(
            "DCC schema folder {folder}: not a usable schema set ({reason})"),
            folder=folder, reason=str(exc))) from None


def load_schema(folder: str | Path) -> etree.XMLSchema:
    """The compiled schema of ``folder`` (cached); DccSchemaError naming what is missing."""
    return _schema(str(Path(folder).expanduser().resolve()))


def validate(xml_bytes: bytes, folder: str | Path) -> list[str]:
    """What makes ``xml_bytes`` invalid against the schema set in ``folder``: one text per
    problem, "line L, /dcc:…/dcc:element: the schema's reason" (empty: valid)."""
    schema = load_schema(folder)
    try:
        document = etree.fromstring(xml_bytes, etree.XMLParser(no_network=True,
                                                               resolve_entities=False))
    except etree.XMLSyntaxError as exc:
        return [f"not well-formed XML: {exc}"]
    if schema.validate(document):
        return []
    return [f"line {e.line}, {_prefixed(e.path)}: {e.message}" for e in schema.error_log]


def _prefixed(path: str | None) -> str:
    """lxml's path ("/*[local-name()='x' …]" or "/dcc:x/…") as the prefixed element path."""
    return (path or "/").replace("{https://ptb.de/dcc}", "dcc:").replace(
        "{https://ptb.de/si}", "si:")
