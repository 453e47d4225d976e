"""ILAC-G8:09/2019's decision rules on a value x with its interval [x − U₋, x + U₊] against a
tolerance T, worked out here from the rules' definitions for tests that redo a printed
decision from the printed figures (issue 39): imports nothing from the code it checks."""

from __future__ import annotations


def ilac_verdict(rule: str, x, minus, plus, t, compared=None) -> str:
    """``simple``: the value against T; ``guarded_binary``: pass only where the whole interval
    is within T; ``guarded``: pass, conditional pass, conditional fail or fail by where T
    falls. Where the value alone is compared with T (simple; a conditional pass against a
    conditional fail) it is ``compared`` when the statement prints one (ASTM E29 §6.4), else
    ``x``. Works on Decimals or floats alike."""
    xc = x if compared is None else compared
    if rule == "simple":
        return "pass" if xc <= t else "fail"
    if rule == "guarded_binary":
        return "pass" if x + plus <= t else "fail"
    if x + plus <= t:
        return "pass"
    if xc <= t:
        return "conditional pass"
    if x - minus <= t:
        return "conditional fail"
    return "fail"
