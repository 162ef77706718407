"""A sweep on a Dask cluster (:mod:`ancf.study.sweep`, ``scheduler=ADDRESS``): each Dask
worker thread drives one worker process of :mod:`ancf.study.sweep_pool`, so time limits,
isolation and the numbers are those of a local sweep.

Failing loudly: an address where no Dask scheduler answers ``identity`` within
:data:`SCHEDULER_TIMEOUT` seconds (a closed port, an HTTP server, a scheduler that never
finishes its handshake) is bad input, one ``error:`` line and exit 2, before any run; a
drive file travels as an absolute path (:func:`ancf.study.sweep_tasks.make_tasks`), so
workers started in another folder read the same file; the workers the scheduler lost
while they held a run, and the runs it therefore ran again, are counted in the sweep's
closing line (:func:`lost_and_retried`).
"""
from __future__ import annotations

import os
import threading
import time

from ancf.common.params import InputError
from ancf.study.sweep_pool import _Runner
from ancf.study.sweep_tasks import failure_row

_LOCAL = threading.local()
SCHEDULER_TIMEOUT = 5.0  # s to connect to a Dask scheduler, hand-shake and hear its identity


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


def _identity(address) -> dict:
    """The scheduler's answer to ``identity`` at ``address``: connect, hand-shake, ask and
    read, all within SCHEDULER_TIMEOUT seconds (TimeoutError otherwise), in a thread of
    its own (a caller may already run an event loop)."""
    import asyncio
    from concurrent.futures import ThreadPoolExecutor

    from distributed.comm import connect

    async def ask():
        comm = await connect(address, timeout=SCHEDULER_TIMEOUT)
        try:
            await comm.write({"op": "identity", "reply": True})
            return await comm.read()
        finally:
            comm.abort()

    with ThreadPoolExecutor(1) as pool:
        return pool.submit(asyncio.run, asyncio.wait_for(ask(), SCHEDULER_TIMEOUT)).result()


def _refused_at_once(address) -> None:
    """Raise ``ConnectionRefusedError`` (or ``OverflowError`` for a port past 65535) at
    once where a ``tcp://HOST:PORT`` (or ``HOST:PORT``) has nothing listening, instead of
    the Dask client's retries until :data:`SCHEDULER_TIMEOUT`; any other address or outcome
    is left to :func:`_identity`."""
    import socket
    host, sep, port = str(address).removeprefix("tcp://").rpartition(":")
    if not sep or not host or not port.isdigit():
        return
    if int(port) > 65535:
        raise OverflowError(f"port {port} past 65535")
    try:
        socket.create_connection((host.strip("[]"), int(port)), timeout=SCHEDULER_TIMEOUT).close()
    except (ConnectionRefusedError, OverflowError):
        raise
    except OSError:  # unreachable, timed out, unresolvable: the Dask path reports it
        return


def _connect(address):
    """A Dask client, or one line naming the address when nothing answers as a Dask
    scheduler within SCHEDULER_TIMEOUT seconds (a closed port, another server, a
    scheduler that does not finish its handshake): never a wait without end."""
    from distributed import Client
    where = f"--scheduler {address}"
    try:
        _refused_at_once(address)
        reply = _identity(address)
    except (ValueError, TypeError) as exc:
        raise InputError(f"{where}: not a scheduler address ({exc}); allowed: "
                         "tcp://HOST:PORT of a running Dask scheduler") from None
    except Exception as exc:  # noqa: BLE001 - timeouts, refused, closed, garbled: no answer
        raise InputError(f"{where}: no Dask scheduler answered within {SCHEDULER_TIMEOUT:g} s "
                         f"({type(exc).__name__}); allowed: the address of a running Dask "
                         "scheduler (tcp://HOST:PORT)") from None
    if not isinstance(reply, dict) or reply.get("type") != "Scheduler":
        raise InputError(f"{where}: the server there is not a Dask scheduler (it answered as "
                         f"{str(reply)[:60]!r}); allowed: the address of a Dask scheduler")
    try:
        return Client(address, timeout=SCHEDULER_TIMEOUT)
    except Exception as exc:  # noqa: BLE001 - it answered, then went away
        raise InputError(f"{where}: no Dask client within {SCHEDULER_TIMEOUT:g} s "
                         f"({type(exc).__name__}); allowed: the address of a running Dask "
                         "scheduler") from None


def _run_dask(todo: list[dict], scheduler, time_limit: float, lost: dict | None = None):
    """Connect now (an unreachable scheduler fails before any run), then yield rows; at
    the end ``lost`` holds the workers lost and runs retried (:func:`lost_and_retried`)."""
    own = not hasattr(scheduler, "submit")
    client = _connect(scheduler) if own else scheduler
    return _dask_rows(client, own, todo, time_limit, {} if lost is None else lost)


def lost_and_retried(events, keys) -> dict:
    """From the scheduler's ``"all"`` events ((time, message) pairs): the workers removed
    unexpectedly while they held tasks of ``keys`` (running them, or their results not yet
    gathered), and how many of those tasks the scheduler therefore ran again."""
    keys, workers, retried = set(keys), set(), set()
    for _, msg in events:
        if not (isinstance(msg, dict) and msg.get("action") == "remove-worker"
                and not msg.get("expected")):
            continue
        hit = (set(msg.get("processing-tasks", ())) | set(msg.get("lost-computed-tasks", ()))) & keys
        if hit:
            workers.add(msg.get("worker"))
            retried |= hit
    return {"lost_workers": len(workers), "retried_runs": len(retried)}


def _dask_rows(client, own: bool, todo: list[dict], time_limit: float, lost: dict):
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
        try:
            events = client.get_events("all")
        except Exception:  # noqa: BLE001 - a scheduler without its event log: none counted
            events = ()
        lost.update(lost_and_retried(events, [f.key for f in futs]))
    finally:
        if own:
            client.close()
