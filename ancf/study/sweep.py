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
* bounded up front: the run count is logged before any run is resolved; more than
  :data:`MAX_RUNS` runs are refused (the count and the least time in one line) and more
  workers than cores capped (a ``warning:``), both unless ``force``; a parameter both in
  the grid and fixed with other values, or ``workers`` beside ``scheduler``, is refused;
* ``scheduler=ADDRESS`` runs the same tasks on a Dask cluster (dask.distributed); each
  Dask worker thread drives one such worker process, so time limits, isolation and
  the numbers are the same as on one machine.
"""
from __future__ import annotations

import json
import math
import os
import signal
import sys
import time

import pandas as pd

from ancf.common.inputs import flag, mapping, number, path, text
from ancf.common.params import InputError
from ancf.study.references import runner, spec
from ancf.study.sweep_files import (_check_out, _order, _with_work, _write_table, check_table,
                                    journal_path, read_rows, rows_for, summary)
from ancf.study.sweep_pool import _run_local
from ancf.study.sweep_tasks import expand, make_tasks, parse_grid

STATUSES = ("ok", "not-converged", "failed", "timeout", "invalid", "worker-died")
RETRY = ("failed", "timeout", "worker-died")
SUCCEEDED = ("ok",)  # converged runs with their error: a sweep of none exits 3

#: the names other modules import from here (the sweep's tasks and files)
__all__ = ["STATUSES", "RETRY", "check_table", "expand", "journal_path", "parse_grid",
           "read_rows", "rows_for", "run_sweep"]


#: the most runs a sweep starts without ``force`` (``ancf sweep --force``): the cheapest
#: run measured costs the machine MIN_RUN_CPU_S (a worker's run, its row and the driver's
#: journal; the runs themselves take far less), so 100 000 runs are some 5.6 CPU hours,
#: about 3 hours on 2 cores, and a table of some 100 MB: more is rarely meant
MAX_RUNS = 100_000
#: CPU seconds per run of the cheapest sweep (axial-bar, 200 runs on 2 workers: 43 s
#: of CPU in all on the development machine): a lower bound of any sweep's time
MIN_RUN_CPU_S = 0.2


def available_cores() -> int:
    """The cores this process may run on (its CPU affinity, else the machine's count)."""
    try:
        return max(len(os.sched_getaffinity(0)), 1)
    except (AttributeError, OSError):
        return os.cpu_count() or 1


def count_runs(grids) -> int:
    """The runs of ``grids`` (a dict or a list of dicts {param: [values]}) before any is
    resolved: the sum of each grid's product (an upper bound where grids overlap)."""
    return sum(math.prod(len(v) for v in g.values()) for g in
               ([grids] if isinstance(grids, dict) else grids))


def _hours(runs: int, workers: int) -> str:
    """The least time ``runs`` can take on ``workers`` processes, as words."""
    s = runs * MIN_RUN_CPU_S / max(workers, 1)
    return f"{s / 3600:.3g} h" if s >= 3600 else f"{s:.3g} s"


def check_size(runs: int, workers: int, force: bool) -> None:
    """InputError above MAX_RUNS runs, unless ``force``: the count and the least time."""
    if runs > MAX_RUNS and not force:
        raise InputError(f"sweep: {runs} runs (at least {_hours(runs, workers)} on {workers} "
                         f"worker(s), {MIN_RUN_CPU_S:g} s CPU per run at the cheapest) is above "
                         f"{MAX_RUNS}; allowed: at most {MAX_RUNS} runs (fewer --grid values), "
                         "or --force (force=True) to run them")


def check_workers(workers, scheduler, force: bool, log) -> int:
    """The local worker count: ``workers`` (default: the cores), capped at the cores this
    process may use with a ``warning:`` unless ``force``; InputError for a count that is
    not a positive integer, or for ``workers`` beside ``scheduler`` (which would ignore it)."""
    cores = available_cores()
    if workers is None:
        return cores
    workers = number("workers", workers, lo=1, lo_open=False, integer=True)
    if scheduler is not None:
        raise InputError(f"workers = {workers} and scheduler: both given; allowed: one of "
                         "them (a Dask scheduler runs the sweep on its own workers)")
    if workers > cores and not force:
        log(f"warning: workers = {workers} is above the {cores} core(s) this process may use; "
            f"starting {cores} (--force, force=True: start {workers})")
        return cores
    return workers


def check_overlap(scene: str, grids, fixed: dict | None, quantity: str) -> None:
    """A parameter both in a grid and in ``fixed`` with other values than the grid's single
    one is a conflict (InputError naming it), not the grid silently winning."""
    params = {p.name: p for p in runner(scene, quantity).params}
    for g in ([grids] if isinstance(grids, dict) else grids):
        for k in set(g) & set(fixed or {}):
            value = params[k].parse(fixed[k]) if k in params else fixed[k]
            if list(g[k]) != [value]:
                raise InputError(f"{k}: given in the grid ({', '.join(map(str, g[k]))}) and "
                                 f"fixed (--set {k}={fixed[k]}); allowed: one of them")


def _check_args(scene, out, reference, scheduler, time_limit, retry_failed, progress, log,
                force) -> None:
    """The arguments of :func:`run_sweep` that are not the grid, as the command line's."""
    from ancf.scenes import SCENES
    if not isinstance(scene, str) or scene not in SCENES:
        raise InputError(f"scene: unknown name {scene!r}; allowed: {', '.join(SCENES)}")
    path("out", out)
    if reference is not None:
        text("reference", reference, "a reference name (see `ancf analytic`) or None")
    if scheduler is not None and not hasattr(scheduler, "submit"):
        text("scheduler", scheduler, "a Dask scheduler address (tcp://HOST:PORT), a "
             "distributed.Client, or None")
    number("time_limit", time_limit)
    flag("retry_failed", retry_failed)
    flag("progress", progress)
    flag("force", force)
    if log is not None and not callable(log):
        raise InputError(f"log: {log!r} is not valid; allowed: a function of one line, or None")


def run_sweep(scene: str, grids=None, *, out, fixed: dict | None = None,
              reference: str | None = None, workers: int | None = None, scheduler=None,
              time_limit: float = 600.0, retry_failed: bool = False, progress: bool = True,
              log=None, quantity: str = "results", force: bool = False) -> pd.DataFrame:
    """Run (or resume) a sweep; returns every row of ``out`` (this grid's first, in grid
    order).  ``grids``: dict or list of dicts {param: [values]} (default: the scene's
    report grid); ``fixed``: overrides applied to every run; ``scheduler``: a Dask
    scheduler address (or a ``distributed.Client``) instead of local processes;
    ``quantity``: ``results`` (the scene's runs) or ``frequency`` (its ``ancf modes`` about
    the reference against the frequency references, :mod:`ancf.study.references`).

    Bounded up front: the run count is logged at once; more than :data:`MAX_RUNS` runs,
    or more ``workers`` than cores (capped, with a ``warning:``), only with ``force``.
    ``df.attrs["sweep"]`` holds this call's counts: ``runs``, ``succeeded`` (status ``ok``:
    converged, with its error), ``lost_workers`` and ``retried_runs`` (a Dask worker lost mid-run: the
    scheduler ran its tasks again)."""
    from ancf.scenes import SCENES
    _check_args(scene, out, reference, scheduler, time_limit, retry_failed, progress, log,
                force)
    log = log or (lambda msg: print(msg, file=sys.stderr, flush=True))
    fixed = mapping("fixed", fixed)
    out = _check_out(out)
    s = spec(scene, quantity)
    if grids is None:  # the scene's report grid, for this problem where it depends on it
        grids = s.grids(SCENES[scene].resolve(fixed) if s.grids_for else None, "report")
    workers = check_workers(workers, scheduler, force, log)
    n_runs = count_runs(grids)
    check_size(n_runs, workers, force)
    check_overlap(scene, grids, fixed, quantity)
    log(f"sweep {scene}: {n_runs} runs in the grid; checking them before the start")
    ref = s.reference(reference)
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
        f"{workers} worker process(es)"
    log(f"sweep {scene}: {len(tasks)} runs, {n_done} already in {out.name}, {len(todo)} to run "
        f"on {where}; reference {ref.name}; time limit {time_limit:g} s per run")

    t_start = time.perf_counter()
    session = f"{time.strftime('%Y%m%dT%H%M%S')}-{os.getpid()}"
    jp = journal_path(out)
    jp.parent.mkdir(parents=True, exist_ok=True)
    gen = None
    lost = {}  # the Dask run's lost workers and retried runs (sweep_dask.lost_and_retried)
    try:
        if todo:
            if scheduler is not None:
                from ancf.study.sweep_dask import _run_dask
                gen = _run_dask(todo, scheduler, time_limit, lost)
            else:
                gen = _run_local(todo, workers, time_limit)
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
    mine = df[df["key"].isin(keys)] if len(df) else df
    ok = int(mine["status"].isin(SUCCEEDED).sum()) if len(mine) else 0
    df.attrs["sweep"] = {"runs": len(keys), "succeeded": ok,
                         "lost_workers": lost.get("lost_workers", 0),
                         "retried_runs": lost.get("retried_runs", 0)}
    log(summary(df, scene, out, time.perf_counter() - t_start, session, lost))
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

