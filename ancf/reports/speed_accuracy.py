"""Speed-accuracy chapter: error vs CPU time for every scene, Pareto fronts, and the
cheapest configuration reaching 10 %, 1 %, 0.1 % and 0.01 % error.

Each scene of ``SCENES`` is swept over its report grid (``ancf.references``: element x
quadrature x element count x solver tolerance, and x integrator for dynamic scenes)
with :func:`ancf.sweep.run_sweep`; the rows go to ``reports/data/speed_accuracy_SCENE.csv``.
"""
from __future__ import annotations

import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import pandas as pd  # noqa: E402

from ancf.references import cache_root, rescore, specs  # noqa: E402
from ancf.reports.output import (fmt, markdown_table, progress, save_figure,  # noqa: E402
                                 write_csv)
from ancf.sweep import run_sweep  # noqa: E402
from ancf.selection import COST_TIE, COST_TIE_ABS_S, cheapest_first  # noqa: E402

TOLERANCES = (1e-1, 1e-2, 1e-3, 1e-4)
FLOOR = 1e-16  # plotted in place of an exact zero error


def pareto(df: pd.DataFrame, cost: str = "cpu_time_s", err: str = "error") -> pd.DataFrame:
    """Rows not dominated in (cost, error): sorted by cost, each more accurate than every
    cheaper one."""
    d = df[np.isfinite(df[err].astype(float)) & np.isfinite(df[cost].astype(float))]
    d = d.sort_values([cost, err], kind="stable")
    keep, best = [], np.inf
    for i, e in zip(d.index, d[err].astype(float)):
        if e < best:
            keep.append(i)
            best = e
    return d.loc[keep]


def _model(row, dynamic: bool) -> str:
    s = f"{row['element']} / {row['integration']}"
    if dynamic:
        integ = row.get("integrator")
        s += f" / {integ}"
    return s


def _solver(row, dynamic: bool) -> str:
    if dynamic:
        if row.get("integrator") == "generalized-alpha":
            return f"dt = {row['dt']:g}"
        return f"rtol = {row['rtol']:g}"
    return f"Newton rtol = {row['rtol']:g}"


def _knob_defaults(name: str, s) -> dict:
    """The scene's default value of each model knob (the tie-breaker of last resort)."""
    from ancf.scenes import SCENES
    p = SCENES[name].resolve({})
    return {k: p[k] for k in s.knobs if k in p}


def cheapest_table(df: pd.DataFrame, dynamic: bool, err: str = "error",
                   defaults: dict | None = None) -> pd.DataFrame:
    """Per tolerance: the cheapest run with error <= tolerance (ties within the timing
    noise go to the smaller model, ``ancf.selection``), or 'not reached'."""
    ok = df[(df["status"] == "ok") & np.isfinite(df[err].astype(float))]
    rows = []
    for tol in TOLERANCES:
        m = ok[ok[err] <= tol]
        if len(m):
            r = cheapest_first(m, err, defaults=defaults).iloc[0]
            rows.append({"error ≤": f"{100 * tol:g} %", "model": _model(r, dynamic),
                         "n_elements": int(r["n_elements"]), "solver": _solver(r, dynamic),
                         "error": float(r[err]), "CPU ms": 1e3 * float(r["cpu_time_s"])})
        else:
            best = ok[err].min() if len(ok) else float("nan")
            rows.append({"error ≤": f"{100 * tol:g} %",
                         "model": f"not reached (best error {fmt(float(best), 2)})",
                         "n_elements": None, "solver": None, "error": None, "CPU ms": None})
    return pd.DataFrame(rows)


def plot(df: pd.DataFrame, scene: str, dynamic: bool, ax, err: str = "error", title=None,
         legend: bool = True):
    ok = df[(df["status"] == "ok") & np.isfinite(df[err].astype(float))]
    groups = ok.groupby([_model(r, dynamic) for _, r in ok.iterrows()])
    markers = "osD^v<>phx*+"
    for k, (label, g) in enumerate(groups):
        ax.loglog(g["cpu_time_s"], np.maximum(g[err].astype(float), FLOOR), markers[k % 12],
                  ms=4, alpha=0.7, label=label)
    front = pareto(ok, err=err)
    if len(front):
        ax.step(front["cpu_time_s"], np.maximum(front[err].astype(float), FLOOR), "k-",
                where="post", lw=1.2, label="Pareto front", zorder=5)
    for tol in TOLERANCES:
        ax.axhline(tol, color="0.8", lw=0.6, zorder=0)
    ax.set(xlabel="CPU time per run [s]", ylabel="error", title=title or scene)
    ax.grid(True, which="both", alpha=0.25)
    if legend:  # outside the axes, so it never hides the front
        ax.legend(fontsize=7, loc="upper left", bbox_to_anchor=(1.02, 1.0))


def scene_sweep(scene: str, workers=None, fresh: bool = True) -> pd.DataFrame:
    out = cache_root() / "speed_accuracy" / f"{scene}.parquet"
    if fresh:
        for p in (out, out.with_name(out.name + ".journal.jsonl")):
            if p.exists():
                p.unlink()
    return run_sweep(scene, None, out=out, workers=workers, time_limit=300.0,
                     progress=False, log=progress)


_CSV_COLS = ("element", "integration", "n_elements", "integrator", "rtol", "atol", "dt",
             "load_steps", "status", "message", "error", "error_self", "cpu_time_s", "steps",
             "iterations")


def speed_accuracy_chapter(workers=None) -> tuple[str, dict]:
    """(markdown, status) of the speed-accuracy chapter for every scene in ``SCENES``."""
    workers = workers or os.cpu_count()
    status = {}
    parts = ["# Speed versus accuracy\n",
             "Generated by `python -m ancf.reports`; do not edit. For every scene, every "
             "configuration of the grid below is one run of `ancf run SCENE` in a single-threaded "
             "worker process (`ancf sweep SCENE` runs the same grid); error is against the "
             "scene's reference (`ancf/references.py`), cost is the CPU time of the run (process "
             "time, measured on the machine that generated this report: identical runs scatter by "
             "10-30 % within one sweep, and on a shared machine all times can shift by a factor "
             "of 2-3 between report runs, so compare times within one report). The Pareto "
             "front connects the runs that no other run beats in both. "
             f"'Cheapest' treats runs within {100 * COST_TIE:g} % (or {1e3 * COST_TIE_ABS_S:g} ms, the "
             "scatter of identical millisecond solves) of the least CPU time as "
             "equally cheap and takes the smallest model among them, then the smallest error, "
             "then the scene's default settings "
             "(`ancf/selection.py`), so that timing noise does not pick between equivalent "
             "models. "
             "`ancf recommend SCENE --tol TOL` answers the last question of each section for a "
             "given tolerance.\n"]
    sp = specs()
    rows = [{"scene": name, "reference": s.default_reference,
             "error definition": s.reference().doc, "physics needed": ", ".join(sorted(s.needs)),
             "other references": ", ".join(k for k in s.references if k != s.default_reference)}
            for name, s in sp.items()]
    parts += ["| scene | reference | error definition | physics needed | other references |",
              "|---|---|---|---|---|"]
    parts += [f"| `{r['scene']}` | {r['reference']} | {r['error definition']} | "
              f"{r['physics needed']} | {r['other references'] or '—'} |" for r in rows]
    parts.append("")
    for name, s in sp.items():
        progress(f"speed-accuracy sweep: {name}")
        try:
            df = scene_sweep(name, workers)
        except Exception as exc:  # noqa: BLE001 - one broken scene must not hide the others
            msg = f"FAIL: the sweep did not run ({type(exc).__name__}: {exc})"
            parts += [f"## `{name}`\n", msg + "\n"]
            status[f"Speed–accuracy {name}: Pareto plot + cheapest-configuration table"] = msg
            continue
        df = df[df["scene"] == name]
        grid_txt = "; ".join(" × ".join(f"{k} ∈ {{{', '.join(map(str, v))}}}" for k, v in g.items())
                             for g in s.report_grids)
        extra = ""
        if "self" in s.references and s.default_reference != "self" and not s.dynamic:
            df = df.assign(error_self=rescore(df, name, "self"))
        data = df[[c for c in _CSV_COLS if c in df]]
        write_csv(data, f"speed_accuracy_{name.replace('-', '_')}")
        ncols = 2 if "error_self" in df else 1
        fig, axes = plt.subplots(1, ncols, figsize=(6.2 * ncols + 2.6, 4.4), squeeze=False)
        plot(df, name, s.dynamic, axes[0][0], title=f"{name}: error vs {s.default_reference}",
             legend=ncols == 1)
        if ncols == 2:
            plot(df, name, s.dynamic, axes[0][1], err="error_self",
                 title=f"{name}: error vs converged self-reference")
        save_figure(fig, f"pareto_{name.replace('-', '_')}")
        defaults = _knob_defaults(name, s)
        table = cheapest_table(df, s.dynamic, defaults=defaults)
        counts = df["status"].value_counts().to_dict()
        front = pareto(df[df["status"] == "ok"])
        parts += [f"## `{name}`\n", f"{s.notes} Grid: {grid_txt} ({len(df)} runs: "
                  + ", ".join(f"{k} {v}" for k, v in counts.items()) + "). Reference: "
                  f"{s.reference().doc}.\n",
                  f"![pareto {name}](figures/pareto_{name.replace('-', '_')}.png)\n",
                  f"Cheapest configuration per error level (against {s.default_reference}):\n",
                  markdown_table(table, 3), ""]
        if ncols == 2:
            parts += ["Against the converged self-reference (`--reference self`: discretisation "
                      "error only):\n", markdown_table(cheapest_table(df, s.dynamic, "error_self", defaults), 3),
                      ""]
            extra = _self_note(df)
        parts += [f"Pareto front: {len(front)} of {len(df)} runs. " + _front_text(front, s.dynamic)
                  + extra + "\n", f"Data: `data/speed_accuracy_{name.replace('-', '_')}.csv`.\n"]
        status[f"Speed–accuracy {name}: Pareto plot + cheapest-configuration table"] = (
            "PASS" if len(front) and len(table) == len(TOLERANCES) else "FAIL")
    return "\n".join(parts), status


def _front_text(front: pd.DataFrame, dynamic: bool) -> str:
    if not len(front):
        return "no converged run."
    models = front.apply(lambda r: _model(r, dynamic), axis=1).value_counts()
    return "Models on the front: " + ", ".join(f"{m} ({c})" for m, c in models.items()) + "."


def _self_note(df: pd.DataFrame) -> str:
    ok = df[df["status"] == "ok"]
    if not len(ok) or "error_self" not in ok:
        return ""
    best = ok["error"].min()
    best_self = ok["error_self"].min()
    if best_self < best / 10:
        return (f" The error against the analytic reference levels off at {best:.1e} while the "
                f"self-reference error keeps falling (to {best_self:.1e}): that floor is the "
                "difference between the ANCF continuum and the analytic model, not "
                "discretisation.")
    return (f" Both references give the same picture (best errors {best:.1e} and "
            f"{best_self:.1e}).")
