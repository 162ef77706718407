"""The floor under the plate belt's march: how much cheaper per simulated second it
could get at today's model (issue 36 asks for five times).

    python -m benchmarks.belt3d_floor [--window 0.02] [--out reports/benchmarks]

Per case (:data:`CASES`: the belt3d scene's Model 2; ``examples/three_pulleys_3d.toml``):

1. the case's own run, its CPU time per simulated second and its states at the window
   starts;
2. from each state, a window of ``--window`` s marched with each lever of
   :data:`LEVERS` (the march's Newton settings, twice the step, fewer contact points):
   CPU per simulated second, per step the residual evaluations, iteration matrices and
   Newton iterations, the halved steps, and the end state against today's settings'
   (largest coordinate difference over the largest coordinate);
3. the cost of one residual evaluation at the window's start (the march's own
   evaluation: gather, elastic forces, contact, assembly; median of warm calls), once
   per drive (the step and the Newton settings do not change it);
4. the floor of each window: the fewest residual evaluations per simulated second any
   lever needed, times that lever's cost of one residual, with iteration matrices,
   factorisations and solves taken as free.  A march that evaluates residuals as
   often as the best lever cannot be cheaper than this, whatever it does about its
   matrices.  Over the run, each window stands for the times nearer to it than to the
   others (weights ``w``): floor = sum w_k floor_k / t_end, against sum w_k cpu_k /
   t_end of today's settings; their ratio bounds the speed-up.

Writes ``belt3d_floor.json`` (keys ``schema``, ``started``, ``command``, ``machine``,
``settings``, ``cases``: per case ``run_cpu_per_s``, ``windows`` (per start ``t``,
``weight_s``, ``residual_us`` per lever, ``levers``: per lever ``cpu_per_s``,
``residuals_per_step``, ``matrices_per_step``, ``iterations_per_step``, ``steps``,
``halved``, ``converged``, ``state_difference``, ``floor_per_s``), ``floor_per_s``,
``today_per_s``, ``bound``) and ``belt3d_floor.md``.
"""
from __future__ import annotations

import argparse
import dataclasses
import statistics
import time
from pathlib import Path

import numpy as np

from ancf.belts.dynamics import BeltOptions, simulate
from ancf.common.threads import one_blas_thread
from benchmarks import peers
from benchmarks.belt3d_newton import OneStep

#: name -> (scene, parameters, window starts (s))
CASES = {"belt3d Model 2": ("belt3d", {"model": 2}, (0.1, 0.4, 0.7, 1.0)),
         "three_pulleys_3d.toml": ("belt-drive", {"file": "examples/three_pulleys_3d.toml"},
                                   (0.1, 0.3, 0.5))}
#: label -> (march settings, scene parameters); the first is today's
LEVERS = {"today's settings": ({}, {}),
          "full Newton (a fresh matrix every iteration)": ({"refresh_ratio": 1e-9}, {}),
          "refresh at |d_k| > 0.2 |d_k-1|": ({"refresh_ratio": 0.2}, {}),
          "refresh at |d_k| > 0.8 |d_k-1|": ({"refresh_ratio": 0.8}, {}),
          "refresh once per step": ({"refresh": "once"}, {}),
          "accept the evaluated iterate": ({"newton_accept": "evaluated"}, {}),
          "twice the step": ({"dt": 2.0}, {}),
          "25 contact points per plate": ({}, {"contact_points": 25})}
MAX_WINDOW = 0.1  # s: the last window of each case still ends within its run
OPTION_KEYS = ("dt", "rho_inf", "newton_tol", "refresh_ratio", "newton_accept", "refresh",
               "give_up", "max_steps")
RULE_KEY = {"belt3d": "contact_points", "belt-drive": "gauss_points"}


def _options(scene: str, out: dict, res) -> BeltOptions:
    """The march settings the case's run used."""
    r = res.extra["description"].run if scene == "belt-drive" else out["params"]
    return BeltOptions(**{k: r[k] for k in OPTION_KEYS if k in r})


def _drive(scene: str, params: dict, extra: dict):
    """The case's drive with the scene parameters ``extra`` (a 1 ms run builds it)."""
    from ancf.scenes import SCENES
    short = {"set": "run.t_end=0.001; run.output_dt=0.001; run.steady_window=0.001"} \
        if scene == "belt-drive" else {"t_end": 1e-3, "output_dt": 1e-3}
    extra = {RULE_KEY[scene]: v for v in extra.values()}
    return SCENES[scene].execute({**params, **short, **extra})[1].extra["drive"]


def residual_cost(drive, x, v, t: float, h: float, repeats: int = 50) -> float:
    """Seconds per residual evaluation of the march at (x, v, t), warm, median."""
    one = OneStep(drive, x, v, t, h)
    acc = one.st[2].copy()
    one.residual(acc)
    samples = []
    for _ in range(repeats):
        t0 = time.perf_counter()
        one.residual(acc)
        samples.append(time.perf_counter() - t0)
    return statistics.median(samples)


def window(drive, x, v, t: float, span: float, opt: BeltOptions) -> dict:
    """A march of ``span`` s from (x, v) at t: its costs and end state."""
    sim = simulate(drive, np.linspace(t, t + span, 3), opt, x0=x, v0=v)
    n = max(sim.steps, 1)
    return {"cpu_per_s": sim.cpu_time_s / span, "residuals_per_step": sim.nfev / n,
            "matrices_per_step": sim.njev / n, "iterations_per_step": sim.newton_iterations / n,
            "steps": sim.steps, "halved": sim.rejected_steps, "converged": bool(sim.converged),
            "end": sim.q[-1] if sim.converged else None}


def case_windows(scene: str, params: dict, starts, span: float) -> dict:
    """Today's run, then every lever over a window from each start."""
    from ancf.scenes import SCENES
    out, res = SCENES[scene].execute(params)
    run, opt = res.extra["result"], _options(scene, out, res)
    drives = {label: res.extra["drive"] if not extra else _drive(scene, params, extra)
              for label, (_, extra) in LEVERS.items()}
    t_end, rows = float(run.t[-1]), []
    edges = np.r_[0.0, (np.array(starts[1:]) + starts[:-1]) / 2, t_end]
    for i, t in enumerate(starts):
        k = int(np.argmin(np.abs(run.t - t)))
        x, v = run.q[k], run.v[k]
        row = {"t": float(run.t[k]), "weight_s": float(edges[i + 1] - edges[i]),
               "residual_us": {}, "levers": {}}
        cost = {id(d): residual_cost(d, x, v, row["t"], opt.dt) * 1e6 for d in drives.values()}
        for label, (change, _) in LEVERS.items():
            o = dataclasses.replace(opt, **{key: val * opt.dt if key == "dt" else val
                                            for key, val in change.items()})
            d = drives[label]
            row["residual_us"][label] = cost[id(d)]
            w = window(d, x, v, row["t"], span, o)
            w["floor_per_s"] = (w["residuals_per_step"] * w["steps"] / span
                                * row["residual_us"][label] * 1e-6) if w["converged"] else None
            row["levers"][label] = w
        base = row["levers"]["today's settings"]["end"]
        for w in row["levers"].values():
            end = w.pop("end")
            w["state_difference"] = (float(np.max(np.abs(end - base)) / np.max(np.abs(base)))
                                     if end is not None and base is not None else None)
        rows.append(row)
    floor = sum(r["weight_s"] * min(w["floor_per_s"] for w in r["levers"].values()
                                    if w["floor_per_s"]) for r in rows) / t_end
    today = sum(r["weight_s"] * r["levers"]["today's settings"]["cpu_per_s"] for r in rows) / t_end
    return {"run_cpu_per_s": float(out["results"]["integration_cpu_s"]) / t_end,
            "windows": rows, "floor_per_s": floor, "today_per_s": today, "bound": today / floor}


READING = """## Reading

The floor takes the iteration matrices, their factorisations and the solves as free and
keeps only the residual evaluations of the lever that needed the fewest per simulated
second; a march cannot go below it unless it evaluates fewer residuals than every lever
here.  Each residual is the whole belt's forces: the elastic forces and the contact at
every point of every plate near a pulley (81 or 49 per plate), all compiled.  The
count per step is set by Newton: at speed, rows of contact points enter and leave each
pulley within a step, and even a fresh matrix at every iteration (full Newton) needs
4-6 iterations; twice the step halves steps at speed and costs more.  Fewer contact
points make a residual cheaper but need more of them."""


def _cell(label: str) -> str:
    """A lever's label in a Markdown table cell (its norms' bars escaped)."""
    return label.replace("|", "\\|")


def _weighted(rows: list) -> str:
    """Each lever's CPU per simulated second over the run (the windows weighted as the
    floor's), against today's settings."""
    total = sum(r["weight_s"] for r in rows)
    cost = {label: sum(r["weight_s"] * r["levers"][label]["cpu_per_s"] for r in rows) / total
            for label in rows[0]["levers"]}
    today = cost["today's settings"]
    return ("| lever | CPU-s per simulated s, windows weighted | today's / lever's |\n"
            "|---|---|---|\n" + "\n".join(f"| {_cell(k)} | {v:.1f} | {today / v:.2f} |"
                                         for k, v in cost.items()))


def _table(res: dict) -> str:
    head = ("| window start (s) | lever | CPU-s per simulated s | residuals / step | "
            "matrices / step | iterations / step | halved steps | end state vs today's | "
            "one residual (µs) | floor (CPU-s per simulated s) |\n" + "|---" * 10 + "|")
    parts = [f"# The floor under the plate belt's march\n\nGenerated by `{res['command'].strip()}` "
             f"on {res['started']} ({res['machine']['cpu_model']}, one BLAS thread). Windows of "
             f"{res['settings']['window_s']} s from states of each case's own run; the floor "
             "counts residual evaluations only (module docstring).\n"]
    for name, c in res["cases"].items():
        parts.append(f"## {name}\n\nIts run: {c['run_cpu_per_s']:.1f} CPU-s per simulated s. "
                     f"Windows weighted over the run: today {c['today_per_s']:.1f}, floor "
                     f"{c['floor_per_s']:.1f} CPU-s per simulated s: at most "
                     f"**{c['bound']:.2f}×** cheaper; five times cheaper needs "
                     f"{c['today_per_s'] / 5:.1f}.\n")
        parts.append(_weighted(c["windows"]) + "\n\n" + head)
        for r in c["windows"]:
            for label, w in r["levers"].items():
                diff = "—" if w["state_difference"] is None else f"{w['state_difference']:.1e}"
                fl = "—" if w["floor_per_s"] is None else f"{w['floor_per_s']:.1f}"
                parts.append(f"| {r['t']:g} | {_cell(label)} | {w['cpu_per_s']:.1f} | "
                             f"{w['residuals_per_step']:.2f} | {w['matrices_per_step']:.2f} | "
                             f"{w['iterations_per_step']:.2f} | {w['halved']} | {diff} | "
                             f"{r['residual_us'][label]:.0f} | {fl} |")
        parts.append("")
    parts.append(READING)
    return "\n".join(parts) + "\n"


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--window", type=float, default=0.02)
    ap.add_argument("--out", default=str(peers.ROOT / "reports" / "benchmarks"))
    a = ap.parse_args(argv)
    if not 0.0 < a.window <= MAX_WINDOW:
        ap.error(f"--window must be in (0, {MAX_WINDOW:g}] s (got {a.window:g})")
    one_blas_thread()
    result = peers.record("belt3d_floor", argv or [], {"window_s": a.window})
    result["cases"] = {}
    for name, (scene, params, starts) in CASES.items():
        print(f"{name} ...", flush=True)
        result["cases"][name] = case_windows(scene, params, starts, a.window)
    peers.write(Path(a.out), "belt3d_floor", result, _table(result))
    print(_table(result))
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
