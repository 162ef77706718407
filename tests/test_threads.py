"""The report generator and sweep workers run with one BLAS thread (`ancf.threads`), so
their numbers agree with each other and do not depend on the machine's core count."""
import os
import subprocess
import sys

from ancf.sweep import _ENV
from ancf.threads import BLAS_ENV


def test_report_generator_pins_one_blas_thread_before_numpy():
    env = {k: v for k, v in os.environ.items() if k not in BLAS_ENV}
    env["OPENBLAS_NUM_THREADS"] = "2"          # a user's setting is overridden
    code = ("import ancf.reports.__main__, os, sys; "
            "sys.stdout.write(','.join(os.environ[k] for k in sorted(%r)))" % sorted(BLAS_ENV))
    out = subprocess.run([sys.executable, "-c", code], env=env, capture_output=True,
                         text=True, check=True).stdout
    assert out == "1,1,1"


def test_sweep_workers_get_the_same_environment():
    assert all(_ENV[k] == v for k, v in BLAS_ENV.items())
