"""The local pool of a sweep (:mod:`ancf.study.sweep`): worker processes
(``python -m ancf.study.sweep_pool --worker``) that run one task at a time on a line
protocol, each killed at its CPU time limit (the clock stopped while it compiles or loads
numba kernels), a pilot that runs first on an empty kernel cache, and the idle workers
of a finished sweep parked for the next one of the same process.
"""
from __future__ import annotations

import atexit
import json
import os
import selectors
import signal
import subprocess
import sys
import tempfile
import threading
import time
from collections import deque

from ancf.common.paths import REPO
from ancf.common.threads import BLAS_ENV
from ancf.study.sweep_tasks import failure_row, run_case

COMPILE_LIMIT = 1800.0  # s of wall time one compilation (or cache load) of a kernel may take
HANG_FACTOR = 10.0      # wall time beyond this many times the (CPU) time limit: a hang
PILOT_CPU = 2.0  # s of its first run's CPU (compiling left out) before the pilot's peers start
_ENV = {**BLAS_ENV, "PYTHONWARNINGS": "ignore"}


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
    """``python -m ancf.study.sweep_pool --worker``: read tasks (JSON lines) on stdin, write rows on
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
    """One worker process (``python -m ancf.study.sweep_pool --worker``) and its line protocol."""

    def __init__(self, env: dict | None = None):
        self.err = tempfile.TemporaryFile()
        self.env = _runner_env() if env is None else env
        self.proc = subprocess.Popen([sys.executable, "-m", "ancf.study.sweep_pool", "--worker"],
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



if __name__ == "__main__":
    if sys.argv[1:] == ["--worker"]:
        raise SystemExit(_worker_main())
    raise SystemExit("usage: python -m ancf.study.sweep_pool --worker (internal); see "
                     "`ancf sweep --help`")
