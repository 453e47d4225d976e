"""A sent origin as a project file keeps it: what the sending workbench's "Readings:" line
was made of, so that it is worded again in any language (day review 67 F3: kept as its
English text, it was printed in English on a Chinese certificate). Files that kept only
the text are read as before; no record, however damaged, ends in an error."""

from __future__ import annotations

import json

from models.certificate.readings_origin import sheet_source
from models.certificate.stored_origin import origin_record, stored_origin
from models.messages import in_language, translator

DIGEST = "6d947a8a7a7fec7974d2fb1bb047961323026e4e0aaad50e6683f46a1515f561"

#: a positioning sheet's origin as a project file holds it: sent from the polygon
#: workbench, whose readings were imported from a file and edited, rows 6–7 pasted and
#: rows 9–10 captured (written here as the file is, not by the code read back)
SENT = {"source": "sent", "workbench": "Polygon encoder test",
        "origin": ("imported from run.csv (SHA-256 " + DIGEST + "), edited in AngleBench; "
                   "rows 6–7 (2 of 50) pasted into AngleBench; rows 9–10 (2 of 50) captured "
                   "from the instruments"),
        "readings": {"origin": {"source": "imported", "name": "run.csv", "sha256": DIGEST,
                                "edited": True, "pasted_rows": [5, 6]},
                     "rows": 50, "captured_rows": [8, 9], "project": "", "unsaved": False,
                     "named": ""},
        "edited": False, "pasted_rows": []}


def _line(record, language: str) -> str:
    opened = stored_origin(json.loads(json.dumps(record)), "p.anglebench.json")
    said = sheet_source(opened.origin, opened.edited, list(opened.pasted), 50)
    assert said is not None
    return in_language(said, translator(language))


def test_a_sent_origin_is_worded_in_the_language_asked():
    english = _line(SENT, "en")
    assert english == ("sent from the Polygon encoder test workbench (its readings: "
                       + SENT["origin"] + ")")
    chinese = _line(SENT, "zh_CN")
    assert "run.csv" in chinese and DIGEST in chinese and "6–7" in chinese \
        and "9–10" in chinese
    for words in ("sent from", "imported from", "edited in", "pasted into", "captured from",
                  "its readings"):
        assert words not in chinese, (words, chinese)


def test_the_record_written_is_the_record_read():
    opened = stored_origin(SENT, "p.anglebench.json")
    again = origin_record(opened.origin, opened.edited, opened.pasted)
    assert again == SENT
    assert stored_origin(again, "p.anglebench.json") == opened


def test_a_file_that_kept_only_the_text_says_it_as_it_is():
    old = {k: v for k, v in SENT.items() if k != "readings"}
    assert _line(old, "en") == _line(SENT, "en")
    assert SENT["origin"] in _line(old, "zh_CN")  # what it holds: the English text
    # a damaged "readings" is the text, never an error
    for readings in ("x", {"origin": "x"}, {**SENT["readings"], "rows": -1},
                     {**SENT["readings"], "captured_rows": ["9"]},
                     {**SENT["readings"], "unsaved": "no"}):
        assert SENT["origin"] in _line({**SENT, "readings": readings}, "zh_CN")


def test_a_sent_origin_nested_too_deep_is_read_without_an_error():
    record: dict = {"source": "typed"}
    for _ in range(5000):
        record = {"source": "sent", "workbench": "Polygon encoder test", "origin": "x",
                  "readings": {"origin": record, "rows": 1}}
    opened = stored_origin(record, "p.anglebench.json")
    assert sheet_source(opened.origin, False, [], 1).startswith("sent from the Polygon")
