"""Progress lines of long runs (:mod:`ancf.common.progress`): a ticker prints only when
its interval has passed (so a short run's stderr stays errors and warnings), at most
every 2 s on a terminal and at least every 20 s when stderr is piped; the belt march's
chunks follow the wall clock when a ticker listens, and that split leaves the
arithmetic unchanged (the march carries its state across calls)."""
from __future__ import annotations

import io

import numpy as np
import pytest

from ancf.belts import dynamics
from ancf.belts.drive_file import load
from ancf.belts.drive_model import build
from ancf.belts.dynamics import BeltOptions, simulate
from ancf.common import progress
from ancf.common.paths import REPO
from ancf.common.progress import Ticker


class _Clock:
    def __init__(self):
        self.now = 100.0

    def __call__(self):
        return self.now


class _Tty(io.StringIO):
    def isatty(self):
        return True


def test_ticker_prints_only_after_its_interval(monkeypatch):
    clock = _Clock()
    monkeypatch.setattr(progress.time, "monotonic", clock)
    out = io.StringIO()
    tick = Ticker("belt-drive", 2.45, stream=out)
    for t, dt_wall in ((0.1, 5.0), (0.2, 9.0), (0.3, 1.5), (0.4, 0.1)):
        clock.now += dt_wall
        tick(t)
    lines = out.getvalue().splitlines()
    assert lines == ["progress: belt-drive: t = 0.3 / 2.45 s (16 s)"]  # 5 + 9 + 1.5 >= 15 s, once


def test_piped_interval_is_under_twenty_seconds_and_a_terminal_faster():
    piped, tty = Ticker("x", 1.0, stream=io.StringIO()), Ticker("x", 1.0, stream=_Tty())
    assert piped.every == progress.PIPED_EVERY_S < 20.0
    assert tty.every == progress.TTY_EVERY_S < piped.every


def test_a_piped_drive_run_prints_progress_lines(monkeypatch, capsys):
    """The wiring: ``ancf run belt-drive`` (the THREAD file, coarse and short) gives its
    ticker the march's chunks; with the piped interval at 0 every chunk prints a line on
    stderr and stdout stays the one JSON object."""
    import json
    from ancf.cli import main
    monkeypatch.setattr(progress, "PIPED_EVERY_S", 0.0)
    rc = main(["run", "belt-drive", "--file", str(REPO / "examples" / "thread_benchmark.toml"),
               "--set", "belt.n_elements=24", "--set", "run.t_end=0.004", "--set", "run.steady_window=0.002", "--json"])
    out, err = capsys.readouterr()
    assert rc == 0 and json.loads(out)["converged"]
    lines = [ln for ln in err.splitlines() if ln.startswith("progress: belt-drive: t = ")]
    assert len(lines) >= dynamics.CHUNKS
    assert lines[-1].startswith("progress: belt-drive: t = 0.004 / 0.004 s")


def test_chunks_equal_parts_or_timed(monkeypatch):
    assert list(dynamics._chunks(100, False)) == list(range(5, 101, 5))
    clock = _Clock()
    monkeypatch.setattr(dynamics.time, "monotonic", clock)
    gen, seen = dynamics._chunks(1000, True), []
    for k in gen:  # each step takes 0.5 s of wall time: CHUNK_S = 2 s is 4 steps
        seen.append(k)
        clock.now += 0.5 * (k - (seen[-2] if len(seen) > 1 else 0))
    assert seen[0] == 50 and seen[1] - seen[0] == int(dynamics.CHUNK_S / 0.5) and seen[-1] == 1000


@pytest.fixture(scope="module")
def thread_coarse():
    return build(load(REPO / "examples" / "thread_benchmark.toml", ["belt.n_elements=24"]))


def test_timed_chunks_leave_the_march_unchanged(thread_coarse, monkeypatch):
    t = np.linspace(0.0, 0.006, 7)
    opt = BeltOptions(dt=5e-5)
    plain = simulate(thread_coarse, t, opt)
    monkeypatch.setattr(dynamics, "CHUNK_S", 1e-9)  # a chunk per step
    calls = []
    split = simulate(thread_coarse, t, opt, progress=calls.append)
    assert plain.converged and split.converged
    assert len(calls) == 120 - 6 + 1  # the first 1/20 of the run, then every step
    np.testing.assert_array_equal(split.q, plain.q)
    np.testing.assert_array_equal(split.v, plain.v)
    assert split.newton_iterations == plain.newton_iterations
