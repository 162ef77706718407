"""A sweep on a Dask cluster (:mod:`ancf.study.sweep`, ``scheduler=ADDRESS``): each Dask
worker thread drives one worker process of :mod:`ancf.study.sweep_pool`, so time limits,
isolation and the numbers are those of a local sweep.
"""
from __future__ import annotations

import os
import threading
import time

from ancf.common.params import InputError
from ancf.study.sweep_pool import _Runner
from ancf.study.sweep_tasks import failure_row

_LOCAL = threading.local()
SCHEDULER_TIMEOUT = 5.0  # s to reach a Dask scheduler


def dask_run(task: dict, time_limit: float) -> dict:
    """Dask task: run one case in this Dask worker thread's own worker process."""
    r = getattr(_LOCAL, "runner", None)
    if r is None or r.proc.poll() is not None:
        r = _LOCAL.runner = _Runner()
        r.wait_ready()
    row = r.run_blocking(task, time_limit)
    if row["status"] in ("timeout", "worker-died"):
        _LOCAL.runner = None
    return row


def _connect(address):
    """A Dask client, or one line naming the address after SCHEDULER_TIMEOUT seconds."""
    from distributed import Client
    try:
        return Client(address, timeout=SCHEDULER_TIMEOUT)
    except OSError:  # TimeoutError is an OSError
        raise InputError(f"--scheduler {address}: no Dask scheduler answered within "
                         f"{SCHEDULER_TIMEOUT:g} s") from None
    except (ValueError, TypeError) as exc:
        raise InputError(f"--scheduler {address}: not a scheduler address ({exc})") from None


def _run_dask(todo: list[dict], scheduler, time_limit: float):
    """Connect now (an unreachable scheduler fails before any run), then yield rows."""
    own = not hasattr(scheduler, "submit")
    return _dask_rows(_connect(scheduler) if own else scheduler, own, todo, time_limit)


def _dask_rows(client, own: bool, todo: list[dict], time_limit: float):
    from distributed import as_completed
    try:
        session = f"{os.getpid()}-{time.time_ns()}"
        futs = {client.submit(dask_run, t, time_limit, pure=False,
                              key=f"ancf-sweep-{t['key']}-{session}"): t for t in todo}
        for fut in as_completed(futs):
            try:
                yield fut.result()
            except Exception as exc:  # noqa: BLE001
                yield failure_row(futs[fut], "failed", f"dask: {type(exc).__name__}: {exc}")
    finally:
        if own:
            client.close()

