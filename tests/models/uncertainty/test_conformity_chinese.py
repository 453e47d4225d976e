"""The statement of conformity in Chinese joins its parts in Chinese punctuation (assessor,
item 14): full-width "；" and "，" between Chinese parts, no space after "。" before the next
sentence; the English text and every figure as they were."""

from __future__ import annotations

import math
import re

import numpy as np

from models.messages import in_language, message, translator
from models.uncertainty.budget import BudgetComponent, UncertaintyBudget
from models.uncertainty.conformity import decide_conformity

ZH = translator("zh_CN")
P = 0.9544997361036416
#: an ASCII separator beside a Chinese character or a full-width bracket
ASCII_BESIDE_CHINESE = re.compile(r"[\u4e00-\u9fff（）][;,]|[;,] ?[\u4e00-\u9fff（]")


def _budget(u: float, n: int) -> UncertaintyBudget:
    return UncertaintyBudget((BudgetComponent("noise", "B", "normal", u, 1.0, 1.0, math.inf),),
                             n, P)


def _curve() -> np.ndarray:
    return 0.8 * np.sin(np.linspace(0.0, 2.0 * np.pi, 24, endpoint=False))


def test_separated_reads_as_before_in_english_and_full_width_in_chinese():
    from models.messages import JOINS, separated

    parts = [message("Item resolution"), message("Reading error (pointing)"), "0.5\""]
    assert separated(parts, "; ") == "Item resolution; Reading error (pointing); 0.5\""
    assert separated(parts, ", ") == "Item resolution, Reading error (pointing), 0.5\""
    assert separated(["", parts[0], ""]) == "Item resolution"  # one part: as it is
    assert separated([]) == ""
    assert in_language(separated(parts, "; "), ZH) == "被校对象分辨力；读数误差（瞄准）；0.5\""
    assert in_language(separated(parts, ", "), ZH) == "被校对象分辨力，读数误差（瞄准），0.5\""
    assert {ZH(template) for template in JOINS.values()} == {
        "{first}；{second}", "{first}，{second}", "{first}{second}"}


def test_a_list_of_names_takes_the_enumeration_comma_in_chinese():
    """Names listed (the inputs U leaves out, a draft's missing fields) are items of one
    list: "、" between them in Chinese, not the clause comma "，"; English as before."""
    from models.messages import listed

    parts = [message("Item resolution"), message("Reading error (pointing)"), "0.5\""]
    assert listed(parts) == "Item resolution, Reading error (pointing), 0.5\""
    assert in_language(listed(parts), ZH) == "被校对象分辨力、读数误差（瞄准）、0.5\""
    assert listed(["", parts[0], None]) == "Item resolution" and listed([]) == ""
    assert in_language(listed([parts[0]]), ZH) == "被校对象分辨力"


def test_the_chinese_statement_and_decided_quantity_join_in_chinese_punctuation():
    """Fails on the old code: the decided quantity read "随机种子 …; 该区间在验证中…" and
    the risk sentence followed "（合格）。 " after an ASCII space."""
    c = decide_conformity(_curve(), _budget(0.05, 24), 3.0, "guarded", "half_range")
    assert c.verdict == "pass"
    quantity, statement = in_language(c.quantity, ZH), in_language(c.statement, ZH)
    assert "；" in quantity and not ASCII_BESIDE_CHINESE.search(quantity), quantity
    assert "。 " not in statement and "（合格）。本判定的误合格概率" in statement, statement
    # the English as it was: the same parts, the same separators, the same figures
    assert "; the interval's coverage achieved in validation" in c.quantity
    assert "(pass). Probability of a false acceptance" in c.statement
    figures = re.compile(r"\d+\.\d+\"")
    assert figures.findall(statement) == figures.findall(str(c.statement))


def test_the_reasons_for_no_statement_are_listed_in_chinese_punctuation():
    """The inputs not stated (a list) and the reasons withheld ("; ") of a Chinese
    certificate: "、" and "；" (old: "被校对象分辨力, 读数误差（瞄准）", then "，")."""
    c = decide_conformity(_curve(), _budget(0.05, 24), 3.0, "guarded", "points",
                          invalid_reason=message("corrected error"),
                          not_stated=("Item resolution", "Reading error (pointing)"))
    assert c.verdict == "not assessed"
    reason = in_language(c.reason, ZH)
    assert reason == "修正后误差；U 不完整：以下输入量未给出，未计入 U：被校对象分辨力、读数误差（瞄准）"
    assert not ASCII_BESIDE_CHINESE.search(in_language(c.statement, ZH))
    assert c.reason == ("corrected error; U is incomplete: inputs not stated, so not in U: "
                        "Item resolution, Reading error (pointing)")


def test_no_space_between_chinese_runs_where_a_point_is_named():
    """The deciding point named in Chinese follows the Chinese words without a space
    (assessment 76 L3: "起决定作用的点为 目标位置 90°"); a point named in Latin letters
    (the theodolite's θ) keeps the space that sets it off, and the English is as it was."""
    e = np.array([0.5, -1.0, 2.6, 0.2])
    budget = _budget(0.25, e.size)
    names = [message("target {target} ({arrow})", target=f"{t}°", arrow="↑")
             for t in (0, 30, 60, 90)]
    c = decide_conformity(e, budget, 3.0, "guarded", "points", point_names=names)
    assert "the deciding point is target 60° (↑): |e|" in c.statement
    statement = in_language(c.statement, ZH)
    assert "起决定作用的点为目标位置 60°（↑）：" in statement, statement
    assert not re.search(r"[\u4e00-\u9fff] [\u4e00-\u9fff]", statement), statement
    theta = ["θ = 0.0000°", "θ = 30.0000°", "θ = 60.0000°", "θ = 90.0000°"]
    c = decide_conformity(e, budget, 3.0, "guarded", "points", point_names=theta)
    assert "起决定作用的点为 θ = 60.0000°：" in in_language(c.statement, ZH)
    # U ≥ T at a point: "U = … (at {point}) is not smaller", in Chinese "（在 {point}）"
    # (assessment 78 L2)
    c = decide_conformity(e, _budget(2.0, e.size), 3.0, "guarded", "points", point_names=names)
    assert c.verdict == "not assessed" and "(at target" in c.statement
    zh = in_language(c.statement, translator("zh_CN"))
    assert "（在目标位置 " in zh, zh


def test_a_template_space_goes_only_between_its_chinese_and_a_chinese_figure():
    from models.messages import rendered

    words = {"为 {x}。": "为 {x}。", "{a} {b}": "{a} {b}", "第 {n} 点，{x} 的": "第 {n} 点，{x} 的"}
    say = words.__getitem__
    assert rendered(message("为 {x}。", x="目标"), say) == "为目标。"
    assert rendered(message("为 {x}。", x="θ = 1°"), say) == "为 θ = 1°。"
    assert rendered(message("{a} {b}", a="甲", b="乙"), say) == "甲 乙"  # two figures: as typed
    assert rendered(message("第 {n} 点，{x} 的", n=3, x="边"), say) == "第 3 点，边的"
    assert message("for {x} the", x="目标") == "for 目标 the"  # English: never touched


def test_no_space_between_a_quoted_name_and_the_chinese_beside_it():
    """A typed name quoted in Chinese (“Data acquisition (16-bit ADC)”, assessment 78 L5) is
    set as Chinese text sets its quotes, with no space beside them: the fringe DCC read
    "“Data acquisition (16-bit ADC)” 未给出不确定度"."""
    from models.messages import rendered

    words = {"{name} 未给出不确定度": "{name} 未给出不确定度", "未说明 {name} 的": "未说明 {name} 的"}
    say = words.__getitem__
    assert rendered(message("{name} 未给出不确定度", name="“ADC 16”"), say) == "“ADC 16”未给出不确定度"
    assert rendered(message("未说明 {name} 的", name="“ADC 16”"), say) == "未说明“ADC 16”的"
    # unquoted Latin keeps its space, as before
    assert rendered(message("{name} 未给出不确定度", name="ADC 16"), say) == "ADC 16 未给出不确定度"
