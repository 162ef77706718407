"""Side by side with Exudyn: the same cases, the same mesh and load or step, in one run.

    python -m benchmarks.peers [--quick] [--out reports/benchmarks]

Writes ``peers.md`` (generated table, see :mod:`benchmarks.peers_report`) and
``peers.json`` (raw numbers) into ``--out``; ``--quick`` runs the small meshes only,
with fewer repeats, and writes ``peers_quick.md`` / ``peers_quick.json``.  Without
exudyn importable (``pip install -e .[peers]``), or with ``ANCF_PEERS_NO_EXUDYN=1``,
it prints one line saying so and exits 0.

Measurement: each code runs in its own long-lived worker (:mod:`benchmarks.peers_worker`)
with one BLAS thread and OPENBLAS_CORETYPE / OPENBLAS_L2_SIZE unset, both workers (and
the whole-process runs) on one and the same CPU (:data:`CPU`: unpinned, the workers
moved between the cores and a small case's samples doubled on some rounds); every case is run
once per side as a warm-up, then ``repeats`` times alternating ours, Exudyn, ours,
Exudyn, ...; the medians are compared.  Ours is the scene's ``cpu_time_s``, Exudyn's
the CPU time of its solve call.  The whole-process row runs ``ancf run cantilever
--set n_elements=64 --json`` and ``python -m benchmarks.peers_exudyn cantilever 64`` as
fresh subprocesses (byte code compiled first, :func:`compile_byte_code`), alternately,
and compares their CPU time (user + system, from ``getrusage``); their wall times are
recorded too.

JSON keys (stable): ``schema``, ``quick``, ``started``, ``command``,
``machine`` (with the 1 / 5 / 15 min load average at the start: the machine may be
shared), ``workers`` (per side: versions, thread environment, BLAS kernel), ``settings``,
``references`` (Reissner and shear-rigid elastica tips of the cantilever; per pendulum
n and side the reference run with its final tip: ours DOP853 rtol 1e-10, Exudyn its
generalised-alpha with h = 1e-4), and ``cases``: a list of rows ``{case, n, label,
ours, exudyn, ratio, ratio_paired}`` where ``case`` is ``cantilever``, ``pendulum-ga``,
``pendulum-dop853`` or ``process``, ``ratio`` = ours cpu_s / Exudyn cpu_s (medians),
``ratio_paired`` the ratio of each alternating pair of samples, and each side
holds ``cpu_s`` (median), ``cpu_s_samples``, ``converged``, the run statistics the code
reports (ours: ``newton_iterations``, ``njev``, ``nlu``, ``nfev``, ``steps``; Exudyn:
``newton_iterations``, ``jacobians``, ``steps``, and its Newton settings
``modified_newton``, ``rel_tol``, ``abs_tol``), the final ``tip_x``, ``tip_y``, and the
accuracy: ``tip_error_m`` (cantilever: distance to the Reissner tip for ours, to the
shear-rigid elastica tip for Exudyn; pendulum: largest distance over the 0.01 s samples
to our DOP853 rtol 1e-10 tip, for both; Exudyn also ``tip_error_self_m``, the same
distance to its own h = 1e-4 run) and, for the pendulum, ``energy_max_deviation_J``;
``process`` rows hold ``command``, ``cpu_s``, ``wall_s``, their samples,
``exit_codes`` and ``ratio_wall``.
"""
from __future__ import annotations

import argparse
import compileall
import datetime as dt
import importlib.util
import json
import math
import os
import platform
import resource
import statistics
import subprocess
import sys
import time
from pathlib import Path

from ancf.common.machine import cpu_model
from benchmarks import peers_report

ROOT = Path(__file__).resolve().parents[1]
DEFAULT_OUT = ROOT / "reports" / "benchmarks"
SIDES = ("ours", "exudyn")
FULL = {"cantilever": (8, 16, 64, 256, 1024), "pendulum-ga": (4, 16, 64, 128),
        "pendulum-dop853": (4,), "process": (64,)}
QUICK = {"cantilever": (8, 16), "pendulum-ga": (4,), "pendulum-dop853": (4,), "process": (64,)}
REPEATS = {"cantilever": 7, "pendulum-ga": 7, "pendulum-dop853": 5, "process": 7}
QUICK_REPEATS = 2
THREAD_ENV = {"OPENBLAS_NUM_THREADS": "1", "OMP_NUM_THREADS": "1", "MKL_NUM_THREADS": "1"}
UNSET_ENV = ("OPENBLAS_CORETYPE", "OPENBLAS_L2_SIZE")
SKIP_ENV = "ANCF_PEERS_NO_EXUDYN"
SETTINGS = {
    "ours": {"cantilever": "scene defaults: linear element, thesis integration, 10 initial "
                           "load steps (adaptive), Newton rtol 1e-8, stability check auto",
             "pendulum": "linear element, constraints by elimination; generalized-alpha "
                         "dt 1e-3, rho_inf 0.9 (default); DOP853 rtol 1e-8, atol 1e-10 "
                         "(defaults); reference DOP853 rtol 1e-10"},
    "exudyn": {"cantilever": "ObjectANCFCable2D, static solver, 10 load steps (linear ramp), "
                             "full Newton, relativeTolerance 1e-8 (n < 256), 1e-7 (256), "
                             "1e-6 (512), 1e-5 (1024), EigenSparse",
               "pendulum": "ObjectANCFCable2D, pin by CoordinateConstraints (index 3), "
                           "generalized-alpha h 1e-3 (1000 fixed steps), spectralRadius 0.9, "
                           "Exudyn's default Newton settings (modified Newton; values in "
                           "the JSON), "
                           "EigenSparse; the pendulum-dop853 row runs this same "
                           "generalized-alpha"},
}


def exudyn_missing() -> bool:
    return bool(os.environ.get(SKIP_ENV)) or importlib.util.find_spec("exudyn") is None


def worker_env() -> dict:
    env = {k: v for k, v in os.environ.items() if k not in UNSET_ENV}
    env.update(THREAD_ENV)
    env["PYTHONPATH"] = os.pathsep.join(filter(None, (str(ROOT), env.get("PYTHONPATH"))))
    return env


#: the CPU both sides run on: the lowest this process may use.  Unpinned on a shared 2-core
#: host (4 December), the cantilever n = 8's samples were 0.8 ms (ours) and 2.5 ms
#: (Exudyn) in some rounds and up to 1.8 and 4.3 ms in others; pinned to either CPU, 0.76-
#: 0.84 and 2.54-2.57 ms in every round
CPU = min(os.sched_getaffinity(0))


def _pin() -> None:
    """In a child before exec: run on :data:`CPU` alone."""
    os.sched_setaffinity(0, {CPU})


class Worker:
    """One long-lived worker process on :data:`CPU`; :meth:`ask` sends a request, returns
    the answer."""

    def __init__(self, side: str, env: dict):
        self.side = side
        self.proc = subprocess.Popen([sys.executable, "-m", "benchmarks.peers_worker", side],
                                     stdin=subprocess.PIPE, stdout=subprocess.PIPE, text=True,
                                     cwd=ROOT, env=env, preexec_fn=_pin)

    def ask(self, case: str, n: int = 0, **kw) -> dict:
        self.proc.stdin.write(json.dumps({"case": case, "n": n, **kw}) + "\n")
        self.proc.stdin.flush()
        line = self.proc.stdout.readline()
        if not line:
            raise RuntimeError(f"{self.side} worker died (exit {self.proc.wait()})")
        return json.loads(line)

    def close(self) -> None:
        self.proc.stdin.close()
        self.proc.wait()


def machine() -> dict:
    cpu = cpu_model()
    return {"cpu_model": cpu, "logical_cores": os.cpu_count(),
            "usable_cores": len(os.sched_getaffinity(0)),
            "os": f"{platform.system()} {platform.release()}",
            "python": f"{platform.python_implementation()} {platform.python_version()}",
            "load_average_at_start": " / ".join(f"{x:.2f}" for x in os.getloadavg())}


def record(name: str, args, settings: dict, **first) -> dict:
    """The head of a race's JSON (``python -m benchmarks.NAME ARGS``): schema, ``first``'s
    keys, the start time, the command, the machine and ``settings``."""
    return {"schema": 1, **first,
            "started": dt.datetime.now(dt.timezone.utc).isoformat(timespec="seconds"),
            "command": f"python -m benchmarks.{name} " + " ".join(args),
            "machine": machine(), "settings": settings}


def write(out: Path, stem: str, res: dict, text: str) -> None:
    """out/stem.json (the raw numbers) and out/stem.md (``text``)."""
    out.mkdir(parents=True, exist_ok=True)
    (out / f"{stem}.json").write_text(json.dumps(res, indent=1) + "\n")
    (out / f"{stem}.md").write_text(text)


def tip_error(ans: dict, ref: dict) -> float | None:
    """Largest distance between two tip trajectories (lists) or two tip points."""
    x, y, rx, ry = ans.get("tip_x"), ans.get("tip_y"), ref.get("tip_x"), ref.get("tip_y")
    cols = [v if isinstance(v, list) else [v] for v in (x, y, rx, ry)]
    if x is None or rx is None or len({len(c) for c in cols}) != 1:
        return None
    return max(math.hypot(a - c, b - d) for a, b, c, d in zip(*cols))


def final_tip(ans: dict) -> dict:
    """The answer with scalar tip_x / tip_y (last sample of a trajectory)."""
    last = {k: ans[k][-1] if isinstance(ans.get(k), list) else ans.get(k)
            for k in ("tip_x", "tip_y")}
    return ans | last


def measure(workers: dict, case: str, n: int, repeats: int) -> dict:
    """Warm-up once per side, then ``repeats`` alternating rounds; medians per side."""
    last = {s: workers[s].ask(case, n) for s in SIDES}
    samples = {s: [] for s in SIDES}
    for _ in range(repeats if not any("error" in a for a in last.values()) else 0):
        for s in SIDES:
            last[s] = workers[s].ask(case, n)
            samples[s].append(last[s].get("cpu_s"))
    return {s: {**last[s], "cpu_s": _median(samples[s]), "cpu_s_samples": samples[s]}
            for s in SIDES}


def _median(xs):
    xs = [x for x in xs if x is not None]
    return statistics.median(xs) if xs else None


def _ratio(a, b):
    return a / b if a is not None and b else None


def static_rows(workers, ns, repeats, refs) -> list:
    rows = []
    for n in ns:
        res = measure(workers, "cantilever", n, repeats)
        for side, ref in (("ours", refs["reissner"]), ("exudyn", refs["elastica"])):
            res[side]["tip_error_m"] = tip_error(res[side], ref)
        rows.append(_row("cantilever", n, "static cantilever Model 1, 10 load steps", res))
    return rows


def pendulum_rows(workers, case, ns, repeats, refs) -> list:
    label = {"pendulum-ga": "pendulum 1 s, generalised-α dt = 1e-3 in both",
             "pendulum-dop853": "pendulum 1 s, our DOP853 vs Exudyn's generalised-α"}[case]
    rows = []
    for n in ns:
        if str(n) not in refs["pendulum"]:
            refs["pendulum"][str(n)] = {s: workers[s].ask("pendulum-ref", n) for s in SIDES}
        ref = refs["pendulum"][str(n)]
        res = measure(workers, case, n, repeats)
        for side in SIDES:
            res[side]["tip_error_m"] = tip_error(res[side], ref["ours"])
        res["exudyn"]["tip_error_self_m"] = tip_error(res["exudyn"], ref["exudyn"])
        rows.append(_row(case, n, label, res))
    return rows


def _paired(sides: dict) -> list:
    """Ratio of each alternating pair of samples (its spread shows the noise)."""
    pairs = zip(sides["ours"]["cpu_s_samples"], sides["exudyn"]["cpu_s_samples"])
    return [r for r in (_ratio(a, b) for a, b in pairs) if r is not None]


def _row(case, n, label, res) -> dict:
    sides = {s: final_tip(res[s]) for s in SIDES}
    return {"case": case, "n": n, "label": label, **sides,
            "ratio": _ratio(sides["ours"].get("cpu_s"), sides["exudyn"].get("cpu_s")),
            "ratio_paired": _paired(sides)}


def process_commands(n: int) -> dict:
    return {"ours": [str(Path(sys.executable).parent / "ancf"), "run", "cantilever",
                     "--set", f"n_elements={n}", "--json"],
            "exudyn": [sys.executable, "-m", "benchmarks.peers_exudyn", "cantilever", str(n)]}


def run_process(cmd: list, env: dict) -> dict:
    """CPU (user + system, from getrusage) and wall time of one whole subprocess (on
    :data:`CPU`)."""
    before, t0 = resource.getrusage(resource.RUSAGE_CHILDREN), time.perf_counter()
    proc = subprocess.run(cmd, env=env, cwd=ROOT, capture_output=True, text=True,
                          preexec_fn=_pin)
    wall, after = time.perf_counter() - t0, resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    return {"cpu_s": cpu, "wall_s": wall, "exit_code": proc.returncode}


def compile_byte_code() -> None:
    """Byte code for this tree's modules, as ``make setup`` writes it: under
    PYTHONDONTWRITEBYTECODE an editable install's modules would otherwise be compiled by
    every process (4 December: 353 against 327 ms of ours, 24 modules)."""
    for folder in ("ancf", "analytic", "benchmarks"):
        compileall.compile_dir(ROOT / folder, quiet=1)


def process_rows(env, ns, repeats) -> list:
    compile_byte_code()
    rows = []
    for n in ns:
        cmds = process_commands(n)
        for s in SIDES:
            run_process(cmds[s], env)          # warm-up: file cache, byte code
        runs = {s: [] for s in SIDES}
        for _ in range(repeats):
            for s in SIDES:
                runs[s].append(run_process(cmds[s], env))
        sides = {s: {"command": " ".join(Path(c).name if i == 0 else c
                                         for i, c in enumerate(cmds[s])),
                     "cpu_s": _median([r["cpu_s"] for r in runs[s]]),
                     "wall_s": _median([r["wall_s"] for r in runs[s]]),
                     "cpu_s_samples": [r["cpu_s"] for r in runs[s]],
                     "wall_s_samples": [r["wall_s"] for r in runs[s]],
                     "exit_codes": sorted({r["exit_code"] for r in runs[s]})} for s in SIDES}
        rows.append({"case": "process", "n": n, "label": "whole process, cantilever Model 1, "
                     "imports included (CPU of the subprocess)", **sides,
                     "ratio": _ratio(sides["ours"]["cpu_s"], sides["exudyn"]["cpu_s"]),
                     "ratio_paired": _paired(sides),
                     "ratio_wall": _ratio(sides["ours"]["wall_s"], sides["exudyn"]["wall_s"])})
    return rows


def run_all(plan: dict, repeats: dict) -> dict:
    env = worker_env()
    workers = {s: Worker(s, env) for s in SIDES}
    try:
        refs = {"reissner": workers["ours"].ask("reissner"),
                "elastica": workers["ours"].ask("reissner", shear_rigid=True), "pendulum": {}}
        cases = static_rows(workers, plan["cantilever"], repeats["cantilever"], refs)
        for case in ("pendulum-ga", "pendulum-dop853"):
            cases += pendulum_rows(workers, case, plan[case], repeats[case], refs)
        cases += process_rows(env, plan["process"], repeats["process"])
        infos = {s: workers[s].ask("info") for s in SIDES}
    finally:
        for w in workers.values():
            w.close()
    refs["pendulum"] = {n: {s: final_tip(r) for s, r in d.items()}
                        for n, d in refs["pendulum"].items()}
    return {"workers": infos, "references": refs, "cases": cases}


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(prog="python -m benchmarks.peers",
                                 description=__doc__.split("\n")[0])
    ap.add_argument("--quick", action="store_true", help="small meshes only, 2 repeats")
    ap.add_argument("--out", type=Path, default=DEFAULT_OUT, help="output folder")
    args = ap.parse_args(argv)
    if exudyn_missing():
        print("peers: exudyn is not installed (pip install -e .[peers]); "
              "side-by-side benchmark skipped")
        return 0
    plan = QUICK if args.quick else FULL
    repeats = {k: QUICK_REPEATS for k in REPEATS} if args.quick else REPEATS
    started = dt.datetime.now(dt.timezone.utc).isoformat(timespec="seconds")
    result = {"schema": 1, "quick": args.quick, "started": started,
              "command": "python -m benchmarks.peers" + (" --quick" if args.quick else ""),
              "machine": machine(), "settings": {**SETTINGS, "repeats": repeats, "cpu": CPU,
                                                 "worker_env": THREAD_ENV, "unset": UNSET_ENV},
              **run_all(plan, repeats)}
    stem = "peers_quick" if args.quick else "peers"
    paths = peers_report.write(result, args.out, stem)
    print("peers: wrote " + ", ".join(str(p) for p in paths))
    return 0


if __name__ == "__main__":
    sys.exit(main())
