"""``ancf.common.threads``: a process started with one BLAS thread in its environment
skips the threadpoolctl scan (about 1.2 ms per run, half the 8-element cantilever's
2.5 ms); one started without it, or with the variables set only after exec, does not."""
from __future__ import annotations

import os
import subprocess
import sys

from ancf.common.threads import BLAS_ENV

PROBE = ("import os; from ancf.common import threads as t; {before}"
         "print(t.started_pinned())")


def _probe(env: dict, before: str = "") -> str:
    clean = {k: v for k, v in os.environ.items() if k not in BLAS_ENV}
    out = subprocess.run([sys.executable, "-c", PROBE.format(before=before)],
                         env={**clean, **env}, capture_output=True, text=True, check=True)
    return out.stdout.strip()


def test_started_with_one_thread_is_pinned():
    assert _probe(BLAS_ENV) == "True"


def test_any_variable_missing_or_other_than_one_is_not():
    assert _probe({}) == "False"
    assert _probe({**BLAS_ENV, "OMP_NUM_THREADS": "2"}) == "False"
    assert _probe({k: v for k, v in BLAS_ENV.items() if k != "MKL_NUM_THREADS"}) == "False"


def test_variables_set_after_exec_do_not_count():
    assert _probe({}, before=f"os.environ.update({BLAS_ENV!r}); ") == "False"


def test_the_suite_runs_with_one_blas_thread():
    """tests/conftest.py sets :data:`BLAS_ENV` before numpy loads in the test processes
    (xdist's workers start with it): every BLAS this process loaded has one thread."""
    import numpy as np
    from threadpoolctl import threadpool_info
    np.linalg.inv(np.eye(3))
    blas = [p for p in threadpool_info() if p["user_api"] == "blas"]
    assert blas and all(p["num_threads"] == 1 for p in blas), blas
