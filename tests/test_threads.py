"""The report generator and sweep workers run with one BLAS thread (`ancf.common.threads`), so
their numbers agree with each other and do not depend on the machine's core count."""
import os
import subprocess
import sys
from pathlib import Path

from ancf.study.sweep import _Runner
from ancf.common.threads import BLAS_ENV


def test_report_generator_pins_one_blas_thread_before_numpy():
    env = {k: v for k, v in os.environ.items() if k not in BLAS_ENV}
    env["OPENBLAS_NUM_THREADS"] = "2"          # a user's setting is overridden
    code = ("import ancf.reports.__main__, os, sys; "
            "sys.stdout.write(','.join(os.environ[k] for k in sorted(%r)))" % sorted(BLAS_ENV))
    out = subprocess.run([sys.executable, "-c", code], env=env, capture_output=True,
                         text=True, check=True).stdout
    assert out == "1,1,1"


def test_sweep_workers_start_with_one_blas_thread(monkeypatch):
    """The environment a sweep worker process actually has once it is ready, with a user's
    OPENBLAS_NUM_THREADS=2 in ours (OpenBLAS, OpenMP and MKL read it when they load)."""
    monkeypatch.setenv("OPENBLAS_NUM_THREADS", "2")
    runner = _Runner()
    try:
        runner.wait_ready()
        raw = Path(f"/proc/{runner.proc.pid}/environ").read_bytes().decode()
    finally:
        runner.close()
    env = dict(kv.split("=", 1) for kv in raw.split("\0") if "=" in kv)
    assert {k: env.get(k) for k in BLAS_ENV} == dict.fromkeys(BLAS_ENV, "1")
