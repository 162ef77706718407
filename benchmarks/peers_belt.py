"""Belt drive side by side with Exudyn: thesis chapter 3, 1 s, n = 20 and 40 elements.

    python -m benchmarks.peers_belt [--quick] [--out reports/benchmarks]

Writes ``peers_belt.md`` (see :mod:`benchmarks.peers_belt_report`) and
``peers_belt.json``; ``--quick`` runs n = 20 once (``peers_belt_quick.*``).  Without
exudyn importable, or with ``ANCF_PEERS_NO_EXUDYN=1``, prints one line and exits 0.

Measurement as in :mod:`benchmarks.peers`: one long-lived worker per code, one BLAS
thread, OPENBLAS_CORETYPE / OPENBLAS_L2_SIZE unset; per n each side first runs a short
warm-up (t_end = WARMUP_T_END), then ``repeats`` full runs alternating ours, Exudyn;
medians.  Ours is the scene's ``cpu_time_s`` (build and settling included), Exudyn's
``total_cpu_s`` (build, static pre-tension and dynamic solve; its dynamic solve alone
is ``cpu_s``).  While our scene ``belt2d`` is not registered, ours is recorded as
pending and Exudyn's numbers are still measured.  Exudyn's step convergence: per n one
untimed run with half the step.

JSON keys: ``schema``, ``quick``, ``started``, ``command``, ``machine``, ``workers``,
``settings``, ``cases`` (per n: ``n``, ``ours``, ``exudyn``, ``exudyn_half_step``,
``ratio`` = ours cpu_s / Exudyn total_cpu_s, ``ratio_dynamic`` = ours cpu_s / Exudyn
cpu_s, ``ratio_paired``); each side holds its last answer (without the time series),
``cpu_s_samples`` and, for Exudyn, ``total_cpu_s_samples``; ``series`` (per n and side:
``t`` [s] and ``omega_driven`` [rad/s] of the last run, for a plot).
"""
from __future__ import annotations

import argparse
import datetime as dt
import sys
from pathlib import Path

from benchmarks import peers, peers_belt_report
from benchmarks.peers_belt_exudyn import SEGMENTS, STEP, STICK_SPRING, TABLE, wrapped_length

NS, QUICK_NS = (20, 40), (20,)
REPEATS, QUICK_REPEATS = 3, 1
T_END, WARMUP_T_END = 1.0, 0.01
PENDING = "ours: pending (scene belt2d not registered)"
SETTINGS = {
    "ours": "scene belt2d, params {n_elements: n, t_end: 1.0} (the scene's defaults "
            "otherwise: dt 2.5e-4 s, generalised-alpha rho_inf 0.5, 7 contact points); "
            "static frictionless pre-tension first, like Exudyn's",
    "exudyn": f"ObjectANCFCable2D loop, ObjectContactFrictionCircleCable2D per element and "
              f"pulley ({SEGMENTS} segments), static pre-tension, then generalised-alpha h = {STEP:g} s "
              "(fixed; Exudyn halves it when Newton fails), spectralRadius 0.5, modified "
              "Newton, EigenSparse, discontinuous iterations <= 7",
}


def _split(ans: dict) -> tuple:
    """(answer without the time series, its series)."""
    series = {"t": ans.get("t_series"), "omega_driven": ans.get("omega_driven_series")}
    return {k: v for k, v in ans.items() if not k.endswith("_series")}, series


def run_pair(workers: dict, n: int, repeats: int) -> dict:
    """Warm-up, then ``repeats`` alternating full runs; medians and the last answers."""
    sides = [s for s in peers.SIDES if "pending" not in workers[s].ask("belt", n,
                                                                         t_end=WARMUP_T_END)]
    last, samples, totals = {}, {s: [] for s in peers.SIDES}, []
    for _ in range(repeats):
        for s in sides:
            last[s] = workers[s].ask("belt", n, t_end=T_END)
            samples[s].append(last[s].get("cpu_s"))
        totals.append(last["exudyn"].get("total_cpu_s"))
    return _row(workers, n, last, samples, totals)


def _row(workers, n, last, samples, totals) -> dict:
    ours, ours_series = _split(last.get("ours", {"pending": PENDING}))
    exu, exu_series = _split(last["exudyn"])
    ours |= {"cpu_s": peers._median(samples["ours"]), "cpu_s_samples": samples["ours"]}
    exu |= {"cpu_s": peers._median(samples["exudyn"]), "cpu_s_samples": samples["exudyn"],
            "total_cpu_s": peers._median(totals), "total_cpu_s_samples": totals}
    half, _ = _split(workers["exudyn"].ask("belt", n, t_end=T_END, step=STEP / 2))
    paired = [peers._ratio(a, b) for a, b in zip(samples["ours"], totals)]
    return {"n": n, "ours": ours, "exudyn": exu, "exudyn_half_step": half,
            "ratio": peers._ratio(ours["cpu_s"], exu["total_cpu_s"]),
            "ratio_dynamic": peers._ratio(ours["cpu_s"], exu["cpu_s"]),
            "ratio_paired": [r for r in paired if r is not None],
            "series": {"ours": ours_series, "exudyn": exu_series}}


def run_all(ns, repeats: int) -> dict:
    workers = {s: peers.Worker(s, peers.worker_env()) for s in peers.SIDES}
    try:
        cases = [run_pair(workers, n, repeats) for n in ns]
        infos = {s: workers[s].ask("info") for s in peers.SIDES}
    finally:
        for w in workers.values():
            w.close()
    return {"workers": infos, "cases": cases}


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(prog="python -m benchmarks.peers_belt",
                                 description=__doc__.split("\n")[0])
    ap.add_argument("--quick", action="store_true", help="n = 20 only, one run")
    ap.add_argument("--out", type=Path, default=peers.DEFAULT_OUT, help="output folder")
    args = ap.parse_args(argv)
    if peers.exudyn_missing():
        print("peers_belt: exudyn is not installed (pip install -e .[peers]); "
              "belt side-by-side skipped")
        return 0
    repeats = QUICK_REPEATS if args.quick else REPEATS
    result = {"schema": 1, "quick": args.quick,
              "started": dt.datetime.now(dt.timezone.utc).isoformat(timespec="seconds"),
              "command": "python -m benchmarks.peers_belt" + (" --quick" if args.quick else ""),
              "machine": peers.machine(),
              "settings": {**SETTINGS, "repeats": repeats,
                           "model": {"table": TABLE, "wrapped_length": wrapped_length(),
                                     "segments": SEGMENTS, "stick_spring": STICK_SPRING}, "t_end": T_END,
                           "warmup_t_end": WARMUP_T_END, "worker_env": peers.THREAD_ENV,
                           "unset": peers.UNSET_ENV},
              **run_all(QUICK_NS if args.quick else NS, repeats)}
    stem = "peers_belt_quick" if args.quick else "peers_belt"
    paths = peers_belt_report.write(result, args.out, stem)
    print("peers_belt: wrote " + ", ".join(str(p) for p in paths))
    return 0


if __name__ == "__main__":
    sys.exit(main())
