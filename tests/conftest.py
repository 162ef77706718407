"""Shared fixtures of the whole suite.

``workdir``: a per-module scratch folder that is also the reference cache.  ``cli``: runs
``ancf ARGV`` in-process and gives (exit code, stdout, stderr), whether the command
returns its code or exits.  ``examples``: the repository's ``examples/`` folder.

Tiers: ``make test-fast`` runs every test not marked ``slow`` (``pytest -m "not slow"``),
``make test`` all of them; a test that takes more than a few seconds on an idle machine is
marked ``@pytest.mark.slow`` in its own file.  Under xdist the controller first compiles
the kernels most files share (:data:`WARM_UP`), so the two workers do not both compile them,
and hands the files of :data:`LONG` out first (:func:`pytest_collection_modifyitems`).
"""
import collections
import os
import subprocess
import sys

import pytest

from ancf.common.paths import REPO
from ancf.common.threads import one_blas_thread

#: one BLAS thread in every worker, as in every run (ancf.common.threads): set before xdist
#: starts its workers, so their BLAS reads it when it loads.  With OpenBLAS's default (a
#: thread per core) the tests that call numpy's linear algebra outside a run (the Chrono
#: plate's history: 2.37 CPU-s for 1000 steps alone, 4.38 with two threads spinning) took
#: the other worker's core
one_blas_thread()

#: the kernels most test files compile (the belt marches: 2D, one compiled march for every
#: friction law, and 3D; the ALE belt; the beams; the generalised-alpha march of the
#: beams), as commands in two groups run side by side before xdist starts its workers, so
#: that the workers load them from numba's cache instead of compiling the same kernels
#: twice at once.  Cold, side by side (4 December): the serpentine (it compiles the 2D
#: march, in which THREAD's bristle law runs too), the beams and the generalised-alpha
#: pendulum 69 + 12 + 22 s; the 3D belt, the ALE steady state and the pendulum (its beam
#: kernels compiled by then) 77 + 12 + 4 s: 102 s (126 s when THREAD compiled a second 2D
#: march for the law with a state, 39 s).  The generalised-alpha pendulum filled an idle
#: half minute: without it the two processes of the quick report
#: (tests/reports/test_reports.py) each compiled that march, at once
WARM_UP = (
    (("run", "belt-drive", "--file", "examples/serpentine.toml", "--set", "run.t_end=0.002",
      "--set", "run.output_dt=0.001", "--set", "run.steady_window=0.001"),
     ("run", "cantilever"),
     ("run", "pendulum", "--set", "integrator=generalized-alpha", "--set", "t_end=0.01")),
    (("run", "belt3d", "--set", "t_end=0.002", "--set", "output_dt=0.001"),
     ("steady", "belt-drive", "--file", "examples/thesis_table_3_1.toml"),
     ("run", "pendulum", "--set", "t_end=0.01")))


def _warm(group) -> str:
    """Run one group's commands in order in a child process each; '' or what failed."""
    for argv in group:
        p = subprocess.run([sys.executable, "-m", "ancf.cli", *argv, "--json"], cwd=REPO,
                           capture_output=True, text=True)
        if p.returncode != 0:
            return f"{' '.join(argv)}: exit {p.returncode}"
    return ""


def pytest_sessionstart(session):
    """Under xdist (``-n``), in the controller before the workers start: compile the kernels
    of :data:`WARM_UP` once, its two groups side by side (a warm cache makes this a few
    seconds).  Measured cold (fresh clone, idle 2-core machine, with set-up): ``make test``
    15:56 -> 14:11, ``make test-fast`` 7:25 -> 6:36.  ``ANCF_WARM_UP=0`` skips it; a
    failure is only reported, the tests find it."""
    config = session.config
    if (hasattr(config, "workerinput") or not getattr(config.option, "numprocesses", None)
            or os.environ.get("ANCF_WARM_UP") == "0"):
        return
    from concurrent.futures import ThreadPoolExecutor
    with ThreadPoolExecutor(len(WARM_UP)) as ex:
        failed = [f for f in ex.map(_warm, WARM_UP) if f]
    for f in failed:
        print(f"warm-up: {f}", file=sys.stderr)


#: test files of few tests that run long: under ``--dist loadfile`` a file runs in one
#: worker, and xdist hands the files out by test count, most first, so these came late
#: (of 126 files: test_reports.py 76th, test_thread_plate.py 117th) and the last of them
#: ran on while the other worker idled.  Under xdist without a marker selection (``make
#: test``) they go out first, in this order, the others after them in xdist's order.
#: Each alone, CPU s with --durations (kernels loaded or compiled in it): test_reports
#: 267 (its quick-report fixture 302 s wall), the chrono_elements chapter 80, the plate
#: belt's module fixture 132 compiling (13 with its kernels cached), belt3d_checks 72
#: (a Model 2 run), serpentine_modes 31 (its module fixture).  Two other orders, measured
#: cold in a fresh clone (4 December), were no faster: every file of 27 s or more first,
#: longest first (pytest 763 s against 645 s: files that compile their kernels early run
#: longer than late, when others have cached them), and the Chrono 3423 history sixth
#: (776 s, the whole run about 15 % slower that hour; again on 5 December with the plate
#: serpentine's checks seventh: pytest 625 s against 609 s, the history 86 s early against
#: 42 s last, when test_chrono_3423.py has compiled its kernels, though it ends the run
#: 30 s after the other worker)
LONG = ("tests/reports/test_reports.py", "tests/reports/test_chrono_elements_chapter.py",
        "tests/checks/test_thread_plate.py", "tests/checks/test_belt3d_checks.py",
        "tests/checks/test_serpentine_modes.py")


def _long_first(config) -> bool:
    """Under xdist (its controller or a worker) without a marker selection."""
    xdist = getattr(config.option, "numprocesses", None) or hasattr(config, "workerinput")
    return bool(xdist) and not config.option.markexpr


def pytest_configure(config):
    """``make test``: the controller hands the files out in the order the workers collect
    them (:func:`pytest_collection_modifyitems`), not in xdist's by test count."""
    if _long_first(config):
        config.option.loadscopereorder = False


def file_order(items) -> list:
    """``items`` by file: :data:`LONG`'s files first, in its order, then the others by
    test count, most first (xdist's own order); a file's tests in their order."""
    path = {id(i): i.nodeid.split("::", 1)[0] for i in items}
    count = collections.Counter(path.values())
    rank = {f: k - len(LONG) for k, f in enumerate(LONG)}   # negative: before the others
    return sorted(items, key=lambda i: (rank.get(path[id(i)], 0), -count[path[id(i)]],
                                        path[id(i)]))


@pytest.hookimpl(trylast=True)
def pytest_collection_modifyitems(config, items):
    """``make test``: each worker collects in :func:`file_order` (both alike)."""
    if _long_first(config):
        items[:] = file_order(items)


@pytest.fixture(scope="module")
def workdir(tmp_path_factory, request):
    """A per-module scratch folder that is also the reference cache (ANCF_CACHE), so
    sweeps in tests never read or write reports/.cache."""
    d = tmp_path_factory.mktemp(request.module.__name__.rsplit(".", 1)[-1])
    old = os.environ.get("ANCF_CACHE")
    os.environ["ANCF_CACHE"] = str(d / "cache")
    yield d
    if old is None:
        os.environ.pop("ANCF_CACHE", None)
    else:
        os.environ["ANCF_CACHE"] = old


@pytest.fixture
def cli(capsys):
    """``cli(*argv) -> (exit code, stdout, stderr)`` of ``ancf ARGV`` run in this process."""
    from ancf.cli import main

    def run(*argv):
        try:
            rc = main(list(argv))
        except SystemExit as exc:
            rc = exc.code
        out, err = capsys.readouterr()
        return rc, out, err
    return run


@pytest.fixture(scope="session")
def examples():
    """The repository's examples/ folder (drive files)."""
    return REPO / "examples"
