"""Three costs of a short ``ancf run`` process that are not its work: PyYAML at numba's
import, readying numba's compiler to load cached kernels, and the interpreter's shutdown.

* ``numba.core.config`` imports PyYAML (10-15 ms CPU) only to read a ``.numba_config.yaml``
  in the working directory.  :func:`numba_without_yaml` lets numba be imported with
  ``yaml`` unimportable where no such file exists (numba then reads nothing either way);
  afterwards ``import yaml`` works as before.  With the file, nothing changes.
* The end of a process tears down every module numba and llvmlite loaded (about 25 ms
  CPU).  :func:`end_process` flushes the output and ends the process at once
  (``os._exit``): nothing in ``ancf run`` waits for the interpreter's exit handlers.  A
  numba chrome trace asked for (``NUMBA_CHROME_TRACE``) is written by one, so then the
  process ends the usual way.
* Numba readies its whole compiler before it looks in its on-disk cache (``refresh``: it
  imports every implementation module and fills its typing and lowering tables, about
  0.1 s CPU), though a cached kernel is machine code that needs only numba's runtime.
  :func:`lean_cache_loads` makes a cache load ready the runtime alone; a kernel not in the
  cache is compiled as before (numba's compiler refreshes the tables itself first).
"""
from __future__ import annotations

import os
import sys
from contextlib import contextmanager

NUMBA_CONFIG = ".numba_config.yaml"  # numba.core.config's file in the working directory


@contextmanager
def numba_without_yaml():
    """Within: ``import yaml`` fails (ImportError) unless yaml is loaded already or the
    working directory holds numba's config file."""
    block = "yaml" not in sys.modules and not os.path.isfile(NUMBA_CONFIG)
    if block:
        sys.modules["yaml"] = None
    try:
        yield
    finally:
        if block and sys.modules.get("yaml", 0) is None:
            del sys.modules["yaml"]


def end_process(code: int) -> None:
    """Flush stdout and stderr and end the process with ``code``, without the interpreter's
    shutdown (returns only where a chrome trace waits to be written at exit)."""
    if os.environ.get("NUMBA_CHROME_TRACE"):
        return
    sys.stdout.flush()
    sys.stderr.flush()
    os._exit(code)


def lean_cache_loads() -> None:
    """From now on numba loads a cached kernel after readying its runtime (NRT) only, not
    its compiler; a cache miss compiles as before (``CompilerBase`` refreshes first).  A
    numba whose cache lacks the loader this wraps keeps its own loads."""
    import numba.cpython.hashing  # noqa: F401  its import adds the hash-secret symbols
    from numba.core.caching import Cache
    from numba.core.runtime import rtsys
    if not hasattr(Cache, "_load_overload"):
        return

    def load_overload(self, sig, target_context):
        rtsys.initialize(target_context)
        with self._guard_against_spurious_io_errors():
            return self._load_overload(sig, target_context)
    Cache.load_overload = load_overload
