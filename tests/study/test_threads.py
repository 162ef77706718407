"""Every run uses one BLAS thread (`ancf.common.threads`): the report generator and sweep
workers set it before numpy loads, and ``Scene.execute`` pins it with threadpoolctl
whatever the process's ``OPENBLAS_NUM_THREADS``, so numbers do not depend on the
machine's core count."""
import json
import os
import subprocess
import sys
from pathlib import Path

import pytest

from ancf.study.sweep_pool import _Runner
from ancf.common.threads import BLAS_ENV


def test_report_generator_pins_one_blas_thread_before_numpy():
    env = {k: v for k, v in os.environ.items() if k not in BLAS_ENV}
    env["OPENBLAS_NUM_THREADS"] = "2"          # a user's setting is overridden
    code = ("import ancf.reports.__main__, os, sys; "
            "sys.stdout.write(','.join(os.environ[k] for k in sorted(%r)))" % sorted(BLAS_ENV))
    out = subprocess.run([sys.executable, "-c", code], env=env, capture_output=True,
                         text=True, check=True).stdout
    assert out == "1,1,1"


@pytest.mark.slow
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


#: numpy loads first, so the environment cannot pin BLAS: only Scene.execute's pin can
_RADAU = """
import json, numpy, scipy.linalg
from threadpoolctl import threadpool_info
from ancf.scenes import SCENES
out, _ = SCENES["pendulum"].execute({"integrator": "radau", "rtol": 1e-3, "atol": 1e-5})
print(json.dumps({"steps": out["results"]["steps"], "threads_outside": sorted(
    {d["num_threads"] for d in threadpool_info()}),
    "energy": out["results"]["energy_max_deviation_J"]}))
"""


def _radau(threads: str) -> dict:
    env = {k: v for k, v in os.environ.items() if k not in BLAS_ENV}
    env["OPENBLAS_NUM_THREADS"] = threads
    return json.loads(subprocess.run([sys.executable, "-c", _RADAU], env=env, check=True,
                                     capture_output=True, text=True).stdout)


@pytest.mark.slow
def test_radau_pendulum_row_does_not_depend_on_blas_threads():
    """The dynamics chapter's Radau rtol 1e-3 row: unpinned, 325 steps with one OpenBLAS
    thread and 330 with two (energy deviation 3.02e-3 vs 4.64e-3 J); pinned, the same."""
    one, two = _radau("1"), _radau("2")
    assert two["threads_outside"] == [2]       # the process itself keeps the user's two
    assert (two["steps"], two["energy"]) == (one["steps"], one["energy"])
