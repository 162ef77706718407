"""Parameter sweeps: the cartesian product of parameter values, run in parallel.

``ancf sweep SCENE --grid key=v1,v2 [--grid ...]`` (or :func:`run_sweep`) runs every
combination in worker processes, one row per run, into a Parquet or CSV file:

* the row holds the key (a hash of the scene and every resolved parameter value), the
  parameters (one column each, all values used), ``status`` (``ok``, ``not-converged``,
  ``failed``, ``timeout``, ``invalid``, ``worker-died``), ``converged``, ``message``,
  ``error`` against the scene's reference (:mod:`ancf.study.references`), ``reference``,
  ``cpu_time_s`` (process CPU time of the run, without compiling or loading numba
  kernels), ``compile_cpu_s`` (that compiling and loading), ``wall_time_s``, ``steps``
  (load steps or time steps), ``iterations`` (Newton iterations), ``work`` (the run's
  counted work, :mod:`ancf.study.cost`: what ``recommend`` ranks by; NaN when the
  results carry no counters), ``session`` (which invocation computed it) and the scalar
  results as ``res_<name>`` (list results: their last value as ``res_<name>_final``);
* the sweep ends with one line on stderr: rows, converged, not converged, failed and the
  time taken;
* runs are deterministic (one BLAS thread per worker) and resumable: every finished row
  is appended at once to ``FILE.journal.jsonl``; a new call with the same file skips the
  keys already there (``retry_failed`` reruns failed / timed-out ones) and the journal is
  folded into FILE at the end, also after Ctrl-C;
* each run happens in a separate worker process, killed when it exceeds ``time_limit``
  CPU seconds (the row says ``time limit exceeded (X s)``); the clock stops while the
  worker compiles or loads numba kernels (it says so on its line protocol), so neither an
  empty kernel cache nor a loaded machine decides a row.  A run that takes ``HANG_FACTOR``
  times its limit in wall time (a hang), or a single compilation over ``COMPILE_LIMIT``
  seconds, is a timeout too; an exception or a crash of the worker
  becomes a failed row with its message; the other runs go on;
* the idle workers of a finished sweep wait for the next sweep of the same process and
  environment (:func:`_take_runner`): a worker's start (interpreter, imports, a warm-up
  solve) costs about 1.6 CPU seconds, and ``make reports`` runs some 27 sweeps; an
  interrupted or failed sweep ends its workers;
* ``scheduler=ADDRESS`` runs the same tasks on a Dask cluster (dask.distributed); each
  Dask worker thread drives one such worker process, so time limits, isolation and
  the numbers are the same as on one machine.
"""
from __future__ import annotations

import atexit
import itertools
import json
import math
import os
import selectors
import signal
import subprocess
import sys
import tempfile
import threading
import time
import traceback
from collections import deque
from pathlib import Path

import numpy as np
import pandas as pd

from ancf.study.cost import row_counts, work
from ancf.study.references import ReferenceFailed, runner, spec, stable_hash
from ancf.common.threads import BLAS_ENV
from ancf.common.params import InputError
from ancf.common.paths import REPO
from ancf.scenes.store import keep

STATUSES = ("ok", "not-converged", "failed", "timeout", "invalid", "worker-died")
RETRY = ("failed", "timeout", "worker-died")
COMPILE_LIMIT = 1800.0  # s of wall time one compilation (or cache load) of a kernel may take
HANG_FACTOR = 10.0      # wall time beyond this many times the (CPU) time limit: a hang
PILOT_CPU = 2.0  # s of its first run's CPU (compiling left out) before the pilot's peers start
_ENV = {**BLAS_ENV, "PYTHONWARNINGS": "ignore"}


# ---------------------------------------------------------------------------------------
# grids and tasks
# ---------------------------------------------------------------------------------------

def parse_grid(scene: str, items, quantity: str = "results") -> dict:
    """``["n_elements=2,4,8", "integration=thesis;normal=2x2,shear=1x1"]`` -> {name: [values]}.
    Values are separated by ',' (or by ';' when a value itself holds commas) and parsed
    by the scene's parameter (bad values raise InputError naming the field)."""
    sc = runner(scene, quantity)
    params = {p.name: p for p in sc.params}
    grid = {}
    for item in items or []:
        if "=" not in item:
            raise InputError(f"--grid {item!r}: expected key=v1,v2,...")
        k, v = item.split("=", 1)
        k = k.strip()
        if k not in params:
            raise InputError(f"{k}: unknown parameter of scene {scene!r}; allowed: "
                             f"{', '.join(params)}")
        if k in grid:
            raise InputError(f"--grid {k}: given twice; allowed: one --grid per parameter "
                             f"(list every value in it: {k}=v1,v2,...)")
        vals = [s.strip() for s in (v.split(";") if ";" in v else v.split(",")) if s.strip()]
        if not vals:
            raise InputError(f"--grid {item!r}: no values")
        grid[k] = list(dict.fromkeys(params[k].parse(s) for s in vals))
    return grid


def expand(grids, fixed: dict | None = None) -> list[dict]:
    """Union of the cartesian products of ``grids`` (a dict or a list of dicts), each
    combination merged over ``fixed``; deterministic order, duplicates removed."""
    if isinstance(grids, dict):
        grids = [grids]
    out, seen = [], set()
    for g in grids:
        keys = list(g)
        for combo in itertools.product(*(g[k] for k in keys)):
            ov = dict(fixed or {})
            ov.update(zip(keys, combo))
            h = json.dumps(ov, sort_keys=True, default=str)
            if h not in seen:
                seen.add(h)
                out.append(ov)
    return out


def run_key(scene: str, params: dict, quantity: str = "results") -> str:
    if quantity != "results":  # the scene's own runs keep their keys
        return stable_hash({"scene": scene, "params": params, "quantity": quantity})
    return stable_hash({"scene": scene, "params": params})


def make_tasks(scene: str, overrides: list[dict], reference: str | None = None,
               quantity: str = "results") -> list[dict]:
    """Resolve every combination, key it, and attach the reference values (computed
    once per distinct physical problem, in this process)."""
    sc = runner(scene, quantity)
    s = spec(scene, quantity)
    ref = s.reference(reference)
    refs: dict = {}
    tasks = []
    for i, ov in enumerate(overrides):
        t = {"index": i, "scene": scene, "reference": ref.name, "ref_values": None,
             "ref_error": None, "quantity": quantity}
        try:
            params = sc.resolve(ov)
        except InputError as exc:
            t.update(params=None, overrides={k: _jsonable(v) for k, v in ov.items()},
                     invalid=str(exc), key=stable_hash({"scene": scene, "overrides": ov}))
            tasks.append(t)
            continue
        t.update(params={k: _jsonable(v) for k, v in params.items()},
                 key=run_key(scene, params, quantity))
        pk = stable_hash(s.physical(params))
        if pk not in refs:
            try:
                refs[pk] = (ref.values(params), None)
            except (ReferenceFailed, ValueError) as exc:
                refs[pk] = (None, str(exc))
        t["ref_values"], t["ref_error"] = refs[pk]
        tasks.append(t)
    return tasks


def _jsonable(v):
    if isinstance(v, np.generic):
        return v.item()
    return v


# ---------------------------------------------------------------------------------------
# one run (in a worker process)
# ---------------------------------------------------------------------------------------

def _base_row(task: dict) -> dict:
    row = {"key": task["key"], "scene": task["scene"]}
    if task.get("quantity", "results") != "results":
        row["quantity"] = task["quantity"]
    row.update(task.get("params") or task.get("overrides") or {})
    row.update(status=None, converged=False, message="", error=float("nan"),
               reference=task["reference"], cpu_time_s=float("nan"),
               compile_cpu_s=float("nan"), wall_time_s=float("nan"), steps=None, iterations=None)
    return row


def failure_row(task: dict, status: str, message: str, wall: float = float("nan")) -> dict:
    row = _base_row(task)
    row.update(status=status, message=message, wall_time_s=wall)
    return row


def run_case(task: dict) -> dict:
    """Run one task; never raises (failures become rows)."""
    quantity = task.get("quantity", "results")
    if task.get("invalid"):
        return failure_row(task, "invalid", f"invalid input: {task['invalid']}", 0.0)
    row = _base_row(task)
    t0 = time.perf_counter()
    try:
        with np.errstate(all="ignore"):
            out, _ = runner(task["scene"], quantity).execute(task["params"])
    except InputError as exc:
        return failure_row(task, "invalid", f"invalid input: {exc}", time.perf_counter() - t0)
    except Exception as exc:  # noqa: BLE001 - a failing run is data, not a crash
        tb = traceback.extract_tb(exc.__traceback__)
        where = f" at {Path(tb[-1].filename).name}:{tb[-1].lineno}" if tb else ""
        return failure_row(task, "failed", f"{type(exc).__name__}: {exc}{where}",
                           time.perf_counter() - t0)
    wall = time.perf_counter() - t0
    if quantity == "results":  # the run store holds scene runs, keyed by their parameters
        keep(task["scene"], task["params"], out)
    res = out["results"] or {}
    row.update(converged=bool(out["converged"]), message=out["message"],
               cpu_time_s=float(out["cpu_time_s"]),
               compile_cpu_s=float(out.get("compile_cpu_s", float("nan"))), wall_time_s=wall)
    row["steps"] = res.get("steps", res.get("load_steps_taken"))
    row["iterations"] = res.get("newton_iterations")
    for k, v in res.items():
        if isinstance(v, (list, tuple)):
            if v and isinstance(v[-1], (int, float)) and not isinstance(v[-1], bool):
                row[f"res_{k}_final"] = float(v[-1])
        elif v is None or isinstance(v, (bool, int, float, str)):
            row[f"res_{k}"] = v
    if not out["converged"]:
        row["status"] = "not-converged"
        return row
    bad = [k for k, v in res.items() if isinstance(v, float) and not math.isfinite(v)]
    if bad:
        row.update(status="failed", converged=False,
                   message=f"non-finite result ({', '.join(bad)}) reported as converged")
        return row
    row["status"] = "ok"
    if task.get("ref_values") is not None:
        try:
            ref = spec(task["scene"], quantity).reference(task["reference"])
            err = float(ref.error(res, task["ref_values"], out["params"]))
        except Exception as exc:  # noqa: BLE001
            err, row["message"] = float("nan"), f"{out['message']}; error not computed: {exc}"
        if not math.isfinite(err):
            row.update(status="failed", message=f"{out['message']}; error against "
                       f"{task['reference']} is not finite")
        row["error"] = err
    else:
        row["message"] = f"{out['message']}; reference unavailable: {task.get('ref_error')}"
    return row


PARENT_ENV = "ANCF_SWEEP_PARENT"  # the driver's pid, given to its workers
WATCH_S = 0.5  # the watchdog's polling interval (s)


def _die_with_parent(parent: int | None, pdeathsig: bool = True) -> None:
    """End this worker when its driver ends, however it ends (even SIGKILL): Linux's
    ``prctl(PR_SET_PDEATHSIG, SIGKILL)``, and on every platform a daemon thread that
    ends the process once its parent is no longer ``parent`` (reparented: the driver
    died), checked every WATCH_S seconds, also while the main thread computes.  (The
    driver also closes the worker's stdin, whose end of file stops the task loop.)
    ``ANCF_SWEEP_PDEATHSIG=0`` in a worker's environment leaves the watchdog alone (so
    that the tests can check it on its own)."""
    if parent is None:
        return
    if pdeathsig and sys.platform.startswith("linux"):
        try:
            import ctypes
            libc = ctypes.CDLL(None, use_errno=True)
            libc.prctl(1, signal.SIGKILL, 0, 0, 0)  # 1 = PR_SET_PDEATHSIG
        except (OSError, AttributeError):
            pass
    if os.getppid() != parent:  # died before the prctl took effect
        os._exit(1)

    def watch():
        while True:
            time.sleep(WATCH_S)
            if os.getppid() != parent:
                os._exit(1)
    threading.Thread(target=watch, name="ancf-parent-watchdog", daemon=True).start()


def _worker_main() -> int:
    """``python -m ancf.study.sweep --worker``: read tasks (JSON lines) on stdin, write rows on
    the original stdout; anything the scenes print goes to stderr.  Ends with its driver
    (:func:`_die_with_parent`)."""
    parent = os.environ.get(PARENT_ENV)
    _die_with_parent(int(parent) if parent and parent.isdigit() else None,
                     pdeathsig=os.environ.get("ANCF_SWEEP_PDEATHSIG", "1") != "0")
    signal.signal(signal.SIGINT, signal.SIG_IGN)  # the driver decides when to stop
    out = os.fdopen(os.dup(1), "w")
    os.dup2(2, 1)
    sys.stdout = sys.stderr
    from ancf.scenes import SCENES  # warm the imports and the compiled kernels (a
    SCENES["axial-bar"].execute({"n_elements": 1})  # one-element solve) before saying ready
    _announce_compiles(out)
    out.write(json.dumps({"ready": os.getpid()}) + "\n")
    out.flush()
    for line in sys.stdin:
        if not line.strip():
            continue
        row = run_case(json.loads(line))
        out.write(json.dumps(row) + "\n")
        out.flush()
    return 0


def _announce_compiles(out):
    """Write ``{"compiling": true}`` / ``{"compiling": false}`` lines to the driver around
    every outermost span of numba's compiler lock (compilations and cache loads: see
    :mod:`ancf.common.compile_time`), so that its time limit leaves them out.  Returns the
    registered listener."""
    from numba.core import event

    def say(flag: bool) -> None:
        out.write(json.dumps({"compiling": flag}) + "\n")
        out.flush()

    class _Announce(event.Listener):
        depth = 0

        def on_start(self, ev):
            self.depth += 1
            if self.depth == 1:
                say(True)

        def on_end(self, ev):
            self.depth -= 1
            if self.depth == 0:
                say(False)

    listener = _Announce()
    event.register("numba:compiler_lock", listener)
    return listener


# ---------------------------------------------------------------------------------------
# worker processes
# ---------------------------------------------------------------------------------------

_TICKS = os.sysconf("SC_CLK_TCK") if hasattr(os, "sysconf") else 100


def process_cpu(pid: int) -> float | None:
    """CPU seconds (user + system) the live process ``pid`` has used; None where /proc
    cannot tell."""
    try:
        with open(f"/proc/{pid}/stat", "rb") as f:
            fields = f.read().rsplit(b")", 1)[1].split()
    except (OSError, IndexError):
        return None
    return (int(fields[11]) + int(fields[12])) / _TICKS  # utime, stime: fields 14, 15


class _RunClock:
    """What a worker's current run has taken: CPU seconds of the worker process (wall
    seconds where /proc is missing) and wall seconds, both without the spans in which it
    compiled or loaded kernels (:func:`_announce_compiles`)."""

    def __init__(self, pid: int):
        self.pid = pid
        self.wall0, self.cpu0 = self._now()
        self.compiling = None  # (wall, cpu) when the current compilation began

    def _now(self) -> tuple[float, float]:
        wall = time.monotonic()
        cpu = process_cpu(self.pid)
        return wall, wall if cpu is None else cpu

    def note(self, compiling: bool) -> None:
        """The worker began (True) or ended (False) a compilation: stop or restart."""
        now = self._now()
        if compiling:
            self.compiling = now
        elif self.compiling is not None:
            self.wall0 += now[0] - self.compiling[0]
            self.cpu0 += now[1] - self.compiling[1]
            self.compiling = None

    def wall(self) -> float:
        return (self.compiling or self._now())[0] - self.wall0

    def cpu(self) -> float:
        return (self.compiling or self._now())[1] - self.cpu0

    def expired(self, time_limit: float) -> str | None:
        """Why the run is over its limits (the row's words), or None."""
        if self.compiling is not None:
            if time.monotonic() - self.compiling[0] > COMPILE_LIMIT:
                return f"one compilation over {COMPILE_LIMIT:g} s"
            return None
        if self.cpu() > time_limit:
            return f"{time_limit:g} s"
        if self.wall() > HANG_FACTOR * time_limit:
            return f"{time_limit:g} s; {HANG_FACTOR:g} times that in wall time"
        return None

    def wait(self, time_limit: float) -> float:
        """Wall seconds before the run can expire at the earliest (a process uses at most
        one CPU second per second)."""
        if self.compiling is not None:
            return max(COMPILE_LIMIT - (time.monotonic() - self.compiling[0]), 0.0)
        return max(min(time_limit - self.cpu(), HANG_FACTOR * time_limit - self.wall()), 0.0)


def _runner_env() -> dict:
    """The environment a worker started now gets."""
    env = dict(os.environ, **_ENV)
    root = str(REPO)
    env["PYTHONPATH"] = root + (os.pathsep + env["PYTHONPATH"] if env.get("PYTHONPATH") else "")
    env[PARENT_ENV] = str(os.getpid())
    return env


class _Runner:
    """One worker process (``python -m ancf.study.sweep --worker``) and its line protocol."""

    def __init__(self, env: dict | None = None):
        self.err = tempfile.TemporaryFile()
        self.env = _runner_env() if env is None else env
        self.proc = subprocess.Popen([sys.executable, "-m", "ancf.study.sweep", "--worker"],
                                     stdin=subprocess.PIPE, stdout=subprocess.PIPE,
                                     stderr=self.err, env=self.env, start_new_session=True)
        self.fd = self.proc.stdout.fileno()
        os.set_blocking(self.fd, False)
        self.buf = b""
        self.task = None
        self.clock = None  # the current run's _RunClock
        self.ready = False

    def send(self, task: dict) -> None:
        self.task, self.clock = task, _RunClock(self.proc.pid)
        self.proc.stdin.write((json.dumps(task) + "\n").encode())
        self.proc.stdin.flush()

    def timeout_row(self, reason: str) -> dict:
        return failure_row(self.task, "timeout", f"time limit exceeded ({reason})",
                           self.clock.wall())

    def feed(self):
        """New complete messages, or None at end of file (the worker died)."""
        try:
            data = os.read(self.fd, 1 << 20)
        except BlockingIOError:
            return []
        if not data:
            return None
        self.buf += data
        *lines, self.buf = self.buf.split(b"\n")
        return [json.loads(x) for x in lines if x.strip()]

    def stderr_tail(self, n: int = 400) -> str:
        try:
            self.err.seek(0)
            text = self.err.read().decode(errors="replace").strip()
        except (OSError, ValueError):
            return ""
        return (": " + text[-n:].replace("\n", " | ")) if text else ""

    def kill(self) -> None:
        if self.proc.poll() is None:
            try:
                os.killpg(self.proc.pid, signal.SIGKILL)
            except (ProcessLookupError, PermissionError):
                self.proc.kill()
        self.proc.wait()
        self._close()

    def close(self) -> None:
        """Ask the worker to finish (end of input), then kill it if it does not."""
        try:
            self.proc.stdin.close()
        except (OSError, BrokenPipeError):
            pass
        try:
            self.proc.wait(timeout=2)
        except subprocess.TimeoutExpired:
            self.kill()
        self._close()

    def _close(self):
        for f in (self.proc.stdin, self.proc.stdout, self.err):
            try:
                f.close()
            except (OSError, BrokenPipeError, ValueError):
                pass

    def died_row(self, task) -> dict:
        code = self.proc.wait()
        how = f"killed by signal {-code}" if code < 0 else f"exit code {code}"
        return failure_row(task, "worker-died", f"worker process died ({how}){self.stderr_tail()}",
                           self.clock.wall())

    def wait_ready(self, timeout: float = 120.0) -> None:
        deadline = time.monotonic() + timeout
        sel = selectors.DefaultSelector()
        sel.register(self.fd, selectors.EVENT_READ)
        try:
            while not self.ready:
                if not sel.select(max(deadline - time.monotonic(), 0.0)):
                    raise RuntimeError("sweep worker did not start in time" + self.stderr_tail())
                msgs = self.feed()
                if msgs is None:
                    raise RuntimeError("sweep worker failed to start" + self.stderr_tail())
                self.ready = any("ready" in m for m in msgs)
        finally:
            sel.close()

    def run_blocking(self, task: dict, time_limit: float) -> dict:
        """Send one task and wait for its row (or kill on the time limit)."""
        self.send(task)
        sel = selectors.DefaultSelector()
        sel.register(self.fd, selectors.EVENT_READ)
        try:
            while True:
                if not sel.select(min(self.clock.wait(time_limit), 1.0)):
                    reason = self.clock.expired(time_limit)
                    if reason is None:
                        continue
                    row = self.timeout_row(reason)
                    self.kill()
                    return row
                msgs = self.feed()
                if msgs is None:
                    return self.died_row(task)
                for m in msgs:
                    if "key" in m:
                        self.task = None
                        return m
                    if "compiling" in m:
                        self.clock.note(m["compiling"])
        finally:
            sel.close()


#: idle workers of this process's finished sweeps, for its next sweep (:func:`_take_runner`)
_PARKED: list[_Runner] = []


def _take_runner() -> _Runner:
    """An idle worker a finished sweep of this process left, started with the environment
    a new one would get now (another one is ended), else a new worker."""
    env = _runner_env()
    while _PARKED:
        r = _PARKED.pop()
        if r.env == env and r.proc.poll() is None:
            r.clock = None  # no run yet in this sweep (the pilot's rule, _pilot_done)
            return r
        r.close()
    return _Runner(env)


def _close_parked() -> None:
    """End the parked workers (at exit; a worker also ends with its driver)."""
    while _PARKED:
        _PARKED.pop().close()


atexit.register(_close_parked)


def _pilot_done(pilot, rows: int) -> bool:
    """May the other workers take runs?  One worker, the pilot, runs first: workers running
    together on an empty kernel cache would each compile the same kernels (numba writes a
    kernel to the cache once compiled): ``python -m ancf.reports --quick`` from an empty
    cache took 768 CPU seconds that way, 582 with a pilot.  The others (started, and
    ready, meanwhile) take runs, loading what the pilot compiled, once it has returned a
    row, died, or run :data:`PILOT_CPU` seconds of its first run outside compilation (a
    run's kernels compile as it starts)."""
    if rows or pilot.proc.poll() is not None:
        return True
    clock = pilot.clock
    return clock is not None and clock.compiling is None and clock.cpu() >= PILOT_CPU


def _run_local(todo: list[dict], workers: int, time_limit: float):
    """Yield one row per task, running ``workers`` worker processes at a time (the first
    of them alone until :func:`_pilot_done`)."""
    pending = deque(todo)
    sel = selectors.DefaultSelector()
    runners: list[_Runner] = []
    rows = 0

    def spawn():
        r = _take_runner()
        sel.register(r.fd, selectors.EVENT_READ, r)
        runners.append(r)

    def retire(r, kill):
        sel.unregister(r.fd)
        runners.remove(r)
        (r.kill if kill else r.close)()

    finished = False
    try:
        for _ in range(max(1, min(workers, len(todo)))):
            spawn()
        pilot, released = runners[0], False
        while pending or any(r.task is not None for r in runners):
            released = released or _pilot_done(pilot, rows)
            for r in runners:
                if r.ready and r.task is None and pending and (released or r is pilot):
                    r.send(pending.popleft())
            busy = [r for r in runners if r.task is not None]
            wait = min([r.clock.wait(time_limit) for r in busy] + [1.0])
            for key, _ in sel.select(max(wait, 0.005)):
                r = key.data
                msgs = r.feed()
                if msgs is None:
                    task, was_ready = r.task, r.ready
                    row = r.died_row(task) if task is not None else None
                    tail = r.stderr_tail()
                    retire(r, kill=True)
                    if not was_ready:
                        raise RuntimeError("sweep worker failed to start" + tail)
                    spawn()
                    if row is not None:
                        rows += 1
                        yield row
                    continue
                for m in msgs:
                    if "ready" in m:
                        r.ready = True
                    elif "key" in m:
                        r.task = None
                        rows += 1
                        yield m
                    elif "compiling" in m and r.clock is not None:
                        r.clock.note(m["compiling"])
            for r in [r for r in runners if r.task is not None]:
                reason = r.clock.expired(time_limit)
                if reason is None:
                    continue
                row = r.timeout_row(reason)
                retire(r, kill=True)
                spawn()
                rows += 1
                yield row
        finished = True
    finally:
        sel.close()
        for r in list(runners):
            if finished and r.proc.poll() is None:
                _PARKED.append(r)  # idle: every task came back
            else:
                r.kill() if r.task is not None else r.close()


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


# ---------------------------------------------------------------------------------------
# files
# ---------------------------------------------------------------------------------------

def journal_path(out) -> Path:
    out = Path(out)
    return out.with_name(out.name + ".journal.jsonl")


def read_rows(out) -> pd.DataFrame:
    """Rows of a sweep file plus its journal (an interrupted sweep), deduplicated by key."""
    out = Path(out)
    frames = []
    if out.exists():
        frames.append(_read_table(out))
    jp = journal_path(out)
    if jp.exists():
        rows = []
        for line in jp.read_text().splitlines():
            try:
                rows.append(json.loads(line))
            except ValueError:
                pass  # a line cut by a hard kill
        if rows:
            frames.append(pd.DataFrame(rows))
    frames = [f for f in frames if len(f)]
    if not frames:
        return pd.DataFrame()
    df = pd.concat(frames, ignore_index=True) if len(frames) > 1 else frames[0]
    return df.drop_duplicates("key", keep="last").reset_index(drop=True)


def _read_table(path: Path) -> pd.DataFrame:
    if path.suffix == ".parquet":
        return pd.read_parquet(path)
    return pd.read_csv(path)


def _write_table(df: pd.DataFrame, path: Path) -> None:
    path.parent.mkdir(parents=True, exist_ok=True)
    tmp = path.with_name(f".{path.name}.tmp{os.getpid()}")
    if path.suffix == ".parquet":
        df.to_parquet(tmp, index=False)
    else:
        df.to_csv(tmp, index=False)
    os.replace(tmp, path)


SWEEP_COLUMNS = ("key", "status")  # every sweep file has them


def check_table(path, what: str = "--out") -> pd.DataFrame:
    """The rows of an existing sweep file, or InputError (one line naming ``what`` and the
    path) when it cannot be read or is not a sweep file (no ``key`` / ``status`` column)."""
    path = Path(path)
    if path.is_dir():
        raise InputError(f"{what} {str(path)!r}: is a directory; allowed: a .parquet or .csv file")
    try:
        df = _read_table(path)
    except pd.errors.EmptyDataError:
        raise InputError(f"{what} {str(path)!r}: the file is empty, not a sweep file") from None
    except PermissionError:
        raise InputError(f"{what} {str(path)!r}: the file cannot be read (permission "
                         "denied)") from None
    except Exception as exc:  # noqa: BLE001 - pyarrow / parser errors: not the format
        kind = "Parquet" if path.suffix == ".parquet" else "CSV"
        first = str(exc).strip().splitlines()[0] if str(exc).strip() else type(exc).__name__
        raise InputError(f"{what} {str(path)!r}: not a readable {kind} file ({first[:200]})") from None
    missing = [c for c in SWEEP_COLUMNS if c not in df]
    if missing:
        raise InputError(f"{what} {str(path)!r}: not a sweep file (no {', '.join(missing)} "
                         f"column{'s' if len(missing) > 1 else ''}); allowed: a file written by "
                         "`ancf sweep`" + (", or a new file name" if what == "--out" else ""))
    return df


def _check_out(out) -> Path:
    """``out`` as a Path, checked before any run: its suffix, a writable place for it
    (every existing ancestor a directory, the nearest one writable) and, when it exists, a
    readable sweep file of the same format.  Errors: one line naming the path."""
    out = Path(out)
    if out.suffix not in (".parquet", ".csv"):
        raise InputError(f"--out {str(out)!r}: the file name must end in .parquet or .csv")
    parent = out.parent if str(out.parent) else Path(".")
    anc = parent
    while not anc.exists():
        if anc.is_symlink() or anc == anc.parent:
            break
        anc = anc.parent
    if anc.exists() and not anc.is_dir():
        raise InputError(f"--out {str(out)!r}: {str(anc)!r} is a file, not a directory")
    if not anc.exists():
        raise InputError(f"--out {str(out)!r}: no existing directory to create it in")
    try:  # a real write, not os.access: root, read-only mounts and /proc answer honestly
        parent.mkdir(parents=True, exist_ok=True)
        fd, probe = tempfile.mkstemp(prefix=f".{out.name}.", suffix=".probe", dir=parent)
        os.close(fd)
        os.unlink(probe)
    except OSError as exc:
        raise InputError(f"--out {str(out)!r}: cannot write in {str(parent)!r} "
                         f"({exc.strerror or exc})") from None
    if out.exists() or out.is_symlink():
        if out.is_dir():
            raise InputError(f"--out {str(out)!r}: is a directory; allowed: a .parquet or .csv "
                             "file")
        if not os.access(out, os.W_OK) and os.access(out, os.F_OK):
            raise InputError(f"--out {str(out)!r}: the file is not writable")
        check_table(out, "--out")
    return out


_FRONT = ("key", "scene")
_BACK = ("status", "converged", "message", "error", "reference", "cpu_time_s", "compile_cpu_s",
         "wall_time_s", "steps", "iterations", "work", "session")


def _with_work(df: pd.DataFrame) -> pd.DataFrame:
    """``df`` with its ``work`` column (re)computed from each row's parameters and counters
    (:func:`ancf.study.cost.with_work` also adds a column per counted feature)."""
    return df.assign(work=[work(row_counts(r)) for _, r in df.iterrows()])


def summary(df: pd.DataFrame, scene: str, out, seconds: float, session: str) -> str:
    """The closing line of a sweep: rows, converged, not converged, failed, time."""
    st = df["status"].value_counts().to_dict() if len(df) else {}
    failed = {k: v for k, v in st.items() if k not in ("ok", "not-converged")}
    mine = df[df["session"] == session] if "session" in df else df.iloc[0:0]
    cpu = float(pd.to_numeric(mine["cpu_time_s"], errors="coerce").sum()) if len(mine) else 0.0
    kinds = f" ({', '.join(f'{k} {v}' for k, v in failed.items())})" if failed else ""
    return (f"sweep {scene}: {len(df)} rows in {out}: {st.get('ok', 0)} converged, "
            f"{st.get('not-converged', 0)} not converged, {sum(failed.values())} failed{kinds}; "
            f"{len(mine)} run now in {seconds:.1f} s wall ({cpu:.2f} s CPU in the runs)")


def _order(df: pd.DataFrame, param_names, keys_in_order) -> pd.DataFrame:
    rank = {k: i for i, k in enumerate(keys_in_order)}
    df = df.assign(_o=df["key"].map(lambda k: rank.get(k, len(rank))))
    df = df.sort_values("_o", kind="stable").drop(columns="_o").reset_index(drop=True)
    cols = [c for c in _FRONT if c in df] + [c for c in param_names if c in df]
    cols += [c for c in _BACK if c in df]
    cols += sorted(c for c in df.columns if c not in cols)
    df = df[cols]
    for c in ("converged",):
        df[c] = df[c].astype(bool)
    for c in ("error", "cpu_time_s", "compile_cpu_s", "wall_time_s", "work"):
        if c not in df:  # rows written before the column existed
            df[c] = float("nan")
        df[c] = pd.to_numeric(df[c], errors="coerce").astype(float)
    return df


# ---------------------------------------------------------------------------------------
# driver
# ---------------------------------------------------------------------------------------

def run_sweep(scene: str, grids=None, *, out, fixed: dict | None = None,
              reference: str | None = None, workers: int | None = None, scheduler=None,
              time_limit: float = 600.0, retry_failed: bool = False, progress: bool = True,
              log=None, quantity: str = "results") -> pd.DataFrame:
    """Run (or resume) a sweep; returns every row of ``out`` (this grid's first, in grid
    order).  ``grids``: dict or list of dicts {param: [values]} (default: the scene's
    report grid); ``fixed``: overrides applied to every run; ``scheduler``: a Dask
    scheduler address (or a ``distributed.Client``) instead of local processes;
    ``quantity``: ``results`` (the scene's runs) or ``frequency`` (its ``ancf modes`` about
    the reference against the frequency references, :mod:`ancf.study.references`)."""
    from ancf.scenes import SCENES
    if scene not in SCENES:
        raise InputError(f"scene: unknown name {scene!r}; allowed: {', '.join(SCENES)}")
    if not time_limit > 0:
        raise InputError(f"time_limit = {time_limit!r} is out of range; allowed: a number > 0")
    out = _check_out(out)
    s = spec(scene, quantity)
    if grids is None:  # the scene's report grid, for this problem where it depends on it
        grids = s.grids(SCENES[scene].resolve(fixed) if s.grids_for else None, "report")
    ref = s.reference(reference)
    log = log or (lambda msg: print(msg, file=sys.stderr, flush=True))
    tasks = make_tasks(scene, expand(grids, fixed), ref.name, quantity)
    if tasks and all(t.get("invalid") for t in tasks):  # nothing to run: bad input, not rows
        raise InputError(tasks[0]["invalid"])
    keys = [t["key"] for t in tasks]

    have = read_rows(out)
    if len(have) and "reference" in have:
        other = set(have["reference"].dropna().astype(str)) - {ref.name}
        if other:
            raise InputError(f"reference: {out} holds errors against {', '.join(sorted(other))}, "
                             f"not {ref.name!r}; use that reference or another --out file")
    done = set()
    if len(have):
        ok = ~have["status"].isin(RETRY) if retry_failed else pd.Series(True, index=have.index)
        done = set(have.loc[ok, "key"])
    todo = [t for t in tasks if t["key"] not in done]
    n_done = len(tasks) - len(todo)
    where = f"Dask scheduler {scheduler}" if scheduler is not None else \
        f"{workers or os.cpu_count()} worker process(es)"
    log(f"sweep {scene}: {len(tasks)} runs, {n_done} already in {out.name}, {len(todo)} to run "
        f"on {where}; reference {ref.name}; time limit {time_limit:g} s per run")

    t_start = time.perf_counter()
    session = f"{time.strftime('%Y%m%dT%H%M%S')}-{os.getpid()}"
    jp = journal_path(out)
    jp.parent.mkdir(parents=True, exist_ok=True)
    gen = None
    try:
        if todo:
            if scheduler is not None:
                gen = _run_dask(todo, scheduler, time_limit)
            else:
                gen = _run_local(todo, workers or os.cpu_count() or 1, time_limit)
            bar = _bar(len(todo), scene, progress)
            stop = _interrupt_after()
            with open(jp, "a") as journal:
                for n, row in enumerate(gen, 1):
                    row["session"] = session
                    journal.write(json.dumps(row) + "\n")
                    journal.flush()
                    bar.update(1)
                    if n == stop:  # a Ctrl-C after exactly `stop` rows (tests, demos)
                        os.kill(os.getpid(), signal.SIGINT)
            bar.close()
    finally:
        if gen is not None:
            gen.close()
        df = read_rows(out)
        if len(df):
            df = _order(_with_work(df), [p.name for p in runner(scene, quantity).params], keys)
            _write_table(df, out)
        if jp.exists():
            jp.unlink()
    log(summary(df, scene, out, time.perf_counter() - t_start, session))
    return df


INTERRUPT_ENV = "ANCF_SWEEP_INTERRUPT_AFTER"


def _interrupt_after() -> int | None:
    """``ANCF_SWEEP_INTERRUPT_AFTER=N``: the driver sends itself SIGINT (as Ctrl-C does)
    once N rows of this call are journaled, so an interrupted sweep is reproducible
    without timing; unset (or not a positive integer): never."""
    v = os.environ.get(INTERRUPT_ENV, "")
    return int(v) if v.isdigit() and int(v) > 0 else None


class _NoBar:
    def update(self, n):
        pass

    def close(self):
        pass


def _bar(total: int, desc: str, enabled: bool):
    if not enabled:
        return _NoBar()
    try:
        from tqdm import tqdm
    except ImportError:  # pragma: no cover - tqdm is a dependency
        return _Counter(total, desc)
    tqdm.monitor_interval = 0
    return tqdm(total=total, desc=desc, file=sys.stderr, unit="run", dynamic_ncols=True)


class _Counter:
    def __init__(self, total, desc):
        self.total, self.desc, self.n = total, desc, 0

    def update(self, n):
        self.n += n
        print(f"\r{self.desc}: {self.n}/{self.total}", end="", file=sys.stderr, flush=True)

    def close(self):
        print(file=sys.stderr)


def rows_for(df: pd.DataFrame, scene: str, physical: dict) -> pd.DataFrame:
    """Rows of ``df`` whose physical parameters equal ``physical``."""
    m = pd.Series(True, index=df.index)
    for k, v in physical.items():
        if k not in df:
            return df.iloc[0:0]
        col = df[k]
        if v is None:  # a parameter computed by the scene (stored as null)
            m &= col.isna()
        elif isinstance(v, float):
            m &= np.isclose(pd.to_numeric(col, errors="coerce"), v, rtol=1e-12, atol=0)
        else:
            m &= col.astype(str) == str(v)
    return df[m]


if __name__ == "__main__":
    if sys.argv[1:] == ["--worker"]:
        raise SystemExit(_worker_main())
    raise SystemExit("usage: python -m ancf.study.sweep --worker (internal); see `ancf sweep --help`")
