"""Speed-accuracy chapter: error vs counted work for every scene, Pareto fronts, and the
cheapest configuration reaching 10 %, 1 %, 0.1 % and 0.01 % error.

Each scene of ``SCENES`` is swept over its report grid (``ancf.study.references``: element x
quadrature x element count x solver tolerance, and x integrator for dynamic scenes)
with :func:`ancf.study.sweep.run_sweep`; the rows go to ``reports/data/speed_accuracy_SCENE.csv``.
Cost is the counted work of :mod:`ancf.study.cost` (the same on every repeat), so the fronts and
the cheapest configurations do not move with timing noise; the measured CPU times and the
per-machine calibration of work to seconds go to the chapter's timing page.
"""
from __future__ import annotations

import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import pandas as pd  # noqa: E402

from ancf.study.cost import FEATURES, calibrate, with_work  # noqa: E402
from ancf.study.references import cache_root, rescore, runner, spec, specs  # noqa: E402
from ancf.reports.chapter import Chapter  # noqa: E402
from ancf.reports.output import (fmt, markdown_table, progress, save_figure,  # noqa: E402
                                 settings, timing_note, write_csv)
from ancf.study.sweep import run_sweep  # noqa: E402
from ancf.study.selection import WORK_SCATTER, WORK_TIE, cheapest_first  # noqa: E402

TOLERANCES = (1e-1, 1e-2, 1e-3, 1e-4)
FLOOR = 1e-16  # plotted in place of an exact zero error


def pareto(df: pd.DataFrame, cost: str = "work", err: str = "error") -> pd.DataFrame:
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


def _schemes(element: str) -> bool:
    """Whether ``element`` takes the ``integration`` knob (the thesis's beams); the belt
    elements and Chrono's elements integrate by their own rules."""
    from ancf.elements.registry import ELEMENTS
    return element in ELEMENTS and bool(getattr(ELEMENTS[element].cls, "schemes", None))


def _model(row, dynamic: bool) -> str:
    """A run's model as the tables and legends name it: the element, with its integration
    scheme or Gauss rule where it takes one, and the integrator of a dynamic run."""
    element = row.get("element")
    if isinstance(element, str) and isinstance(row.get("integration"), str):
        s = f"{element} / {row['integration']}" if _schemes(element) else element
    elif isinstance(element, str) and element not in ("plate36",) and "ng" in row:
        s = element  # Chrono's shells: their own rule, ng is not theirs
    elif "gauss_points" in row:
        s = f"{int(row['gauss_points'])} contact points"
    elif "contact_points" in row:
        s = f"{int(row['contact_points'])} contact points per plate"
    elif "elastic_points" in row:
        s = f"{int(row['elastic_points'])} elastic points"
    else:  # plate36's Gauss rule
        s = f"{int(row['ng'])} × {int(row['ng'])} Gauss points"
    if dynamic:
        integ = row.get("integrator")
        s += f" / {integ}"
    return s


def _solver(row, dynamic: bool) -> str:
    if row.get("quantity") == "frequency":
        return "eigen solve about the reference"
    if dynamic:
        if row.get("integrator") == "generalized-alpha":
            tol = f", Newton tol = {row['newton_tol']:g}" if "newton_tol" in row else ""
            return f"dt = {row['dt']:g}{tol}"
        return f"rtol = {row['rtol']:g}"
    return f"Newton rtol = {row['rtol']:g}" if "rtol" in row else "linear solve"


def _knob_defaults(name: str, s) -> dict:
    """The scene's default value of each model knob (the tie-breaker of last resort)."""
    p = runner(name, s.quantity).resolve({})
    return {k: p[k] for k in s.knobs if k in p}


def cheapest_table(df: pd.DataFrame, dynamic: bool, err: str = "error",
                   defaults: dict | None = None) -> pd.DataFrame:
    """Per tolerance: the cheapest run with error <= tolerance by counted work (the runs
    chained to the least work are equally cheap and go to the least nominal work, then the
    smaller model, ``ancf.study.selection``), or 'not reached'."""
    ok = df[(df["status"] == "ok") & np.isfinite(df[err].astype(float))]
    rows = []
    for tol in TOLERANCES:
        m = ok[ok[err] <= tol]
        if len(m):
            r = cheapest_first(m, err, defaults=defaults).iloc[0]
            rows.append({"error ≤": f"{100 * tol:g} %", "model": _model(r, dynamic),
                         "n_elements": int(r["n_elements"]), "solver": _solver(r, dynamic),
                         "error": float(r[err]), "work": float(r["work"]),
                         "timing: CPU ms": 1e3 * float(r["cpu_time_s"])})
        else:
            best = ok[err].min() if len(ok) else float("nan")
            rows.append({"error ≤": f"{100 * tol:g} %",
                         "model": f"not reached (best error {fmt(float(best), 2)})",
                         "n_elements": None, "solver": None, "error": None, "work": None,
                         "timing: CPU ms": None})
    return pd.DataFrame(rows)


def _label_text(front: pd.DataFrame, dynamic: bool) -> tuple[list, str]:
    """Short labels of the front's runs (the element count, and the time step where the
    front's runs differ in it) and what they are."""
    with_dt = dynamic and "dt" in front and front["dt"].nunique() > 1
    labels = [f"{int(r['n_elements'])}" + (f", {r['dt']:g}" if with_dt else "")
              for _, r in front.iterrows()]
    return labels, "labels: n_elements" + (", dt [s]" if with_dt else "")


def _label_front(ax, front: pd.DataFrame, y, dynamic: bool) -> None:
    """Label the front's runs, leaving out a label too close to the last one written."""
    if "n_elements" not in front:
        return
    labels, what = _label_text(front, dynamic)
    last = None
    for j, (x, yj, text) in enumerate(zip(front["work"].astype(float), y, labels)):
        at = np.log10([x, yj])
        if last is not None and abs(at[0] - last[0]) < 0.06 and abs(at[1] - last[1]) < 0.15:
            continue
        ax.annotate(text, (x, yj), fontsize=6.5, xytext=(5, 4), textcoords="offset points",
                    zorder=6)
        last = at
    ax.text(0.99, 0.98, what, transform=ax.transAxes, fontsize=7, ha="right", va="top")


def plot(df: pd.DataFrame, scene: str, dynamic: bool, ax, err: str = "error", title=None,
         legend: bool = True, ylabel: str = "error"):
    """Error against counted work of every converged run, one marker per model, the Pareto
    front (a step line through circled runs) with its runs labelled (:func:`_label_front`)."""
    ok = df[(df["status"] == "ok") & np.isfinite(df[err].astype(float))]
    groups = ok.groupby([_model(r, dynamic) for _, r in ok.iterrows()])
    markers = "osD^v<>phx*+"
    for k, (label, g) in enumerate(groups):
        ax.loglog(g["work"], np.maximum(g[err].astype(float), FLOOR), markers[k % 12],
                  ms=4, alpha=0.7, label=label)
    front = pareto(ok, err=err)
    if len(front):
        y = np.maximum(front[err].astype(float), FLOOR)
        ax.step(front["work"], y, "k-", where="post", lw=1.2, marker="o", mfc="none", ms=7,
                label="Pareto front" if len(front) > 1 else "Pareto front (one run)", zorder=5)
        _label_front(ax, front, y, dynamic)
    for tol in TOLERANCES:
        ax.axhline(tol, color="0.8", lw=0.6, zorder=0)
    ax.set(xlabel="work per run [units, ancf.study.cost]", ylabel=ylabel, title=title or scene)
    ax.grid(True, which="both", alpha=0.25)
    if legend:  # outside the axes, so it never hides the front
        ax.legend(fontsize=7, loc="upper left", bbox_to_anchor=(1.02, 1.0))


#: the reduced configuration (``--quick``): per sub-grid the two smallest element counts
#: and the first value of every other list; dynamic scenes over a shorter simulated time
QUICK_N = 2
QUICK_FIXED = {"pendulum": {"t_end": 0.2, "output_dt": 0.01},
               "spinning-beam": {"t_end": 2.0, "mean_window": 1.0},
               "belt2d": {"t_end": 0.3},
               "belt3d": {"t_end": 0.05, "output_dt": 0.01, "steady_window": 0.01}}


def quick_grids(grids) -> list:
    """``grids`` reduced for ``--quick`` (see ``QUICK_N``)."""
    return [{k: (sorted(v)[:QUICK_N] if k == "n_elements" else list(v)[:1])
             if k not in ("element", "integration") else list(v) for k, v in g.items()}
            for g in grids]


def scene_grids(scene: str, quantity: str = "results",
                fixed: dict | None = None) -> tuple[list, dict]:
    """(grids, fixed parameters) of the scene's speed-accuracy sweep in this report run
    (``fixed``: the chapter's own, beside the reduced configuration's)."""
    s = spec(scene, quantity)
    fixed = dict(fixed or {})
    if settings().quick:
        return quick_grids(s.report_grids), {**QUICK_FIXED.get(scene, {}), **fixed}
    return list(s.report_grids), fixed


def slug(scene: str, quantity: str = "results") -> str:
    """The scene's file-name stem in this chapter (``_frequency`` appended for frequencies)."""
    return scene.replace("-", "_") + ("" if quantity == "results" else f"_{quantity}")


def scene_sweep(scene: str, workers=None, fresh: bool = True, out=None,
                quantity: str = "results", fixed: dict | None = None) -> pd.DataFrame:
    """The scene's rows (fresh unless ``fresh=False``: resumed) with their counted work."""
    out = out or cache_root() / "speed_accuracy" / f"{slug(scene, quantity)}.parquet"
    if fresh:
        for p in (out, out.with_name(out.name + ".journal.jsonl")):
            if p.exists():
                p.unlink()
    grids, fixed = scene_grids(scene, quantity, fixed)
    df = run_sweep(scene, grids, out=out, fixed=fixed, workers=workers, time_limit=300.0,
                   progress=False, log=progress, quantity=quantity)
    return with_work(df[df["scene"] == scene])


_CSV_COLS = ("element", "integration", "n_elements", "ng", "gauss_points", "contact_points", "elastic_points",
             "integrator", "rtol", "atol", "dt", "newton_tol", "load_steps", "status", "message", "error", "error_self", "work", "cpu_time_s",
             "steps", "iterations") + tuple(f"count_{k}" for k in FEATURES)

_INTRO = (
    "Generated by `python -m ancf.reports`; do not edit. For every scene, every configuration "
    "of the grid below is one run of `ancf run SCENE` in a single-threaded worker process "
    "(`ancf sweep SCENE` runs the same grid); error is against the scene's reference "
    "(`ancf/study/references.py`). Cost is the run's counted work (`ancf/study/cost.py`: iterations, "
    "kernel evaluations × elements × quadrature points, factorisations × size, steps, "
    "weighted by a fixed model), which is the same on every repeat on one machine, so the "
    "Pareto fronts and the cheapest configurations below do not move with timing noise. "
    "Across machines (another CPU, BLAS or compiler) round-off can steer Newton: counted work "
    "of the contact runs differs by up to about 10 % (belt2d: 10933 against 9896 Newton "
    "iterations on two machines); the rule for 'cheapest' below is built so that its "
    "picks do not move with that scatter. The "
    "measured CPU times (process time on the machine that generated this report; identical "
    "runs scatter by 10-30 %) do not decide; they are on the timing page "
    "([timing/speed_accuracy.md](timing/speed_accuracy.md)) with the calibration of work to "
    "seconds on that machine. The Pareto front connects the runs that no "
    "other run beats in both work and error. 'Cheapest' treats the runs chained to the "
    "least work by gaps below {gap:g}× (each run's work within {gap:g}× of the next cheaper "
    "one) as equally cheap, and takes among them the least nominal work (kernel points of "
    "one tangent evaluation × steps: the computation's size without the iteration counts "
    "that round-off steers), then the smallest model, then the smallest error, then the "
    "scene's default settings (`ancf/study/selection.py`): on every sweep of this chapter the "
    "picks stay the same when each run's work moves by ±{scatter:g} % (tests/study/test_selection.py). "
    "`ancf recommend SCENE --tol TOL` answers the last question of "
    "each section for a given tolerance. The natural frequencies (`--quantity frequency`) "
    "have their own chapter, speed_accuracy_frequencies.md.\n")


def _references_table(sp: dict) -> list:
    parts = ["| scene | reference | error definition | physics needed | other references |",
             "|---|---|---|---|---|"]
    for name, s in sp.items():
        others = ", ".join(k for k in s.references if k != s.default_reference)
        parts.append(f"| `{name}` | {s.default_reference} | {s.reference().doc} | "
                     f"{', '.join(sorted(s.needs))} | {others or '—'} |")
    return parts + [""]


def _figure(df: pd.DataFrame, name: str, s) -> str:
    ncols = 2 if "error_self" in df else 1
    fig, axes = plt.subplots(1, ncols, figsize=(6.2 * ncols + 2.6, 4.4), squeeze=False)
    plot(df, name, s.dynamic, axes[0][0], title=f"{name}: error vs {s.default_reference}",
         legend=ncols == 1, ylabel=s.reference().measure)
    if ncols == 2:
        plot(df, name, s.dynamic, axes[0][1], err="error_self",
             title=f"{name}: error vs converged self-reference",
             ylabel=s.references["self"].measure)
    stem = f"pareto_{slug(name, s.quantity)}"
    save_figure(fig, stem)
    return stem


def figures_from_data(scenes=None) -> list:
    """Redraw the Pareto figures from the committed rows ``data/speed_accuracy_SCENE.csv``
    (no sweep is run); returns the scenes drawn.  ``python -m
    ancf.reports.speed_accuracy`` does it for every scene with a CSV.  A knob the CSV
    leaves out (the plates' ``ng``) was not swept: it takes the scene's default."""
    drawn = []
    for name, s in specs().items():
        path = settings().root / "data" / f"speed_accuracy_{slug(name, s.quantity)}.csv"
        if (scenes is None or name in scenes) and path.exists():
            df = pd.read_csv(path)
            missing = {k: v for k, v in _knob_defaults(name, s).items() if k not in df}
            _figure(df.assign(**missing), name, s)
            drawn.append(name)
    return drawn


def scene_section(name: str, s, df: pd.DataFrame,
                  fixed: dict | None = None) -> tuple[list, bool]:
    """(markdown lines, PASS) of one scene's section from its sweep rows (``fixed``: the
    parameters its sweep fixed beside the reduced configuration's)."""
    stem = slug(name, s.quantity)
    grids, fixed = scene_grids(name, s.quantity, fixed)
    grid_txt = "; ".join(" × ".join(f"{k} ∈ {{{', '.join(map(str, v))}}}" for k, v in g.items())
                         for g in grids)
    if fixed:
        grid_txt += (" (reduced configuration, with " if settings().quick else " (with ") + \
            ", ".join(f"{k} = {v:g}" for k, v in fixed.items()) + ")"
    if "self" in s.references and s.default_reference != "self" and not s.dynamic:
        df = df.assign(error_self=rescore(df, name, "self"))
    write_csv(df[[c for c in _CSV_COLS if c in df]].rename(
        columns={"cpu_time_s": "timing: cpu_time_s"}), f"speed_accuracy_{stem}")
    figure = _figure(df, name, s)
    defaults = _knob_defaults(name, s)
    table = cheapest_table(df, s.dynamic, defaults=defaults)
    counts = df["status"].value_counts().to_dict()
    front = pareto(df[df["status"] == "ok"])
    parts = [f"## `{name}`\n", f"{s.notes} Grid: {grid_txt} ({len(df)} runs: "
             + ", ".join(f"{k} {v}" for k, v in counts.items()) + "). Reference: "
             f"{s.reference().doc}.\n",
             f"![pareto {name}](figures/{figure}.png)\n",
             f"Cheapest configuration per error level (against {s.default_reference}):\n",
             markdown_table(table, 3, f"`{name}`: cheapest configurations"), ""]
    extra = ""
    if "error_self" in df:
        parts += ["Against the converged self-reference (`--reference self`: discretisation "
                  "error only):\n",
                  markdown_table(cheapest_table(df, s.dynamic, "error_self", defaults), 3,
                                 f"`{name}`: cheapest against the self-reference"), ""]
        extra = _self_note(df, s.reference().kind)
    parts += [f"Pareto front: {len(front)} of {len(df)} runs. " + _front_text(front, s.dynamic)
              + extra + "\n", f"Data: `data/speed_accuracy_{stem}.csv`.\n"]
    return parts, bool(len(front)) and len(table) == len(TOLERANCES)


def calibration_table(frames: dict) -> pd.DataFrame:
    """Per scene, seconds ~ sum_k c_k count_k fitted over its finished rows (``ancf.study.cost``)."""
    rows = []
    for name, df in frames.items():
        cal = calibrate(df[df["status"] == "ok"])
        if cal is None:
            continue
        row = {"scene": name, "rows": cal.rows}
        row.update({f"{k} [µs]": 1e6 * v for k, v in cal.seconds_per.items()})
        row.update({"fit scatter median": cal.scatter_median, "fit scatter p90": cal.scatter_p90,
                    "ns per work unit": 1e9 * cal.seconds_per_work})
        rows.append(row)
    return pd.DataFrame(rows)


def _calibration_section(frames: dict) -> list:
    table = calibration_table(frames)
    if not len(table):
        return []
    write_csv(table, "timing/speed_accuracy_calibration")
    timing_note(
            "Calibration of work to seconds on this machine",
            "Non-negative least squares of each scene's measured CPU times on its counted work "
            "(relative residuals): seconds ≈ Σ c_k × count_k over runs (set-up), calls, kernel "
            "points, factorised coordinates and the dense stability check's coordinates³; "
            "scatter = |predicted / measured − 1|. The last column is the machine's time per "
            "unit of the fixed-weight work that ranks the runs (median of seconds / work). "
            "Data: `../data/timing/speed_accuracy_calibration.csv`.\n", markdown_table(table, 3))
    return ["## Calibration of work to seconds\n",
            "Each scene's measured CPU times fitted on its counted work (seconds per counted "
            "feature, the fit's scatter): on the timing page, since it varies per run and "
            "machine.\n"]


#: swept before the others: the longest sweep, whose runs the 3D belt chapter of the other
#: report process reads (ancf.scenes.store; GROUPS in ancf.reports.__main__)
FIRST = ("belt3d",)


def sweep_workers(workers=None) -> int:
    """The sweeps' processes: ``workers`` if given; else one in a quick report (each of its
    workers would compile the same kernels for its few short runs: the 3D beam element's
    50 CPU-s twice from a cold cache) and one per core in a full one."""
    return workers or (1 if settings().quick else os.cpu_count())


def _sweeps(names, workers) -> dict:
    """{scene: its rows, or the exception its sweep raised}, :data:`FIRST` swept first."""
    got = {}
    for name in sorted(names, key=lambda n: n not in FIRST):  # stable: otherwise in order
        progress(f"speed-accuracy sweep: {name}")
        try:
            got[name] = scene_sweep(name, workers)
        except Exception as exc:  # noqa: BLE001 - one broken scene must not hide the others
            got[name] = exc
    return got


def speed_accuracy_chapter(workers=None) -> tuple[str, dict]:
    """(markdown, status) of the speed-accuracy chapter for every scene in ``SCENES``."""
    status, frames = {}, {}
    sp = specs()
    parts = ["# Speed versus accuracy\n", _INTRO.format(gap=1 + WORK_TIE,
                                                            scatter=100 * WORK_SCATTER)]
    parts += _references_table(sp)
    swept = _sweeps(list(sp), sweep_workers(workers))
    for name, s in sp.items():
        key = f"Speed–accuracy {name}: Pareto plot + cheapest-configuration table"
        if isinstance(swept[name], Exception):
            exc = swept[name]
            status[key] = f"FAIL: the sweep did not run ({type(exc).__name__}: {exc})"
            parts += [f"## `{name}`\n", status[key] + "\n"]
            continue
        frames[name] = swept[name]
        lines, ok = scene_section(name, s, frames[name])
        parts += lines
        status[key] = "PASS" if ok else "FAIL"
    parts += _calibration_section(frames)
    return "\n".join(parts), status


def _front_text(front: pd.DataFrame, dynamic: bool) -> str:
    if not len(front):
        return "no converged run."
    models = front.apply(lambda r: _model(r, dynamic), axis=1).value_counts()
    return "Models on the front: " + ", ".join(f"{m} ({c})" for m, c in models.items()) + "."


def _self_note(df: pd.DataFrame, kind: str) -> str:
    """``kind``: of the default reference (analytic, or published: another code's values)."""
    ok = df[df["status"] == "ok"]
    if not len(ok) or "error_self" not in ok:
        return ""
    best = ok["error"].min()
    best_self = ok["error_self"].min()
    if best_self < best / 10:
        return (f" The error against the {kind} reference levels off at {best:.1e} while the "
                f"self-reference error keeps falling (to {best_self:.1e}): that floor is the "
                f"difference between the ANCF continuum and the {kind} model, not "
                "discretisation.")
    return (f" Both references give the same picture (best errors {best:.1e} and "
            f"{best_self:.1e}).")


CHAPTER = Chapter(
    file="speed_accuracy.md", order=30, generate=speed_accuracy_chapter,
    checks=("ancf.reports.speed_accuracy",),
    process="sweeps",
    contents="Error vs counted work per scene, Pareto fronts, cheapest configuration "
             "per error level (CPU times and the calibration of work to seconds on "
             "its timing page)")


if __name__ == "__main__":
    print("redrawn:", ", ".join(figures_from_data()))
