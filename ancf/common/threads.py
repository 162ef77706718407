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

#: environment of sweep workers and of the report generator
BLAS_ENV = {"OPENBLAS_NUM_THREADS": "1", "OMP_NUM_THREADS": "1", "MKL_NUM_THREADS": "1"}

_PINNED_AT_LOAD = [False]  # BLAS_ENV was set before numpy (and so any BLAS) was loaded


def one_blas_thread() -> None:
    """Set :data:`BLAS_ENV` in this process; effective for BLAS libraries loaded later."""
    os.environ.update(BLAS_ENV)
    if "numpy" not in sys.modules:
        _PINNED_AT_LOAD[0] = True


@contextmanager
def blas_pinned():
    """One thread in every loaded BLAS/OpenMP pool for the block (threadpoolctl, about
    0.3 ms); nothing to do when :func:`one_blas_thread` ran before numpy was loaded."""
    if _PINNED_AT_LOAD[0]:
        yield
        return
    from threadpoolctl import threadpool_limits
    with threadpool_limits(limits=1):
        yield
