"""Benchmark-suite hooks: machine description in the benchmark JSON, no git
look-ups, and a compact end-of-session summary (element x n, linear/OS ratios)."""
from __future__ import annotations

import os
import platform

import pytest

_LOG = pytest.StashKey[list]()


def ancf_machine() -> dict:
    """CPU model, cores, OS, Python and numerical-library versions."""
    import numpy as np
    import scipy

    from ancf.common.machine import cpu_model
    cpu = cpu_model()
    try:
        usable = len(os.sched_getaffinity(0))
    except AttributeError:
        usable = os.cpu_count()
    blas = None
    try:
        deps = np.show_config(mode="dicts")["Build Dependencies"]["blas"]
        blas = f"{deps.get('name')} {deps.get('version')}".strip()
    except Exception:  # numpy < 2 or an unusual build
        pass
    try:
        import pytest_benchmark
        pb = pytest_benchmark.__version__
    except Exception:
        pb = None
    info = {
        "cpu_model": cpu,
        "logical_cores": os.cpu_count(),
        "usable_cores": usable,
        "os": f"{platform.system()} {platform.release()}",
        "platform": platform.platform(),
        "python": f"{platform.python_implementation()} {platform.python_version()}",
        "numpy": np.__version__,
        "scipy": scipy.__version__,
        "blas": blas,
        "pytest_benchmark": pb,
        "thread_env": {k: os.environ[k] for k in
                       ("OMP_NUM_THREADS", "OPENBLAS_NUM_THREADS", "MKL_NUM_THREADS")
                       if k in os.environ},
    }
    info["summary"] = (f"{cpu}, {os.cpu_count()} cores, {info['os']}, Python "
                       f"{platform.python_version()}, numpy {np.__version__}, scipy {scipy.__version__}")
    return info


def pytest_benchmark_update_machine_info(config, machine_info):
    machine_info["ancf_machine"] = ancf_machine()


@pytest.hookimpl(tryfirst=True)
def pytest_benchmark_generate_commit_info(config):
    """Replace the plugin's default (which shells out to git) with a static record."""
    return {"id": "not-recorded", "time": None, "author_time": None, "dirty": None,
            "project": "ancf-bench", "branch": None,
            "note": "VCS look-up disabled in benchmarks/conftest.py"}


@pytest.fixture
def bench_log(request):
    """Tests append (kind, element, n, benchmark fixture) for the session summary."""
    return request.config.stash.setdefault(_LOG, [])


def _fmt(t):
    if t is None:
        return "-"
    for unit, f in (("s", 1.0), ("ms", 1e3), ("us", 1e6)):
        if t * f >= 1.0 or unit == "us":
            return f"{t * f:.3g} {unit}"


def pytest_terminal_summary(terminalreporter, exitstatus, config):
    log = config.stash.get(_LOG, [])
    if not log:
        return
    tr = terminalreporter
    tr.section("ancf benchmark summary")
    enabled = any(b.stats for _, _, _, b in log)
    if not enabled:
        tr.write_line(f"{len(log)} benchmark(s) ran once as tests (benchmarks disabled); "
                      "use --benchmark-enable for timings.")
        return
    means = {(kind, el, n): (b.stats.stats.mean if b.stats else None, b.extra_info)
             for kind, el, n, b in log}
    ns = sorted({n for _, _, n, _ in log})
    tr.write_line(f"{'benchmark':<18}{'element':<14}" + "".join(f"{'n=' + str(n):>12}" for n in ns))
    for kind in ("solve", "kernel"):
        for el in ("linear", "omar-shabana"):
            if not any((kind, el, n) in means for n in ns):
                continue
            cells = [_fmt(means.get((kind, el, n), (None,))[0]) for n in ns]
            tr.write_line(f"{kind:<18}{el:<14}" + "".join(f"{c:>12}" for c in cells))
    if any(kind == "ratio" for kind, _, _, _ in log):
        cells = []
        for n in ns:
            r = means.get(("ratio", None, n), (None, {}))[1].get("ratio_linear_over_os")
            cells.append("-" if r is None else f"{r:.3f}")
        tr.write_line(f"{'ratio lin/OS':<18}{'(thesis 0.5)':<14}" + "".join(f"{c:>12}" for c in cells))
    json_path = config.getoption("benchmark_json", None)
    if json_path is not None:
        name = getattr(json_path, "name", json_path)
        tr.write_line(f"JSON: {name}; Markdown summary: python -m benchmarks.summarize")
