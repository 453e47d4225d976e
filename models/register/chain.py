"""The register's hash chain (ISO/IEC 17025 7.11.3: changes to records are detectable).

Each record's ``chain_sha256`` is the SHA-256 of the previous record's (in the order of
issue) and of the record's own fields as issued — the PDF's SHA-256 among them. A record,
or a PDF and its hash, changed in the database afterwards no longer gives the stored
chain; neither does a record deleted or inserted before the last. What changes lawfully
after issue — the status and ``superseded_by`` when an amendment or replacement is issued —
is outside the chain and checked against the record that supersedes it, which is in it.

Anyone with write access can recompute the whole chain: the chain's head (``anglebench
register verify`` prints it), noted outside the database from time to time, anchors it.
"""

from __future__ import annotations

import hashlib
import json
from collections.abc import Mapping
from typing import Any

__all__ = ["CHAINED", "GENESIS", "link"]

#: a record's fields as issued, in the chain (status and superseded_by change later)
CHAINED = ("number", "issued_at", "issue_date", "calibration_date", "workbench",
           "item_description", "item_manufacturer", "item_serial", "customer", "operator",
           "workstation", "supersedes", "revision", "change_note", "project_json",
           "software_json", "headline_json", "pdf_sha256")
GENESIS = "0" * 64


def link(previous: str, record: Mapping[str, Any]) -> str:
    """The chain after ``record``, given the chain before it."""
    body = json.dumps({k: record[k] for k in CHAINED}, sort_keys=True, ensure_ascii=False,
                      separators=(",", ":"))
    return hashlib.sha256(f"{previous}\n{body}".encode()).hexdigest()
