"""One BLAS thread for every run whose numbers go into a report or a sweep.

Results at loose tolerances depend on the BLAS thread count through the rounding of
threaded kernels: the 4-element pendulum with Radau at rtol 1e-3 takes 318 steps (energy
deviation 4.8e-3 J) with one OpenBLAS thread and 334 steps (4.2e-3 J) with two; the tip
positions agree to 4e-7 m.  Pinning one thread makes reports and sweeps reproducible
and their CPU times comparable (process time of a single thread).  Must run before numpy
is imported to take effect.
"""
from __future__ import annotations

import os

#: environment of sweep workers and of the report generator
BLAS_ENV = {"OPENBLAS_NUM_THREADS": "1", "OMP_NUM_THREADS": "1", "MKL_NUM_THREADS": "1"}


def one_blas_thread() -> None:
    """Set :data:`BLAS_ENV` in this process (before numpy is imported)."""
    os.environ.update(BLAS_ENV)
