"""Two costs of a short ``ancf run`` process that are not its work: PyYAML at numba's
import and the interpreter's shutdown, together about 40 ms CPU of a 0.45 s process.

* ``numba.core.config`` imports PyYAML (10-15 ms CPU) only to read a ``.numba_config.yaml``
  in the working directory.  :func:`numba_without_yaml` lets numba be imported with
  ``yaml`` unimportable where no such file exists (numba then reads nothing either way);
  afterwards ``import yaml`` works as before.  With the file, nothing changes.
* The end of a process tears down every module numba and llvmlite loaded (about 25 ms
  CPU).  :func:`end_process` flushes the output and ends the process at once
  (``os._exit``): nothing in ``ancf run`` waits for the interpreter's exit handlers.  A
  numba chrome trace asked for (``NUMBA_CHROME_TRACE``) is written by one, so then the
  process ends the usual way.
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
