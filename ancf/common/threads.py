"""One BLAS thread for every run: results that do not depend on the machine's core count.

Results at loose tolerances depend on the BLAS thread count through the rounding of
threaded kernels: the pendulum with Radau at rtol 1e-3 (4 linear elements, the dynamics
chapter's trade-off table) takes 325 steps (energy deviation 3.02e-3 J) with one OpenBLAS
thread and 330 steps (4.64e-3 J) with two; each count repeats exactly.  So every
``Scene.execute`` runs inside :func:`blas_pinned` (one thread, whatever the user's
``OPENBLAS_NUM_THREADS``), and the report generator, the CLI and the sweep workers set
:data:`BLAS_ENV` before numpy loads (:func:`one_blas_thread`), which makes the pin free.
CPU times are then the process time of a single thread.
"""
from __future__ import annotations

import os
import sys
from contextlib import contextmanager
from functools import lru_cache

#: environment of sweep workers and of the report generator
BLAS_ENV = {"OPENBLAS_NUM_THREADS": "1", "OMP_NUM_THREADS": "1", "MKL_NUM_THREADS": "1"}

_PINNED_AT_LOAD = [False]  # BLAS_ENV was set before numpy (and so any BLAS) was loaded


def one_blas_thread() -> None:
    """Set :data:`BLAS_ENV` in this process; effective for BLAS libraries loaded later."""
    os.environ.update(BLAS_ENV)
    if "numpy" not in sys.modules:
        _PINNED_AT_LOAD[0] = True


@lru_cache(maxsize=1)
def started_pinned() -> bool:
    """Whether this process started with :data:`BLAS_ENV` (every value "1") in its
    environment (Linux ``/proc/self/environ``, the environment at exec): then every BLAS
    it loads reads one thread at load, whenever numpy came in."""
    try:
        with open("/proc/self/environ", "rb") as f:
            start = dict(v.split(b"=", 1) for v in f.read().split(b"\0") if b"=" in v)
    except OSError:
        return False
    return all(start.get(k.encode()) == b"1" for k in BLAS_ENV)


@contextmanager
def blas_pinned():
    """One thread in every loaded BLAS/OpenMP pool for the block (threadpoolctl, about
    1.2 ms: a scan of the loaded libraries); nothing to do when :func:`one_blas_thread`
    ran before numpy was loaded or the process started with :data:`BLAS_ENV`."""
    if _PINNED_AT_LOAD[0] or started_pinned():
        yield
        return
    from threadpoolctl import threadpool_limits
    with threadpool_limits(limits=1):
        yield
