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

#: English -> Chinese (assessment 78 H1: a fringe standard of no role is not the phase reference)
PENDING_ZH = {
    "the standards that carry the measurand are {roles}, each to be listed with a calibration "
    "certificate and a stated uncertainty; {count} listed so ({listed}): none is listed for "
    "{missing}, as no role is stated for {unnamed} and only a standard whose role says so is "
    "taken as {missing} (one with no role may be another instrument's, such as the ADC's): "
    "state the role {role} of the one that is":
        "承载被测量的计量标准为{roles}，每一项都须列出其校准证书及给定的不确定度；如此列出的有 "
        "{count} 项（{listed}）：未列出{missing}：未说明{unnamed}的角色，只有角色注明为{missing}的"
        "计量标准才作为{missing}（未注明角色的可能是其他仪器的标准，例如 ADC 的）：请为该项注明角色 "
        "{role}",
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
