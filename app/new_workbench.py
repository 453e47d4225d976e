"""``make new-workbench NAME=key TITLE="…" TITLE_ZH="…"``: a new workbench's starting point.

Writes the two folders (``models/KEY``, ``widgets/KEY``), a sample, its user guide in
English and Chinese (``docs/user-guide/KEY.md``, ``docs/zh_CN/user-guide/KEY.md``, linked from
each language's ``index.md``) and the window's manual pages made from them
(``resources/manual/``, as ``make docs`` makes them), its entry in ``models/registry.py``
and the Chinese of its texts in ``resources/translations/anglebench_zh_CN.ts``. The model
it writes is a working one — the errors of indication of an angle against a reference, its
validation case by simulation in ``models/KEY/validation_cases.py`` — to be replaced by the
workbench's own; its presenter asks the view to draw (``view.show_errors``), tested with an
autospec'd view in ``tests/widgets/KEY/``. What it has then is checked by
``tests/test_workbench_contract.py``, each failure saying what to add where. A key another
workbench, instrument of capture, command or folder of models/ or widgets/ has is refused.
"""

from __future__ import annotations

import argparse
import re
import sys
from html import escape
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]

#: the texts of the written model with their Chinese (added to the .ts when missing)
TEXTS_ZH = {
    "Reference angle, as the standard reads it": "参考角（标准器读数）",
    "Angle the instrument under test indicates": "被检仪器的示值角",
    "Zero": "零点",
    "as read": "按读数",
    "at the first reading": "在第一个读数处",
    "Whether the errors are taken relative to the first reading": "示值误差是否以第一个读数为零点",
    "at least {n} readings are needed, not {got}": "至少需要 {n} 个读数，而不是 {got}",
    "Error of indication {low} … {high} (peak-to-peak {ptp}) over {n} readings":
        "示值误差 {low} … {high}（峰峰值 {ptp}），共 {n} 个读数",
    "Error of indication, peak-to-peak {ptp}": "示值误差峰峰值 {ptp}",
    "Error of indication": "示值误差",
    "error of indication": "示值误差",
    "a known error recovered from simulated readings": "由仿真读数复现已知误差",
}

MODEL = '''"""{title} as a workbench: readings columns, settings, analysis, JSON and summary.

Written by ``make new-workbench`` as a starting point — the errors of indication of an
angle against a reference — to be replaced by the workbench's own model.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field
from typing import Any

import numpy as np

{model_imports}

__all__ = ["{const}"]

COLUMNS = (
    Column("reference_deg", "reference", "deg", ColumnKind.ANGLE_DEG,
           help=QT_TR_NOOP("Reference angle, as the standard reads it")),
    Column("indicated_deg", "indicated", "deg", ColumnKind.ANGLE_DEG,
           help=QT_TR_NOOP("Angle the instrument under test indicates")),
)

PARAMETERS = (
    Parameter("zero", QT_TR_NOOP("Zero"), "choice", "none",
              choices=(("none", QT_TR_NOOP("as read")), ("first", QT_TR_NOOP("at the first reading"))),
              help=QT_TR_NOOP("Whether the errors are taken relative to the first reading")),
)


@dataclass(frozen=True)
class {cls}Result:
    reference_deg: np.ndarray
    error_arcsec: np.ndarray  # indicated − reference
    warnings: list[str] = field(default_factory=list)

    @property
    def peak_to_peak(self) -> float:
        return float(np.ptp(self.error_arcsec))


def analyze(parsed: ParsedReadings, settings: Mapping[str, Any]) -> {cls}Result:
    reference = parsed.values["reference_deg"].astype(float)
    indicated = parsed.values["indicated_deg"].astype(float)
    if reference.size < 2:
        raise ValueError(message(QT_TR_NOOP("at least {{n}} readings are needed, not {{got}}"),
                                 n=2, got=reference.size))
    error = ((indicated - reference + 180.0) % 360.0 - 180.0) * 3600.0
    if settings["zero"] == "first":
        error = error - error[0]
    return {cls}Result(reference, error)


def to_json(result: {cls}Result) -> dict[str, Any]:
    return {{"reference_deg": result.reference_deg.tolist(),
            "error_arcsec": result.error_arcsec.tolist(),
            "peak_to_peak_arcsec": result.peak_to_peak,
            "sign_convention": SIGN_CONVENTION, "warnings": list(result.warnings)}}


def summary(result: {cls}Result) -> str:
    return lines([message(
        QT_TR_NOOP("Error of indication {{low}} … {{high}} (peak-to-peak {{ptp}}) over {{n}} readings"),
        low=f"{{result.error_arcsec.min():+.2f}}\\"", high=f"{{result.error_arcsec.max():+.2f}}\\"",
        ptp=f"{{result.peak_to_peak:.2f}}\\"", n=result.error_arcsec.size)])


def error_figure(result: {cls}Result) -> PlotFigure:
    order = np.argsort(result.reference_deg, kind="stable")
    return PlotFigure(QT_TR_NOOP("Error of indication"), "θ (°)", QT_TR_NOOP("error (\\")"), (
        PlotSeries(QT_TR_NOOP("error of indication"), result.reference_deg[order],
                   result.error_arcsec[order], (31, 119, 180), True, role="corrected"),))


# generic over its result: each base names {cls}Result, and mypy (make lint) checks every
# method below and every call of the shared code against it (models/workbench.py)
class {cls}(
        Workbench[{cls}Result], OverlaysRuns[{cls}Result], ShowsHeadline[{cls}Result]):
    key = KEY
    title = TITLE
    columns = COLUMNS
    parameters = PARAMETERS
    sample_file = "{key}_sample.csv"
    method_reference = "VIM 4.1 (JCGM 200:2012): error of indication = indicated − reference"
    presenter = "widgets.{key}.presenter:{cls}Presenter"
    nominal_column = "reference_deg"
    entry_column = "indicated_deg"
    analyze = staticmethod(analyze)
    to_json = staticmethod(to_json)
    summary = staticmethod(summary)
    overlay_figure = staticmethod(error_figure)

    def verdict(self, result: {cls}Result) -> str:
        return message(QT_TR_NOOP("Error of indication, peak-to-peak {{ptp}}"),
                       ptp=f"{{result.peak_to_peak:.2f}}\\"")

    def headline(self, result: {cls}Result) -> dict[str, float]:
        return {{"peak-to-peak (\\")": result.peak_to_peak}}


{const} = {cls}()
'''

VALIDATION = '''"""The {key} workbench's reference cases for the method validation report (``anglebench
validate``; models.validation.run gathers every workbench's): readings simulated from a known
error, not from the model's formula, through the whole analysis.
"""

from __future__ import annotations

import numpy as np

{validation_imports}

__all__ = ["validation_cases"]


def validation_cases(trials: int) -> list[ValidationCase]:
    """Its reference cases (``trials``: the Monte Carlo runs a budget comparison would make)."""
    # readings made from a known error: 5" + 2" sin θ
    reference = np.linspace(0.0, 350.0, 36)
    truth = 5.0 + 2.0 * np.sin(np.radians(reference))
    rows = [[f"{{r:.6f}}", f"{{r + t / 3600.0:.9f}}"] for r, t in zip(reference, truth, strict=True)]
    kind = {const}
    result = kind.analyze(ReadingsSheet(kind.columns, rows).parse(), kind.default_settings)
    worst = float(np.max(np.abs(result.error_arcsec - truth)))
    return [ValidationCase(kind.title, QT_TR_NOOP("a known error recovered from simulated readings"),
                           EXACT_SIMULATION, "≤ 0.001\\"", f"{{worst:.2g}}\\"", worst <= 0.001)]
'''

PRESENTER_TEST = '''"""The {key} workbench's presenter with an autospec'd view: it decides and asks the view
to draw, reaching into none of the view's widgets (written by make new-workbench)."""

from __future__ import annotations

from unittest import mock

import numpy as np

{test_imports}


def test_the_presenter_asks_its_view_to_draw_the_errors(qtbot):
    view = mock.create_autospec({cls}View, instance=True)  # no widget: only the view's methods
    presenter = {cls}Presenter(view)
    reference = np.arange(0.0, 360.0, 30.0)
    rows = [[f"{{r:.6f}}", f"{{r + (4.0 + r / 100.0) / 3600.0:.9f}}"] for r in reference]
    result = {const}.analyze(ReadingsSheet({const}.columns, rows).parse(), {const}.default_settings)
    presenter.show_result(result)
    (figure,), _ = view.show_errors.call_args
    assert np.allclose(figure.series[0].x, reference)
    shown = figure_in_unit(error_figure(result), presenter.angle_unit)
    assert np.allclose(figure.series[0].y, shown.series[0].y)
    presenter.clear_result()
    view.clear_result.assert_called_once_with()
'''

INIT = '''"""The {key} workbench: {title}.

Its key and title are given once, here: the analysis, the window and the registry use them.
"""

from models.messages import QT_TR_NOOP

KEY = "{key}"
TITLE = QT_TR_NOOP("{title}")
'''

VIEW = '''"""The {key} workbench's view: the shared readings and set-up, and its error curve."""

from __future__ import annotations

from models.{key} import TITLE
from widgets.error_plot import ErrorPlot
from widgets.i18n import tr
from widgets.workbench_view import WorkbenchView


class {cls}View(WorkbenchView):
    def __init__(self, parent=None) -> None:
        super().__init__(TITLE, parent)
        self.error_plot = ErrorPlot()
        self.add_plot_tab(self.error_plot, tr("Error curves"))

    def show_errors(self, figure) -> None:
        """Draws the error curves (a models.plots.PlotFigure, in the chosen unit)."""
        self.error_plot.show_figure(figure)

    def clear_result(self) -> None:
        self.error_plot.clear()
'''

PRESENTER = '''"""The {key} workbench's presenter (no widgets: it asks its view to draw)."""

from __future__ import annotations

{presenter_imports}


class {cls}Presenter(WorkbenchPresenter):
    view_class = {cls}View

    def __init__(self, view: {cls}View | None = None, parent=None) -> None:
        super().__init__({const}, view, parent)

    def show_result(self, result) -> None:
        self.view.show_errors(*self.in_unit(error_figure(result)))

    def clear_result(self) -> None:
        self.view.clear_result()
'''

SAMPLE = "reference_deg,indicated_deg\n" + "".join(
    f"{r},{r + (4.0 + 3.0 * ((r // 30) % 3 - 1)) / 3600.0:.6f}\n" for r in range(0, 360, 30))

#: the user guide it writes in docs/user-guide/ (the window's manual is made from it), and
#: its Chinese in docs/zh_CN/user-guide/: the same sections, items and figures
GUIDE = {"en": '''# {title}

*User guide of the {title} workbench (key `{key}`); the window's manual (F1) shows this page.*
Entry, keys, plots, files and autosave, common to every workbench, are in
[Working with the window](window.md); certificates in
[Certificates and the register](../certificates-and-register.md); every option in
[the command-line reference](../command-line.md).

## What you measure

The error of indication of an angle against a reference. Readings: `reference_deg`, the
reference angle as the standard reads it, and `indicated_deg`, the angle the instrument
under test indicates, in degrees; the error of indication is indicated − reference.
*(Written by `make new-workbench`: say what this workbench measures.)*

## Setting up

*(How the instrument and the standard are set up, and what to watch.)*

## Settings

* **Zero** — Whether the errors are taken relative to the first reading: *as read*, or *at the first reading*.

## Plots

* **Error curves** — The error of indication over the reference angle.

## Result

The verdict gives the peak-to-peak of the error of indication.

## How it works

*(The model, how it was checked and what it refuses.)*
''', "zh_CN": '''# {title_zh}

*{title_zh}工作台（键 `{key}`）的用户指南；窗口的手册（F1）显示的就是本页。*
各工作台通用的录入、按键、图、文件和自动保存见[窗口的使用](window.md)；证书见
[证书与证书登记册](../certificates-and-register.md)；每个选项见
[命令行参考](../../command-line.md)（英文）。

## 测量什么

角度相对参考值的示值误差。读数：`reference_deg`，即标准器读得的参考角，以及 `indicated_deg`，即被检仪器的
示值角，单位为度；示值误差 = 示值 − 参考值。
*（由 `make new-workbench` 写出：请说明本工作台测量什么。）*

## 安装

*（仪器和标准器如何安装，以及需要注意什么。）*

## 设置

* **零点** — 示值误差是否以第一个读数为零点：*按读数*，或*在第一个读数处*。

## 图

* **误差曲线** — 示值误差随参考角的变化。

## 结果

结论给出示值误差的峰峰值。

## 工作原理

*（模型、其验证方式以及它拒绝什么。）*
'''}

#: its line in the user guide's contents (docs/…/user-guide/index.md)
INDEX_LINE = {"en": "* [{title}]({key}.md) — the error of indication of an angle against a reference",
              "zh_CN": "* [{title_zh}]({key}.md) — 角度相对参考值的示值误差"}


def _imports(*lines: str) -> str:
    """Import lines in the order ruff's isort keeps them (by module)."""
    return "\n".join(sorted(lines, key=lambda line: line.split()[1]))


def _class_name(key: str) -> str:
    return "".join(part.capitalize() for part in key.split("_"))


def _write(path: Path, text: str) -> None:
    if path.exists():
        raise SystemExit(f"new-workbench: {path.relative_to(ROOT)} exists already")
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(text, "utf-8")


def _register(key: str, const: str) -> None:
    """The workbench's entry in models/registry.py: its key and where its object is."""
    path = ROOT / "models" / "registry.py"
    text = path.read_text("utf-8")
    text = text.replace("\n}\n", f'\n    "{key}": "models.{key}.analysis:{const}",\n}}\n', 1)
    path.write_text(text, "utf-8")


def _contract(key: str) -> None:
    """The workbench in pyproject.toml's import contracts: its models and widgets packages
    independent of the other workbenches', its models package in the workbenches' layer."""
    path = ROOT / "pyproject.toml"
    text = path.read_text("utf-8")
    for top, what in (("models", "models"), ("widgets", "views")):
        name = f"name = \"the workbenches' {what} are independent"
        start = text.index("modules = [", text.index(name))
        end = text.index("]", start)
        text = text[:end] + f', "{top}.{key}"' + text[end:]
    layer = re.search(r'"theodolite \| [^"]*"', text)
    if layer is None:
        raise SystemExit("new-workbench: pyproject.toml has no workbenches' layer to add it to")
    text = text[:layer.end() - 1] + f" | {key}" + text[layer.end() - 1:]
    path.write_text(text, "utf-8")


def _link_guide(key: str, title: str, title_zh: str) -> None:
    """The user guide's line in each language's contents (index.md), after the last
    workbench's; the manual's pages (index and the workbench's) are then made from them."""
    from app import manual_pages

    for language, folder in manual_pages.GUIDES.items():
        path = ROOT / folder / "index.md"
        text = path.read_text("utf-8")
        head = text.split("\n## ", 1)[0]
        lines = re.findall(r"^\* \[[^\]]+\]\(\w+\.md\).*$", head, flags=re.MULTILINE)
        if not lines:
            raise SystemExit(f"new-workbench: {folder}/index.md lists no workbench to add it after")
        at = text.index(lines[-1]) + len(lines[-1])
        line = INDEX_LINE[language].format(key=key, title=title, title_zh=title_zh)
        path.write_text(text[:at] + "\n" + line + text[at:], "utf-8")


def _translate(texts: dict[str, str]) -> None:
    """Each text's Chinese in the .ts (a text it has already keeps its translation)."""
    path = ROOT / "resources" / "translations" / "anglebench_zh_CN.ts"
    text = path.read_text("utf-8")
    entries = "".join(
        f"    <message>\n        <source>{escape(en, quote=False)}</source>\n"
        f"        <translation>{escape(zh, quote=False)}</translation>\n    </message>\n"
        for en, zh in texts.items() if f"<source>{escape(en, quote=False)}</source>" not in text)
    at = text.index("</context>")
    path.write_text(text[:at] + entries + text[at:], "utf-8")


def taken_names() -> dict[str, str]:
    """The names a new workbench's key may not take, each with what already has it: the
    workbenches (models/registry.py), the instruments of capture (app/capture/instruments.py,
    whose folder the architecture test exempts), the commands without a window (app/main.py)
    and the folders of models/ and widgets/."""
    from app.capture.instruments import INSTRUMENTS
    from app.main import COMMANDS
    from models.registry import LOCATIONS

    names = {path.name.removesuffix(".py"): f"a module of {top}/ ({top}/{path.name})"
             for top in ("models", "widgets") for path in sorted((ROOT / top).iterdir())
             if (path.is_dir() and (path / "__init__.py").exists()) or path.suffix == ".py"}
    names.update({name: "a command (anglebench " + name + ")" for name in COMMANDS})
    names.update({name: "an instrument of capture (app/capture/instruments.py)" for name in INSTRUMENTS})
    names.update({name: "a workbench (models/registry.py)" for name in LOCATIONS})
    return names


def new_workbench(key: str, title: str, title_zh: str) -> list[Path]:
    """Writes the workbench ``key``; the files written (registry, import contracts, index and
    .ts edited)."""
    if not re.fullmatch(r"[a-z][a-z0-9_]*", key):
        raise SystemExit("new-workbench: NAME is lower-case letters, digits and _ (a Python name)")
    clash = taken_names().get(key)
    if clash is not None:
        raise SystemExit(f"new-workbench: {key!r} is taken: it is {clash}; choose another NAME "
                         "(nothing was written)")
    names = {"key": key, "title": title, "cls": _class_name(key), "const": key.upper()}
    names["model_imports"] = _imports(
        f"from models.{key} import KEY, TITLE", "from models.messages import QT_TR_NOOP, lines, message",
        "from models.parameters import Parameter", "from models.plots import PlotFigure, PlotSeries",
        "from models.readings.sheet import Column, ColumnKind, ParsedReadings",
        "from models.workbench import SIGN_CONVENTION, OverlaysRuns, ShowsHeadline, Workbench")
    names["presenter_imports"] = _imports(
        f"from models.{key}.analysis import {names['const']}, error_figure",
        f"from widgets.{key}.view import {names['cls']}View",
        "from widgets.workbench_presenter import WorkbenchPresenter")
    names["validation_imports"] = _imports(
        f"from models.{key}.analysis import {names['const']}", "from models.messages import QT_TR_NOOP",
        "from models.readings.sheet import ReadingsSheet",
        "from models.validation.cases import EXACT_SIMULATION, ValidationCase")
    names["test_imports"] = _imports(
        f"from models.{key}.analysis import {names['const']}, error_figure",
        "from models.display_units import figure_in_unit",
        "from models.readings.sheet import ReadingsSheet",
        f"from widgets.{key}.presenter import {names['cls']}Presenter",
        f"from widgets.{key}.view import {names['cls']}View")
    written = {
        ROOT / "models" / key / "__init__.py": INIT.format(**names),
        ROOT / "models" / key / "analysis.py": MODEL.format(**names),
        ROOT / "models" / key / "validation_cases.py": VALIDATION.format(**names),
        ROOT / "widgets" / key / "__init__.py": f'"""The {key} workbench\'s window part."""\n',
        ROOT / "widgets" / key / "view.py": VIEW.format(**names),
        ROOT / "widgets" / key / "presenter.py": PRESENTER.format(**names),
        ROOT / "tests" / "widgets" / key / "__init__.py": "",
        ROOT / "tests" / "widgets" / key / f"test_{key}_presenter.py": PRESENTER_TEST.format(**names),
        ROOT / "resources" / "samples" / f"{key}_sample.csv": SAMPLE,
        ROOT / "docs" / "user-guide" / f"{key}.md": GUIDE["en"].format(key=key, title=title),
        ROOT / "docs" / "zh_CN" / "user-guide" / f"{key}.md": GUIDE["zh_CN"].format(
            key=key, title_zh=title_zh),
    }
    for path, text in written.items():
        _write(path, text)
    _register(key, names["const"])
    _contract(key)
    _link_guide(key, title, title_zh)
    _translate({title: title_zh, **TEXTS_ZH})
    return list(written) + _manual_pages(key)


def _manual_pages(key: str) -> list[Path]:
    """The window's manual pages of the new guide and of the contents, made from docs/ as
    ``make docs`` makes them (app/manual_pages.py)."""
    from app import manual_pages

    (ROOT / manual_pages.MANUAL).mkdir(parents=True, exist_ok=True)
    sources = {folder / name for folder in manual_pages.GUIDES.values()
               for name in (f"{key}.md", "index.md")}
    return [ROOT / path for path in manual_pages.write(ROOT, only=sources)]


def main(argv: list[str] | None = None) -> int:
    p = argparse.ArgumentParser(prog="make new-workbench", description=__doc__.splitlines()[0])
    p.add_argument("name", help="the workbench's key: lower-case letters, digits and _")
    p.add_argument("--title", required=True, help="its title in English")
    p.add_argument("--title-zh", required=True, help="its title in Chinese")
    args = p.parse_args(argv)
    for path in new_workbench(args.name, args.title, args.title_zh):
        sys.stdout.write(f"wrote {path.relative_to(ROOT)}\n")
    sys.stdout.write("edited models/registry.py, pyproject.toml's import contracts, "
                     "docs/user-guide/index.md, docs/zh_CN/user-guide/index.md and "
                     "resources/translations/anglebench_zh_CN.ts\n"
                     f"next: QT_QPA_PLATFORM=offscreen .venv/bin/python -m pytest "
                     f"tests/test_workbench_contract.py -k {args.name}\n"
                     "then (docs/developer-guide.md, Adding a workbench): replace the model, "
                     "test first; a certificate needs resources/samples/"
                     f"certificate_{args.name}.json; after adding texts `make translations` "
                     "lists those without Chinese, `.venv/bin/python -m app.translations "
                     "--fill FILE.json` fills them in; `make docs`; `make lint`\n")
    return 0


if __name__ == "__main__":
    sys.exit(main())
