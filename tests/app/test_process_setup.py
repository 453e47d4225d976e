"""The process as the app starts it (#15): one BLAS thread (OpenBLAS's threads spinning
beside the window held the interpreter for 0.3–0.4 s on two cores), and a million-sample
array taken from the heap, not mapped from the kernel for each temporary. Checked in a
fresh interpreter that imports the app's entry point first, as ``anglebench`` does."""

from __future__ import annotations

import subprocess
import sys
import textwrap
from pathlib import Path

import pytest

pytestmark = pytest.mark.slow  # every test here takes more than 0.4 s (a window, a certificate, a program)

ROOT = Path(__file__).resolve().parents[2]


def _run(code: str, env_extra: dict[str, str] | None = None) -> str:
    import os

    env = {k: v for k, v in os.environ.items()
           if k not in ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS", "MKL_NUM_THREADS")}
    env.update(env_extra or {})
    done = subprocess.run([sys.executable, "-c", textwrap.dedent(code)], cwd=ROOT, env=env,
                          capture_output=True, text=True, timeout=60, check=True)
    return done.stdout.strip()


OPENBLAS_THREADS = """
    import ctypes, glob, os, sys
    {first}
    import numpy as np
    libs = glob.glob(os.path.join(os.path.dirname(np.__file__), os.pardir, "numpy.libs",
                                  "libscipy_openblas*.so"))
    if not libs:
        print("no openblas")
        sys.exit()
    print(ctypes.CDLL(libs[0]).scipy_openblas_get_num_threads64_())
"""


def test_the_app_runs_blas_on_one_thread():
    bare = _run(OPENBLAS_THREADS.format(first=""))
    if bare == "no openblas":
        pytest.skip("numpy here is not built on the bundled OpenBLAS")
    assert _run(OPENBLAS_THREADS.format(first="import app.main")) == "1"
    # a choice of the user's is kept
    assert _run(OPENBLAS_THREADS.format(first="import app.main"),
                {"OPENBLAS_NUM_THREADS": "2"}) == "2"


MAPPED_BYTES = """
    import ctypes, sys
    {first}
    import numpy as np

    class MallInfo(ctypes.Structure):
        _fields_ = [(n, ctypes.c_size_t) for n in ("arena", "ordblks", "smblks", "hblks",
                    "hblkhd", "usmblks", "fsmblks", "uordblks", "fordblks", "keepcost")]

    try:
        info = ctypes.CDLL(None).mallinfo2
    except AttributeError:
        print("no mallinfo2")
        sys.exit()
    info.restype = MallInfo
    before = info().hblkhd
    samples = np.ones(1_000_000)
    print(info().hblkhd - before)
"""


def test_a_million_sample_array_comes_from_the_heap():
    bare = _run(MAPPED_BYTES.format(first=""))
    if bare == "no mallinfo2" or not sys.platform.startswith("linux"):
        pytest.skip("not glibc 2.33 or later")
    assert int(bare) >= 8_000_000  # glibc's default: mapped, and faulted in page by page
    assert int(_run(MAPPED_BYTES.format(first="import app.main"))) == 0
