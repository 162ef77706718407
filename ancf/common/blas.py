"""Numba's BLAS without scipy.linalg's package: a whole ``ancf run`` 0.09 s CPU cheaper.

Numba readies its compiler (a cache load too) by importing its array implementations, and
``numba.np.arraymath`` checks for a BLAS at import: ``import scipy.linalg.cython_blas``.
The kernels call BLAS through that extension module alone (numba's C helpers look up
``__pyx_capi__`` in ``sys.modules['scipy.linalg.cython_blas']``), but the import statement
first runs ``scipy/linalg/__init__.py``, which loads all of scipy.linalg and, through
scipy's array-API layer, numpy's ``f2py``, ``ma`` and ``testing``: about 0.09 s of the
0.5 s an ``ancf run cantilever`` process takes.

:func:`preload_cython_blas` loads the extension module by itself under its own name, so
numba's check finds it in ``sys.modules``.  A later ``import scipy.linalg`` still runs the
package as usual (and its ``from .cython_blas ...`` finds the same module).  If scipy's
layout differs, nothing is preloaded and numba imports scipy.linalg as it always did.
"""
from __future__ import annotations

import importlib.machinery
import importlib.util
import sys
from pathlib import Path

NAME = "scipy.linalg.cython_blas"


def preload_cython_blas() -> bool:
    """Load ``scipy.linalg.cython_blas`` without its package (once); True if it is loaded."""
    if NAME in sys.modules:
        return True
    try:
        import scipy
        folder = Path(scipy.__file__).parent / "linalg"
        for suffix in importlib.machinery.EXTENSION_SUFFIXES:
            path = folder / f"cython_blas{suffix}"
            if path.exists():
                spec = importlib.util.spec_from_file_location(NAME, path)
                module = importlib.util.module_from_spec(spec)
                sys.modules[NAME] = module
                try:
                    spec.loader.exec_module(module)
                except Exception:
                    del sys.modules[NAME]
                    raise
                return True
    except Exception:  # any surprise: numba imports scipy.linalg itself, as before
        return False
    return False
