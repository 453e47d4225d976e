"""The LM polish reaches the same minimum as MINPACK's, and spares the CLI scipy.optimize."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest
from hypothesis import example, given, settings
from hypothesis import strategies as st
from scipy.optimize import least_squares

from models.damped_least_squares import difference_jacobian, polish

ROOT = Path(__file__).resolve().parents[2]


def _damped_sine(x, t):
    """Amplitude, decay and phase of a damped sine: a small nonlinear fit."""
    return x[0] * np.exp(-x[1] * t) * np.sin(3.0 * t + x[2])


def _damped_sine_jacobian(x, t):
    """Its exact Jacobian (the test's own, not the module's finite differences)."""
    e = np.exp(-x[1] * t)
    return np.column_stack([e * np.sin(3.0 * t + x[2]), -t * x[0] * e * np.sin(3.0 * t + x[2]),
                            x[0] * e * np.cos(3.0 * t + x[2])])


def _gauss_newton_step(fun, x, t):
    """The step that remains from x to the minimum (exact Jacobian, least squares)."""
    return np.linalg.lstsq(_damped_sine_jacobian(x, t), -fun(x), rcond=None)[0]


@pytest.mark.slow
@settings(max_examples=60, deadline=None)
@given(amp=st.floats(0.5, 5.0), decay=st.floats(0.0, 2.0), phase=st.floats(-1.5, 1.5),
       seed=st.integers(0, 2**31 - 1))
@example(amp=0.5, decay=0.0, phase=-1.1099152539844552, seed=4546692)  # a parameter at zero
@example(amp=0.5, decay=1.8698970747764965, phase=0.0, seed=1194333)  # a phase near zero
@example(amp=4.55, decay=0.0, phase=0.4, seed=69)  # MINPACK stops on xtol 1.3e-6 σ short
def test_polish_reaches_minpack_minimum_from_a_near_start(amp, decay, phase, seed):
    rng = np.random.default_rng(seed)
    t = np.linspace(0.0, 3.0, 40)
    y = _damped_sine([amp, decay, phase], t) + rng.normal(0, 0.01, t.size)

    def fun(x):
        return _damped_sine(x, t) - y

    start = np.array([amp, decay, phase]) * (1 + rng.uniform(-0.05, 0.05, 3))
    ours = polish(fun, lambda x: difference_jacobian(fun, x, central=True), start)
    ref = least_squares(fun, start, method="lm", xtol=1e-15, ftol=1e-15, gtol=1e-15)
    assert ours.converged
    cost, ref_cost = float(ours.fun @ ours.fun), float(ref.fun @ ref.fun)
    assert cost <= ref_cost * (1 + 1e-9) + 1e-300
    # the same minimum: each parameter within a millionth of its standard uncertainty of
    # the minimum. MINPACK may stop on its x tolerance a step short on a flat minimum
    # (amp 4.55, decay 0, seed 69: a Gauss–Newton step of 1.3e-6 σ remained, its gradient
    # 1.5e-7 against ours 2e-11), so the minimum is MINPACK's point plus the Gauss–Newton
    # step left from it (exact Jacobian); a fixed atol of 1e-9 failed for a phase near
    # zero, 9.8e-5 ± 4e-3 (numerical noise, not another minimum)
    jac = _damped_sine_jacobian(ref.x, t)
    sigma = np.sqrt(np.diag(np.linalg.inv(jac.T @ jac)) * ref_cost / (t.size - 3))
    minimum = ref.x + _gauss_newton_step(fun, ref.x, t)
    assert np.all(np.abs(ours.x - minimum) <= 1e-6 * sigma + 1e-12), (ours.x - minimum, sigma)
    # and ours is itself at it: no step of a millionth of σ left
    assert np.all(np.abs(_gauss_newton_step(fun, ours.x, t)) <= 1e-6 * sigma + 1e-12)


def test_difference_jacobian_of_a_known_function():
    def fun(x):
        return np.array([x[0] ** 2 * x[1], np.sin(x[1])])

    x = np.array([1.5, 0.3])
    exact = np.array([[2 * 1.5 * 0.3, 1.5**2], [0.0, np.cos(0.3)]])
    assert np.allclose(difference_jacobian(fun, x, central=True), exact, rtol=1e-9, atol=1e-10)
    forward = difference_jacobian(fun, x)
    assert np.allclose(forward, exact, rtol=1e-6, atol=1e-7)
    assert not np.allclose(forward, exact, rtol=1e-12, atol=1e-13)  # it is a difference


def test_polish_says_when_it_did_not_converge():
    def fun(x):  # no minimum: the cost falls for ever as x grows
        return np.array([np.exp(-x[0])])

    out = polish(fun, lambda x: difference_jacobian(fun, x), np.array([0.0]), max_iterations=5)
    assert not out.converged


@pytest.mark.slow
def test_small_runs_do_not_import_scipy_optimize():
    """`analyze` on the theodolite and polygon samples stays clear of scipy.optimize (~0.3 s)."""
    code = (
        "import sys, io, contextlib\n"
        "from app.main import main\n"
        "for kind in ('theodolite', 'polygon'):\n"
        "    sys.argv = ['anglebench', 'analyze', kind, f'resources/samples/{kind}_sample.csv']\n"
        "    with contextlib.redirect_stdout(io.StringIO()):\n"
        "        try:\n"
        "            main()\n"
        "        except SystemExit as stop:\n"
        "            assert not stop.code, stop.code\n"
        "print('scipy.optimize' in sys.modules)\n"
    )
    out = subprocess.run([sys.executable, "-c", code], cwd=ROOT, capture_output=True, text=True,
                         timeout=120, env={"QT_QPA_PLATFORM": "offscreen", "PATH": "/usr/bin:/bin"})
    assert out.returncode == 0, out.stderr
    assert out.stdout.strip() == "False"
