"""ancf-bench: the Absolute Nodal Coordinate Formulation for beams, plates and belt drives.

The Python API (``ancf.run``, ``ancf.analytic``, ``ancf.modes``, ``ancf.scenes``, ``ancf.sweep``,
``ancf.recommend``, ``ancf.Result``, ``ancf.InputError``) lives in :mod:`ancf.api`, loaded on
first use by the module ``__getattr__`` below: importing ``ancf`` (every command and every
numba worker process does) stays cheap.

Numba's on-disk cache is invalidated only when a compiled function's own file changes,
not when a function it calls (and compiles in) does: after editing ``contact3d.py`` the
belt march would keep running the old contact kernel from its cache.  So the cache
lives in a directory named by a hash of the package's sources
(``$XDG_CACHE_HOME/ancf-bench/<hash>``, default ``~/.cache``): any edit starts a fresh
cache, and an unchanged tree reuses its compiled kernels.  A ``NUMBA_CACHE_DIR`` set
by the user wins; importing numba before ancf keeps numba's default location.
"""
from __future__ import annotations

import hashlib
import os
from pathlib import Path


def numba_cache_dir(root: Path | None = None) -> Path:
    """The cache directory for the sources below ``root`` (default: this package)."""
    root = root or Path(__file__).resolve().parent
    digest = hashlib.sha1()
    for path in sorted(root.rglob("*.py")):
        digest.update(path.relative_to(root).as_posix().encode())
        digest.update(path.read_bytes())
    base = Path(os.environ.get("XDG_CACHE_HOME") or Path.home() / ".cache")
    return base / "ancf-bench" / digest.hexdigest()[:16]


os.environ.setdefault("NUMBA_CACHE_DIR", str(numba_cache_dir()))


#: the names of the Python API (:mod:`ancf.api`), loaded on first use
API = ("run", "analytic", "modes", "scenes", "sweep", "recommend", "Result", "InputError")


def __getattr__(name):
    if name not in API:
        raise AttributeError(f"module 'ancf' has no attribute {name!r}")
    from ancf import api
    # ``scenes``: once loaded, the package ``ancf.scenes`` is found first (it is callable
    # and lists the scenes, as ``ancf.api.scenes`` does); return it then, for one identity
    return globals()[name] if name in globals() else getattr(api, name)


def __dir__():
    return sorted(set(globals()) | set(API))
