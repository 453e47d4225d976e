"""The Chinese of texts added since the catalogue (resources/translations) was last made, for
the lead's catalogue: until they are in it, the tests that read a Chinese certificate or
results file lay them over it (:func:`pending_catalogue`), as the catalogue will give them."""

from __future__ import annotations

import contextlib
import xml.etree.ElementTree as ET
from collections.abc import Iterator
from pathlib import Path

import pytest

__all__ = ["PENDING_ZH", "pending_catalogue"]

#: English -> Chinese (assessment 78 L1, L2, L5: certificate polish)
PENDING_ZH = {
    # assessment 78 L1: a figure whose interval is withheld, rounded to that interval's place
    "— (withheld; value rounded to {place})": "—（未给出；数值修约到 {place}）",
    "No coverage interval is given for {figure}: {reason}; {figure} is printed rounded to "
    "{place}, the last place of that interval's half-width to two significant digits (GUM "
    "7.2.6): the two runs do not give it more closely.":
        "{figure} 不给出包含区间：{reason}；{figure} 修约到 {place}，即该区间半宽取两位有效数字时"
        "的末位（GUM 7.2.6）：两次测量不能更精确地给出它。",
    # assessment 78 L2: the point where U ≥ T inside the sentence
    "No statement of conformity is possible: the expanded uncertainty U = {u} (at {point}) is "
    "not smaller than the tolerance T = {t}, so no result could be shown to lie within it.":
        "无法作符合性声明：扩展不确定度 U = {u}（在 {point}）不小于允差 T = {t}，任何结果都不能"
        "证明在其范围以内。",
    # assessment 78 L5: a name the user typed, quoted inside a Chinese sentence
    "{typed_name}": "“{typed_name}”",
}


def _clear_caches() -> None:
    from app.writers.certificate_pdf import wording
    from models import messages

    messages.translator.cache_clear()
    wording._say.cache_clear()
    wording._chinese_words.cache_clear()


@contextlib.contextmanager
def pending_catalogue(folder: Path) -> Iterator[None]:
    """The command line's and the certificate's Chinese (models.messages.translator): the
    catalogue with :data:`PENDING_ZH` added where it lacks them, written in ``folder``."""
    from models import messages

    folder.mkdir(parents=True, exist_ok=True)
    source = messages.TRANSLATIONS_DIR / "anglebench_zh_CN.ts"
    tree = ET.parse(source)
    context = tree.getroot().find("context")
    have = messages.catalogue(source)
    for english, chinese in PENDING_ZH.items():
        if english not in have:
            element = ET.SubElement(context, "message")
            ET.SubElement(element, "source").text = english
            ET.SubElement(element, "translation").text = chinese
    tree.write(folder / "anglebench_zh_CN.ts", encoding="utf-8")
    with pytest.MonkeyPatch.context() as patch:
        patch.setattr(messages, "TRANSLATIONS_DIR", folder)
        _clear_caches()
        try:
            yield
        finally:
            patch.undo()
            _clear_caches()
