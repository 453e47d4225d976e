"""A theodolite record through the command line, as a user runs it: its JSON, with the
theodolite stated at u per reading and any other certificate details."""

from __future__ import annotations

import json

from app.main import main


def run_json(capsys, tmp_path, record, stated: float, per: str = "reading",
             **details) -> dict:
    """``anglebench analyze theodolite RECORD --json --metadata M``, M the ``details`` with
    the theodolite stated at ``stated`` (arcsec, u) for each ``per`` (the standards table's
    *Per*: "reading", or "angle" between two readings)."""
    meta = tmp_path / "meta.json"
    meta.write_text(json.dumps({**details, "standards": [{
        "description": "Autocollimating theodolite", "certificate_no": "C-7", "uncertainty": stated,
        "uncertainty_unit": "arcsec", "basis": "u", "applies_to": per}]}))
    code = main(["analyze", "theodolite", str(record), "--json", "--metadata", str(meta),
                 "--language", "en"])
    out = capsys.readouterr()
    assert code == 0, out.err
    return json.loads(out.out)


def passes_summary(capsys, tmp_path, passes: int, seed: int) -> str:
    """``anglebench analyze theodolite RECORD --language en``'s summary, RECORD 13 θ of
    ``passes`` passes each way with a circle error varying along the range and 0.3″ of
    pointing noise (tests/repeatability_rig.theodolite_passes_csv, drawn from ``seed``)."""
    import numpy as np

    from tests.repeatability_rig import theodolite_passes_csv

    text, _ = theodolite_passes_csv("varying", 13, passes, 0.3, np.random.default_rng(seed))
    csv = tmp_path / f"passes{passes}.csv"
    csv.write_text(text, encoding="utf-8")
    assert main(["analyze", "theodolite", str(csv), "--language", "en"]) == 0
    return capsys.readouterr().out
