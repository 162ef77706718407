"""ancf-bench: the Absolute Nodal Coordinate Formulation for beams, plates and belt drives.

The Python API (``ancf.run``, ``ancf.analytic``, ``ancf.modes``, ``ancf.scenes``, ``ancf.sweep``,
``ancf.recommend``, ``ancf.Result``, ``ancf.InputError``) lives in :mod:`ancf.api`, loaded on
first use by the module ``__getattr__`` below: importing ``ancf`` (every command and every
numba worker process does) stays cheap.

Numba's on-disk cache is invalidated only when a compiled function's own file changes,
not when a function it calls (and compiles in) does: after editing ``contact3d.py`` the
belt march would keep running the old contact kernel from its cache.  So the cache
lives in a directory named by a hash of the sources compiled code can reach
(``$XDG_CACHE_HOME/ancf-bench/<hash>``, default ``~/.cache``): the folders of
:data:`KERNEL_FOLDERS`, the layers that hold every compiled kernel and everything a kernel
can import (the layers import only those below them, ``tests/common/test_layers.py``;
``tests/common/test_imports.py`` keeps numba out of the other folders).  An edit there
starts a fresh cache; an edit of a scene, check, report or the study layer keeps the
compiled kernels.  Numba keys its cache by source and CPU, not by LLVM's optimisation
level: a ``NUMBA_OPT`` other than numba's default 3 (``make test`` sets 1) gets a directory
of its own (``<hash>-opt1``), so that kernels compiled for the tests never serve a report
or a benchmark.  A ``NUMBA_CACHE_DIR`` set by the user wins; importing numba before ancf
keeps numba's default location.
"""
from __future__ import annotations

import os
from pathlib import Path


#: the package's folders with compiled code, and the layers below them (ancf.common.layers)
KERNEL_FOLDERS = ("common", "core", "solvers", "elements", "models", "belts")


def source_hash(root: Path | None = None, folders=None) -> str:
    """A hash (16 hex digits) of the sources below ``root`` (default: this package), of
    the ``folders`` below it only where given."""
    import hashlib  # here: a set NUMBA_CACHE_DIR imports ancf without hashing
    root = root or Path(__file__).resolve().parent
    paths = (root.rglob("*.py") if folders is None
             else (p for f in folders for p in (root / f).rglob("*.py")))
    digest = hashlib.sha1()
    for path in sorted(paths):
        digest.update(path.relative_to(root).as_posix().encode())
        digest.update(path.read_bytes())
    return digest.hexdigest()[:16]


def numba_cache_dir(root: Path | None = None, folders=KERNEL_FOLDERS) -> Path:
    """The cache directory for the kernel sources below ``root`` (default: this package;
    ``folders`` None: every source) and the optimisation level ``NUMBA_OPT``."""
    base = Path(os.environ.get("XDG_CACHE_HOME") or Path.home() / ".cache")
    opt = os.environ.get("NUMBA_OPT", "3").strip() or "3"
    return base / "ancf-bench" / (source_hash(root, folders) + ("" if opt == "3" else f"-opt{opt}"))


if "NUMBA_CACHE_DIR" not in os.environ:  # a directory set wins: no sources read, no hash
    os.environ["NUMBA_CACHE_DIR"] = str(numba_cache_dir())


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
