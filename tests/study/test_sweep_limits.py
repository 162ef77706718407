"""Bounded cost up front and distributed runs that fail loudly (issue 33, items 4 and 9).

* a sweep says its run count at once and refuses a grid above MAX_RUNS (the count and
  the least time in one ``error:`` line) unless forced; more workers than cores are
  capped with a ``warning:`` unless forced; an interrupt names only files that exist;
* a sweep none of whose runs converged exits 3 with a summary;
* ``--scheduler`` where no Dask scheduler answers fails within seconds with one line;
  a relative drive file reaches workers started in another folder; workers the
  scheduler lost and the runs it repeated are counted in the closing line.

Every scheduler here listens on 127.0.0.1 only.
"""
from __future__ import annotations

import http.server
import os
import signal
import socket
import subprocess
import sys
import threading
import time

import pytest

import ancf
from ancf.common.params import InputError
from ancf.study import sweep as sweep_mod
from ancf.study.sweep import MAX_RUNS, check_size, check_workers, count_runs
from ancf.study.sweep_dask import SCHEDULER_TIMEOUT, lost_and_retried
from ancf.study.sweep_files import summary
from ancf.study.sweep_tasks import make_tasks, run_case

#: the issue's 4.1-million-run grid: 64 x 80 x 100 x 8 runs of the cantilever
HUGE = ["--grid", "n_elements=" + ",".join(map(str, range(1, 65))),
        "--grid", "F=" + ",".join(str(-100.0 * k) for k in range(1, 81)),
        "--grid", "h=" + ",".join(f"{0.01 + 0.001 * k:g}" for k in range(100)),
        "--grid", "nu=0,0.05,0.1,0.15,0.2,0.25,0.3,0.35"]


@pytest.mark.slow
def test_a_huge_grid_is_refused_at_once_with_its_count_and_time(cli, tmp_path):
    """Before: 90 s of silence (every combination resolved first).  After: one line with
    the count (64 x 80 x 100 x 8 = 4 096 000) and the least time, in well under those 90 s."""
    t0 = time.perf_counter()
    rc, out, err = cli("sweep", "cantilever", *HUGE, "--out", str(tmp_path / "huge.csv"))
    took = time.perf_counter() - t0
    assert rc == 2 and out == ""
    assert err.startswith("error: sweep: 4096000 runs (at least "), err
    assert f"is above {MAX_RUNS}; allowed: at most {MAX_RUNS} runs" in err and "--force" in err
    assert len(err.splitlines()) == 1
    assert took < 10, took  # a hang guard: the count is a product, not a pass over the runs
    assert not any(tmp_path.iterdir())


def test_the_least_time_is_the_runs_times_the_cheapest_run_over_the_workers():
    # 4 096 000 runs x 0.2 s / 2 workers = 409 600 s = 114 h
    with pytest.raises(InputError, match=r"4096000 runs \(at least 114 h on 2 worker"):
        check_size(4_096_000, 2, force=False)
    check_size(4_096_000, 2, force=True)  # forced: no error
    check_size(MAX_RUNS, 2, force=False)  # the limit itself is allowed
    with pytest.raises(InputError, match=f"{MAX_RUNS + 1} runs"):
        check_size(MAX_RUNS + 1, 64, force=False)


def test_run_count_of_grids_is_the_sum_of_their_products():
    assert count_runs({"a": [1, 2, 3], "b": [1, 2]}) == 6
    assert count_runs([{"a": [1, 2]}, {"b": [1, 2, 3, 4]}, {"c": [0]}]) == 7
    assert count_runs({"a": list(range(2000)), "b": list(range(2000)), "c": [1]}) == 4_000_000


def test_workers_above_the_cores_are_capped_with_a_warning(monkeypatch):
    monkeypatch.setattr(sweep_mod, "available_cores", lambda: 2)
    said = []
    assert check_workers(64, None, False, said.append) == 2
    assert said == ["warning: workers = 64 is above the 2 core(s) this process may use; "
                    "starting 2 (--force, force=True: start 64)"]
    said.clear()
    assert check_workers(64, None, True, said.append) == 64 and said == []
    assert check_workers(2, None, False, said.append) == 2 and said == []
    assert check_workers(None, None, False, said.append) == 2 and said == []
    for bad in (0, -1, 1.5, True, "4"):
        with pytest.raises(InputError, match="workers"):
            check_workers(bad, None, False, said.append)
    with pytest.raises(InputError, match="workers = 2 and scheduler: both given"):
        check_workers(2, "tcp://127.0.0.1:1", False, said.append)


def test_available_cores_follow_the_affinity():
    assert sweep_mod.available_cores() == len(os.sched_getaffinity(0))


@pytest.mark.slow
def test_the_run_count_is_the_first_line(tmp_path):
    """The count comes before any run is resolved; then the usual line, then the summary."""
    said = []
    df = ancf.sweep("axial-bar", grid={"n_elements": [1, 2]}, fixed={"F": 1e3},
                    out=tmp_path / "two.csv", log=said.append, workers=1, time_limit=60.0)
    assert said[0] == "sweep axial-bar: 2 runs in the grid; checking them before the start"
    assert "2 runs, 0 already in two.csv" in said[1]
    assert len(df) == 2 and df.attrs["sweep"] == {"runs": 2, "succeeded": 2, "lost_workers": 0,
                                                  "retried_runs": 0}


def test_interrupt_names_only_an_existing_rows_file(tmp_path):
    from ancf.cli import _interrupted
    out = tmp_path / "rows.parquet"
    assert _interrupted(out) == ("interrupted: no run had finished, nothing was written; "
                                 "the same command starts again")
    out.write_text("")
    assert _interrupted(out) == (f"interrupted: the finished rows are in {out}; the same "
                                 "command resumes")


@pytest.mark.slow
def test_sigterm_before_any_row_names_no_file(tmp_path):
    """Before: 'the finished rows are in sweep-X.parquet', a file that did not exist."""
    out = tmp_path / "never.parquet"
    p = subprocess.Popen([sys.executable, "-m", "ancf.cli", "sweep", "pendulum", "--grid",
                          "n_elements=2,3", "--set", "t_end=50", "--workers", "1", "--out",
                          str(out), "--no-progress"], stderr=subprocess.PIPE, text=True)
    for line in p.stderr:  # the second line: the runs are about to start
        if "to run on" in line:
            break
    p.send_signal(signal.SIGTERM)
    _, err = p.communicate(timeout=120)
    assert p.returncode == 130
    assert "interrupted: no run had finished, nothing was written" in err, err
    assert not out.exists()


@pytest.mark.slow
def test_a_sweep_of_which_no_run_converged_exits_3(cli, tmp_path):
    """Every run inverts an element (F = -1e12, as `ancf run` exit 3): before, exit 0."""
    out = tmp_path / "none.csv"
    rc, stdout, err = cli("sweep", "axial-bar", "--grid", "n_elements=1,2", "--set", "F=-1e12",
                          "--out", str(out), "--workers", "1", "--no-progress", "--json")
    assert rc == 3, err
    assert "error: sweep axial-bar: none of its 2 runs converged" in err
    assert '"not-converged": 2' in stdout and out.exists()


# ---------------------------------------------------------------------------------------
# Dask
# ---------------------------------------------------------------------------------------

def _free_port() -> int:
    """A port on 127.0.0.1 that nothing listens on (bound to 0, then released)."""
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


class _Quiet(http.server.BaseHTTPRequestHandler):
    def log_message(self, *args):
        pass


@pytest.mark.slow
@pytest.mark.parametrize("server", ["http", "nothing"])
def test_a_scheduler_address_where_no_scheduler_answers_fails_in_seconds(cli, tmp_path, server):
    """Before: an HTTP server there (a dashboard's port) hung the sweep for 30 minutes."""
    httpd = None
    if server == "http":
        httpd = http.server.HTTPServer(("127.0.0.1", 0), _Quiet)
        threading.Thread(target=httpd.serve_forever, daemon=True).start()
        port = httpd.server_address[1]
    else:
        port = _free_port()
    try:
        t0 = time.perf_counter()
        rc, out, err = cli("sweep", "axial-bar", "--grid", "n_elements=1,2", "--scheduler",
                           f"tcp://127.0.0.1:{port}", "--out", str(tmp_path / "x.csv"),
                           "--no-progress")
        took = time.perf_counter() - t0
    finally:
        if httpd is not None:
            httpd.shutdown()
            httpd.server_close()
    assert rc == 2
    errors = [line for line in err.splitlines() if line.startswith("error: ")]
    assert errors == [line for line in err.splitlines() if not line.startswith("sweep ")]
    assert len(errors) == 1 and errors[0].startswith(
        f"error: --scheduler tcp://127.0.0.1:{port}: no Dask scheduler answered within "
        f"{SCHEDULER_TIMEOUT:g} s"), err
    assert took < SCHEDULER_TIMEOUT + 40, took  # imports and a loaded machine, not 30 min
    assert not (tmp_path / "x.csv").exists()


def test_a_closed_port_is_refused_at_once_and_a_listening_one_goes_on_to_dask():
    """A refused TCP connection (nothing listens) or a port past 65535 ends the wait at
    once, with the error the Dask path gives after its retries; a port where something
    listens is left to the ``identity`` hand-shake (:func:`_identity`)."""
    from ancf.study.sweep_dask import _refused_at_once
    with pytest.raises(ConnectionRefusedError):
        _refused_at_once(f"tcp://127.0.0.1:{_free_port()}")
    with pytest.raises(ConnectionRefusedError):
        _refused_at_once(f"127.0.0.1:{_free_port()}")
    with pytest.raises(OverflowError):
        _refused_at_once("tcp://127.0.0.1:99999")
    httpd = http.server.HTTPServer(("127.0.0.1", 0), _Quiet)
    try:
        assert _refused_at_once(f"tcp://127.0.0.1:{httpd.server_address[1]}") is None
    finally:
        httpd.server_close()
    assert _refused_at_once("inproc://x") is None  # not TCP: the Dask path judges it


def test_lost_workers_and_retried_runs_are_counted_from_the_scheduler_events():
    ours = ["ancf-sweep-a-1", "ancf-sweep-b-1", "ancf-sweep-c-1"]
    events = [
        (1.0, {"action": "add-worker", "worker": "tcp://127.0.0.1:1"}),
        (2.0, {"action": "remove-worker", "worker": "tcp://127.0.0.1:1", "expected": False,
               "processing-tasks": {"ancf-sweep-a-1"}, "lost-computed-tasks": {"ancf-sweep-b-1"}}),
        (3.0, {"action": "remove-worker", "worker": "tcp://127.0.0.1:2", "expected": True,
               "processing-tasks": {"ancf-sweep-c-1"}, "lost-computed-tasks": set()}),  # closed
        (4.0, {"action": "remove-worker", "worker": "tcp://127.0.0.1:3", "expected": False,
               "processing-tasks": {"other-task"}, "lost-computed-tasks": set()}),  # not ours
        (5.0, {"action": "remove-worker", "worker": "tcp://127.0.0.1:4", "expected": False,
               "processing-tasks": {"ancf-sweep-a-1"}, "lost-computed-tasks": set()}),
        (6.0, "a message that is not a dict"),
    ]
    assert lost_and_retried(events, ours) == {"lost_workers": 2, "retried_runs": 2}
    assert lost_and_retried([], ours) == {"lost_workers": 0, "retried_runs": 0}


def test_the_summary_line_names_lost_workers_and_retries():
    import pandas as pd
    df = pd.DataFrame({"key": ["a", "b"], "status": ["ok", "ok"], "session": ["s", "s"],
                       "cpu_time_s": [0.5, 0.25]})
    line = summary(df, "axial-bar", "x.csv", 2.0, "s", {"lost_workers": 1, "retried_runs": 2})
    assert line.endswith("(0.75 s CPU in the runs); 1 Dask worker(s) lost, 2 run(s) retried")
    assert summary(df, "axial-bar", "x.csv", 2.0, "s", {}).endswith("CPU in the runs)")


def _short_drive(folder, examples):
    """examples/three_pulleys.toml, 2 ms long, as drive.toml in ``folder``."""
    text = (examples / "three_pulleys.toml").read_text()
    for old, new in (("t_end = 1.5 ", "t_end = 0.002 "), ("output_dt = 0.005 ", "output_dt = 0.001 "),
                     ("steady_window = 0.3 ", "steady_window = 0.001 ")):
        assert old in text
        text = text.replace(old, new)
    (folder / "drive.toml").write_text(text)


def test_a_task_carries_its_drive_file_as_an_absolute_path(tmp_path, monkeypatch, examples):
    monkeypatch.chdir(tmp_path)
    _short_drive(tmp_path, examples)
    (task,) = make_tasks("belt-drive", [{"file": "drive.toml"}])
    assert task["params"]["file"] == "drive.toml"  # the row and its key as before
    assert task["paths"] == {"file": str(tmp_path / "drive.toml")}


@pytest.mark.slow
def test_a_run_in_another_folder_reads_the_drivers_file(tmp_path, monkeypatch, examples):
    """Before: a worker elsewhere gave 'invalid: no such file' for every row."""
    monkeypatch.chdir(tmp_path)
    _short_drive(tmp_path, examples)
    (task,) = make_tasks("belt-drive", [{"file": "drive.toml"}])
    elsewhere = tmp_path / "elsewhere"
    elsewhere.mkdir()
    monkeypatch.chdir(elsewhere)
    row = run_case(task)
    assert row["status"] in ("ok", "not-converged") and "no such file" not in row["message"]
    assert row["file"] == "drive.toml"


@pytest.fixture
def cluster_elsewhere(tmp_path, monkeypatch):
    """A local Dask cluster (127.0.0.1) whose worker processes start in another folder."""
    from distributed import LocalCluster
    elsewhere = tmp_path / "workers-start-here"
    elsewhere.mkdir()
    monkeypatch.chdir(elsewhere)
    with LocalCluster(n_workers=2, threads_per_worker=1, processes=True, host="127.0.0.1",
                      dashboard_address=None) as cluster:
        monkeypatch.chdir(tmp_path)
        yield cluster


@pytest.mark.slow
def test_dask_workers_in_another_folder_read_a_relative_drive_file(cluster_elsewhere, tmp_path,
                                                                   examples):
    """Before: every row 'invalid: ... no such file' and exit 0."""
    _short_drive(tmp_path, examples)
    df = ancf.sweep("belt-drive", grid={"n_elements": [60, 64]}, fixed={"file": "drive.toml"},
                    scheduler=cluster_elsewhere.scheduler_address, out=tmp_path / "d.csv")
    assert len(df) == 2 and not df["message"].str.contains("no such file").any()
    assert set(df["status"]) <= {"ok", "not-converged"}, df[["status", "message"]]
    assert (df["file"] == "drive.toml").all()


@pytest.mark.slow
def test_a_dask_worker_lost_mid_run_is_counted(cluster_elsewhere, tmp_path):
    """A worker killed while it holds a run: the scheduler runs it again on the other one,
    and the summary says so (before: without a word)."""
    from distributed import Client
    address = cluster_elsewhere.scheduler_address
    killed = []

    def kill_one():
        with Client(address, timeout=30) as c:
            deadline = time.monotonic() + 120
            while time.monotonic() < deadline and not killed:
                for worker, keys in c.processing().items():
                    if any(str(k).startswith("ancf-sweep-") for k in keys):
                        pid = c.run(os.getpid, workers=[worker])[worker]
                        os.kill(pid, signal.SIGKILL)
                        killed.append(worker)
                        break
                time.sleep(0.05)

    killer = threading.Thread(target=kill_one)
    killer.start()
    said = []
    df = ancf.sweep("axial-bar", grid={"n_elements": [1, 2]}, scheduler=address,
                    out=tmp_path / "lost.csv", log=said.append)
    killer.join()
    assert len(killed) == 1
    assert df.attrs["sweep"]["lost_workers"] == 1 and df.attrs["sweep"]["retried_runs"] >= 1
    assert "1 Dask worker(s) lost, " in said[-1]
    assert set(df["status"]) == {"ok"}  # the run itself came back from the other worker
