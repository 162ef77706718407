"""Sweeps (issue 4, part 1): parallel, resumable, failures recorded, same numbers on Dask.

Acceptance: a >= 100-run cantilever sweep with 2 workers, interrupted and resumed
without recomputing finished rows, and the same sweep through a local Dask cluster
with identical results.
"""
import json
import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import numpy as np
import pandas as pd
import pytest

from ancf.cli import main
from ancf.common.params import InputError
from ancf.study.cost import with_work
from ancf.study.sweep import expand, journal_path, parse_grid, read_rows, run_sweep
from ancf.study.sweep_tasks import make_tasks

# 2 elements x 2 schemes x 8 element counts x 2 heights x 2 Poisson ratios = 128 runs
GRID = ["element=linear,omar-shabana", "integration=thesis,exact", "n_elements=1,2,3,4,5,6,7,8",
        "h=0.1,0.5", "nu=0,0.3"]
N_RUNS = 128
SAME = ["key", "element", "integration", "n_elements", "h", "nu", "F", "status", "converged",
        "error", "res_tip_x", "res_tip_y", "res_newton_iterations", "steps"]


def _cli(*argv, **env_extra):
    """The CLI in a process whose Ctrl-C is Python's, even where this one ignores SIGINT (a
    shell's background job does: Python then never turns SIGINT into KeyboardInterrupt)."""
    env = dict(os.environ, **env_extra)
    return subprocess.Popen([sys.executable, "-m", "ancf.cli", *argv], stdout=subprocess.PIPE,
                            stderr=subprocess.PIPE, text=True, env=env,
                            preexec_fn=lambda: signal.signal(signal.SIGINT, signal.SIG_DFL))


@pytest.fixture(scope="module")
def interrupted_and_resumed(workdir):
    """Start the CLI sweep with 2 workers, interrupted (SIGINT, sent by the driver to
    itself: ANCF_SWEEP_INTERRUPT_AFTER) once exactly 30 rows are journaled, whatever the
    timing, then resume it; returns (rows kept from before the interrupt, final frame,
    stderr, summary, seconds)."""
    out = workdir / "cantilever.parquet"
    argv = ["sweep", "cantilever", *sum((["--grid", g] for g in GRID), []), "--workers", "2",
            "--out", str(out)]
    p = _cli(*argv, ANCF_SWEEP_INTERRUPT_AFTER="30")
    _, stderr = p.communicate(timeout=300)  # a hang guard, not a timing
    assert p.returncode == 130 and "interrupted: the finished rows are in" in stderr, stderr
    before = read_rows(out)
    assert len(before) == 30, "the interrupt lands after exactly 30 rows"
    assert not journal_path(out).exists()  # folded into the file
    t0 = time.time()
    p = _cli(*argv, "--json")
    stdout, stderr = p.communicate(timeout=120)
    assert p.returncode == 0, stderr
    final = pd.read_parquet(out)
    return before, final, stderr, json.loads(stdout), time.time() - t0


@pytest.mark.slow
def test_sweep_interrupted_and_resumed_without_recomputing(interrupted_and_resumed):
    before, final, stderr, summary, _ = interrupted_and_resumed
    assert summary["rows"] == N_RUNS and summary["status"] == {"ok": N_RUNS}
    assert len(final) == N_RUNS and final["key"].is_unique
    assert f"{len(before)} already in" in stderr and f"{N_RUNS - len(before)} to run" in stderr
    # the rows finished before the interrupt are the same rows, not recomputed
    old = final.set_index("key").loc[before["key"]]
    assert (old["session"].values == before["session"].values).all()
    assert np.array_equal(old["cpu_time_s"].values, before["cpu_time_s"].astype(float).values)
    assert final["session"].nunique() == 2
    assert not journal_path(Path(summary["out"])).exists()
    # parameters as columns, results and the error against the reference
    for col in ("element", "integration", "n_elements", "E", "nu", "h", "F", "converged",
                "cpu_time_s", "steps", "error", "res_tip_x", "res_tip_y", "message"):
        assert col in final
    assert (final["reference"] == "reissner").all()
    assert final["error"].between(0, 1.5).all()
    # the counted work recommend ranks by, one per row, and the closing line on stderr
    assert np.array_equal(final["work"].values, with_work(final.drop(columns="work"))["work"].values)
    assert np.isfinite(final["work"]).all() and final["work"].nunique() > N_RUNS // 4
    assert (final["compile_cpu_s"] >= 0).all()
    last = stderr.strip().splitlines()[-1]
    assert last.startswith(f"sweep cantilever: {N_RUNS} rows in ")
    assert (f": {N_RUNS} converged, 0 not converged, 0 failed; {N_RUNS - len(before)} run now in "
            in last), last


@pytest.mark.slow
def test_resume_of_a_finished_sweep_runs_nothing(workdir, interrupted_and_resumed):
    out = workdir / "cantilever.parquet"
    msgs = []
    df = run_sweep("cantilever", parse_grid("cantilever", GRID), out=out, workers=2,
                   progress=False, log=msgs.append)
    assert f"{N_RUNS} already in" in msgs[1] and "0 to run" in msgs[1]
    assert len(df) == N_RUNS


@pytest.mark.slow
def test_same_sweep_on_a_local_dask_cluster_gives_identical_results(workdir,
                                                                    interrupted_and_resumed):
    from distributed import LocalCluster
    local = interrupted_and_resumed[1]
    with LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                      dashboard_address=None) as cluster:
        out = workdir / "dask.csv"  # CSV this time: pandas reads both
        p = _cli("sweep", "cantilever", *sum((["--grid", g] for g in GRID), []),
                 "--scheduler", cluster.scheduler_address, "--out", str(out), "--no-progress")
        _, stderr = p.communicate(timeout=180)
        assert p.returncode == 0, stderr
    dask = pd.read_csv(out)
    assert len(dask) == N_RUNS
    a = local[SAME].sort_values("key").reset_index(drop=True)
    b = dask[SAME].sort_values("key").reset_index(drop=True)
    pd.testing.assert_frame_equal(a, b, check_dtype=False, check_exact=True)


@pytest.mark.slow
def test_failures_are_rows_and_do_not_stop_the_others(workdir):
    out = workdir / "failures.csv"
    grids = [{"n_elements": [1, 4]},                                   # fine
             {"element": ["omar-shabana"], "integration": ["report-fix"]},  # invalid pair
             {"n_elements": [4096], "element": ["omar-shabana"], "stability_check": ["off"]},
             {"F": [-5e6], "load_steps": [1], "max_iterations": [1]}]  # cannot converge
    msgs = []
    df = run_sweep("cantilever", grids, out=out, workers=2, time_limit=0.5, progress=False,
                   log=msgs.append)
    assert ": 2 converged, 1 not converged, 2 failed (" in msgs[-1]
    assert "invalid 1" in msgs[-1] and "timeout 1" in msgs[-1] and "; 5 run now in" in msgs[-1]
    by = {(r["element"], r["integration"], r["n_elements"], r["max_iterations"]): r
          for _, r in df.iterrows()}
    assert len(df) == 5
    assert by[("linear", "thesis", 1, 25)]["status"] == "ok"
    assert by[("linear", "thesis", 4, 25)]["status"] == "ok"
    inv = df[df["status"] == "invalid"]
    assert len(inv) == 1 and "integration" in inv["message"].iloc[0]
    slow = df[df["status"] == "timeout"]
    assert len(slow) == 1 and slow["message"].iloc[0] == "time limit exceeded (0.5 s)"
    nc = df[df["status"] == "not-converged"]
    assert len(nc) == 1 and "No convergence" in nc["message"].iloc[0]
    assert df.loc[df["status"] != "ok", "error"].isna().all()
    assert df.loc[df["status"].isin(["invalid", "timeout"]), "work"].isna().all()  # no counters
    assert (df.loc[df["status"].isin(["ok", "not-converged"]), "work"] > 0).all()
    # a rerun skips every recorded row, failures included, unless asked to retry them
    msgs = []
    run_sweep("cantilever", grids, out=out, workers=1, time_limit=0.5, progress=False,
              log=msgs.append)
    assert "5 already in" in msgs[1]
    msgs = []
    run_sweep("cantilever", grids, out=out, workers=1, time_limit=0.5, progress=False,
              log=msgs.append, retry_failed=True)
    assert "1 to run" in msgs[1]  # only the timeout is a retryable failure


def test_grid_parsing_and_expansion():
    g = parse_grid("cantilever", ["n_elements=2,4.0,2", "integration=thesis;normal=2x2,shear=1x1"])
    assert g == {"n_elements": [2, 4], "integration": ["thesis", "normal=2x2,shear=1x1"]}
    assert len(expand([{"a": [1, 2], "b": [3]}, {"a": [1], "b": [3, 4]}])) == 3
    for bad in (["n_elements=0"], ["nope=1"], ["h=abc"], ["n_elements"]):
        with pytest.raises(InputError):
            parse_grid("cantilever", bad)


def test_cli_sweep_bad_input_exits_2(capsys, tmp_path):
    assert main(["sweep", "cantilever", "--grid", "nu=0.7", "--out", str(tmp_path / "x.csv")]) == 2
    assert "nu" in capsys.readouterr().err
    assert main(["sweep", "cantilever", "--grid", "nu=0", "--out", str(tmp_path / "x.txt")]) == 2
    assert main(["sweep", "cantilever", "--grid", "nu=0", "--reference", "nope",
                 "--out", str(tmp_path / "x.csv")]) == 2


def _children(pid):
    """Pids of the live (not zombie) processes whose parent is ``pid`` (Linux /proc)."""
    out = []
    for d in Path("/proc").iterdir():
        if d.name.isdigit():
            try:
                stat = (d / "stat").read_text()
            except OSError:
                continue
            fields = stat.rsplit(")", 1)[1].split()
            if fields[0] != "Z" and int(fields[1]) == pid:
                out.append(int(d.name))
    return out


def _alive(pid):
    try:
        stat = Path(f"/proc/{pid}/stat").read_text()
    except OSError:
        return False
    return stat.rsplit(")", 1)[1].split()[0] != "Z"


# A driver that starts one sweep worker, hands it a run of about an hour (10^7
# generalized-alpha steps of a 128-element pendulum; no reference computed), says the
# worker's pid, and waits to be killed.
_DRIVER = """
import time
from ancf.scenes import SCENES
from ancf.study.sweep_pool import _Runner
p = SCENES["pendulum"].resolve({"integrator": "generalized-alpha", "dt": "1e-6",
                                "t_end": "10", "n_elements": "128"})
task = {"index": 0, "scene": "pendulum", "reference": "none", "ref_values": None,
        "ref_error": "not computed", "params": p, "key": "long"}
r = _Runner()
r.wait_ready()
r.send(task)
print(r.proc.pid, flush=True)
time.sleep(600)
"""


@pytest.mark.slow
@pytest.mark.skipif(not Path("/proc/self/stat").exists(), reason="needs Linux /proc")
@pytest.mark.parametrize("pdeathsig", ["1", "0"])  # "0": the watchdog thread alone
def test_a_computing_worker_ends_when_its_driver_is_killed(pdeathsig):
    """SIGKILL the driver while its worker is inside a run of hours: the worker is gone
    within a bounded wait (polled, 20 s at most; the watchdog polls every 0.5 s).  Its
    stdin's end of file alone would not stop it before the run ends."""
    env = dict(os.environ, ANCF_SWEEP_PDEATHSIG=pdeathsig)
    p = subprocess.Popen([sys.executable, "-c", _DRIVER], stdout=subprocess.PIPE,
                         stderr=subprocess.DEVNULL, text=True, env=env)
    try:
        worker = int(p.stdout.readline())  # hang guard: the suite's own timeout
        time.sleep(1.0)  # the task is in the worker's pipe; let it start computing
        assert _alive(worker) and _children(p.pid) == [worker]
        p.send_signal(signal.SIGKILL)
        p.wait(timeout=30)
        for _ in range(200):
            if not _alive(worker):
                break
            time.sleep(0.1)
        alive = _alive(worker)
        if alive:  # do not leave it behind when the test fails
            os.kill(worker, signal.SIGKILL)
        assert not alive, "the worker outlived its driver"
    finally:
        if p.poll() is None:
            p.kill()
            p.wait()


@pytest.mark.slow
@pytest.mark.skipif(not Path("/proc/self/stat").exists(), reason="needs Linux /proc")
def test_sweep_workers_end_when_the_cli_is_killed(tmp_path):
    """The user's report: SIGKILL `ancf sweep` mid-sweep: both its workers are gone within
    a bounded wait."""
    out = tmp_path / "killed.csv"
    p = subprocess.Popen([sys.executable, "-m", "ancf.cli", "sweep", "cantilever",
                          *sum((["--grid", g] for g in GRID), []), "--workers", "2",
                          "--out", str(out), "--no-progress"],
                         stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    try:
        jp = journal_path(out)
        for _ in range(1200):  # until both workers run and a row is done (hang guard only)
            workers = _children(p.pid)
            if len(workers) == 2 and jp.exists() and jp.read_text().strip():
                break
            assert p.poll() is None, "the sweep ended before it could be killed"
            time.sleep(0.1)
        else:
            pytest.fail("the sweep did not start its workers")
        p.send_signal(signal.SIGKILL)
        p.wait(timeout=30)
        for _ in range(200):
            if not any(_alive(w) for w in workers):
                break
            time.sleep(0.1)
        left = [w for w in workers if _alive(w)]
        for w in left:
            os.kill(w, signal.SIGKILL)
        assert not left, f"workers {left} outlived their driver"
    finally:
        if p.poll() is None:
            p.kill()
            p.wait()


def test_the_time_limit_counts_cpu_without_compilation(monkeypatch):
    """A run's clock is its worker's CPU time, and it stops while the worker compiles or
    loads numba kernels: an empty kernel cache on a loaded machine took 205 s for two
    120 s-limited belt runs whose solves take seconds, and at a load of 10 the 40-plate
    belt3d runs (120 s CPU) took over their 300 s wall.  The worker says when it compiles."""
    import io
    import numba
    from ancf.study import sweep_pool as sweep

    wall, cpu = [100.0], [7.0]
    monkeypatch.setattr(sweep.time, "monotonic", lambda: wall[0])
    monkeypatch.setattr(sweep, "process_cpu", lambda pid: cpu[0])
    clock = sweep._RunClock(pid=0)
    wall[0], cpu[0] = 101.0, 7.5
    clock.note(True)                           # compiling from here ...
    wall[0], cpu[0] = 150.0, 40.0
    assert clock.expired(1.0) is None          # ... no time limit while compiling
    clock.note(False)                          # ... to here: 49 s wall, 32.5 s CPU
    assert clock.cpu() == 0.5 and clock.wall() == 1.0
    wall[0] = 155.0                            # a loaded machine: 6 s wall, 0.5 s CPU
    assert clock.expired(1.0) is None and clock.wait(1.0) == 0.5
    cpu[0] = 40.6
    assert clock.expired(1.0) == "1 s"
    cpu[0], wall[0] = 40.0, 160.1              # 11 s wall without CPU: a hang
    assert clock.expired(1.0) == "1 s; 10 times that in wall time"
    monkeypatch.undo()

    import os
    assert sweep.process_cpu(os.getpid()) > 0  # this platform's /proc is read
    out = io.StringIO()
    listener = sweep._announce_compiles(out)

    @numba.njit
    def fresh(x):
        return x + 1

    try:
        fresh(1)
        fresh(2)  # compiled once: one span
    finally:
        numba.core.event.unregister("numba:compiler_lock", listener)
    assert [json.loads(line) for line in out.getvalue().splitlines()] == [
        {"compiling": True}, {"compiling": False}]


def test_the_other_workers_take_runs_after_the_pilot_compiled(monkeypatch):
    """Workers running together on an empty kernel cache each compile the same kernels: the
    pilot runs alone, the others take runs once it returned a row, died, or ran PILOT_CPU
    seconds of its first run outside compilation."""
    from types import SimpleNamespace
    from ancf.study import sweep_pool as sweep

    wall, cpu = [0.0], [0.0]
    monkeypatch.setattr(sweep.time, "monotonic", lambda: wall[0])
    monkeypatch.setattr(sweep, "process_cpu", lambda pid: cpu[0])
    alive = SimpleNamespace(poll=lambda: None)
    pilot = SimpleNamespace(proc=alive, clock=None)
    assert not sweep._pilot_done(pilot, 0)        # starting up: no run yet
    pilot.clock = sweep._RunClock(pid=0)
    pilot.clock.note(True)
    wall[0], cpu[0] = 60.0, 60.0                  # a minute of compiling
    assert not sweep._pilot_done(pilot, 0)
    pilot.clock.note(False)
    cpu[0] = 60.0 + 0.9 * sweep.PILOT_CPU
    assert not sweep._pilot_done(pilot, 0)
    cpu[0] = 60.0 + sweep.PILOT_CPU
    assert sweep._pilot_done(pilot, 0)            # its kernels are in the cache by now
    pilot.clock = None
    assert sweep._pilot_done(pilot, 1)            # a row came back
    pilot.proc = SimpleNamespace(poll=lambda: -9)
    assert sweep._pilot_done(pilot, 0)            # it died: the others go on without it


@pytest.mark.slow
def test_a_finished_sweeps_workers_serve_the_next_sweep(workdir, monkeypatch):
    """The idle workers of a finished sweep wait for the next sweep of this process (a
    worker's start costs about 1.6 CPU-s); not across a change of the environment a worker
    would get, and not past an interrupted sweep; the rows are a fresh worker's."""
    from ancf.study import sweep_pool as sweep

    sweep._close_parked()
    grids = [{"n_elements": [1, 2, 3, 4]}]
    first = run_sweep("cantilever", grids, out=workdir / "a.csv", workers=2, progress=False)
    pids = sorted(r.proc.pid for r in sweep._PARKED)
    assert len(pids) == 2 and all(r.proc.poll() is None for r in sweep._PARKED)
    again = run_sweep("cantilever", grids, out=workdir / "b.csv", workers=2, progress=False)
    assert sorted(r.proc.pid for r in sweep._PARKED) == pids
    cols = ["key", "status", "error", "res_tip_x", "res_tip_y", "iterations"]
    pd.testing.assert_frame_equal(first[cols], again[cols])
    monkeypatch.setenv("ANCF_TEST_OTHER_ENV", "1")
    run_sweep("cantilever", grids, out=workdir / "c.csv", workers=2, progress=False)
    assert not set(pids) & {r.proc.pid for r in sweep._PARKED}  # the old ones were ended
    rows = sweep._run_local(make_tasks("cantilever", expand(grids)), 2, 60.0)
    next(rows)
    rows.close()  # the consumer stops early: an interrupted sweep
    assert not sweep._PARKED
