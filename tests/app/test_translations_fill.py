"""The public way to add Chinese (app.translations.fill_unfinished) and the list of texts
without it (unfinished), on a .ts of their own."""

from __future__ import annotations

from app.translations import fill_unfinished, unfinished

TS = """<TS><context><name>x</name>
    <message>
        <source>done</source>
        <translation>完成</translation>
    </message>
    <message>
        <source>the table&apos;s zero</source>
        <extracomment>a translator's note</extracomment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>error (&quot;)</source>
        <translation type="unfinished"></translation>
    </message>
</context></TS>
"""


def test_unfinished_texts_are_listed_and_filled(tmp_path):
    ts = tmp_path / "x.ts"
    ts.write_text(TS, "utf-8")
    assert unfinished(ts) == ["the table's zero", 'error (")']
    missing = fill_unfinished({"the table's zero": "转台的零位", "not there": "无"}, ts)
    assert missing == ["not there"]
    assert unfinished(ts) == ['error (")']
    text = ts.read_text("utf-8")
    assert ("<extracomment>a translator's note</extracomment>\n"
            "        <translation>转台的零位</translation>") in text
    assert "<translation>完成</translation>" in text
