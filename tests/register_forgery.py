"""What a forger with write access to the register's database recomputes, worked out here
from the chain's documentation (docs/certificates-and-register.md: each record's chain value
is the SHA-256 of the previous one, a newline and the record's chained fields as sorted,
compact JSON), and a stand-in PDF that carries what a certificate's keywords carry: imports
nothing from the register it attacks."""

from __future__ import annotations

import hashlib
import json

#: the fields of a record of chain format 4 and later, as the chain's documentation lists them
CHAINED = ("number", "issued_at", "issue_date", "calibration_date", "workbench",
           "item_description", "item_manufacturer", "item_serial", "customer", "operator",
           "workstation", "supersedes", "revision", "change_note", "project_json",
           "software_json", "headline_json", "pdf_sha256", "seq", "counter", "counter_value",
           "os_user", "approver", "dcc_sha256", "document_kind")
#: what a record of chain format 7 (schema version 8) adds: the identity of its readings
CHAINED_V7 = ("readings_key",)
#: what a record of chain format 8 (schema version 9) adds: its readings by their physical values
CHAINED_V8 = ("readings_layout", "readings_anchor", "readings_reach")


def relinked(previous: str, row: dict) -> str:
    """The chain value of ``row`` (a certificates row as a dict) after the chain value
    ``previous``: what a forger writes after changing the row."""
    keys = CHAINED + (CHAINED_V7 if (row["chain_format"] or 1) >= 7 else ()) + (
        CHAINED_V8 if (row["chain_format"] or 1) >= 8 else ())
    fields = {k: row[k] for k in keys} | {"chain_format": row["chain_format"]}
    body = json.dumps(fields, sort_keys=True, ensure_ascii=False, separators=(",", ":"))
    return hashlib.sha256(f"{previous}\n{body}".encode()).hexdigest()


def stand_in_pdf(meta, head: str = "", content: str = "", proof: str = "") -> bytes:
    """A stand-in certificate PDF: its title (the number) and the keywords the register
    gives it to carry (the head before it, its record's content digest and, with the lab's
    key, its proof of issue)."""
    carried = f" anglebench-register-proof:{proof}" if proof else ""
    return (f"%PDF-1.4 /Title (Calibration certificate {meta.certificate_number}) /Keywords "
            f"(anglebench-register-head-before:{head} anglebench-record-content:{content}"
            f"{carried})").encode()
