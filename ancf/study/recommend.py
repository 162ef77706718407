"""The cheapest adequate model: ``ancf recommend SCENE --tol 1e-3``.

From sweep data (``--data FILE``, or a sweep of the scene's recommendation grid run on
demand and cached under ``reports/.cache/recommend/``), the cheapest configuration
(least counted work; runs chained to the least work by gaps below 1.4 are equally cheap
and go to the least nominal work, then the smallest model, so the pick does not move
with the machine-to-machine scatter of the counts: see ``ancf.study.selection`` and
``ancf.study.cost``; the measured CPU time is reported, not ranked)
whose error against the scene's reference is at most ``tol``, among the configurations
that provide every physics the scene needs (``ancf.study.references``).  The answer carries
its evidence: the error, counted work and CPU time of the chosen run, how many runs
were considered and met the tolerance, the runners-up, the runs excluded for lacking
physics, and how the scene's default model compares (whether a lighter model suffices).
"""
from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pandas as pd

from ancf.study.cost import calibrate, counts, with_work, work
from ancf.study.references import (ReferenceFailed, cache_root, model_physics, runner, spec,
                                   stable_hash)
from ancf.study.selection import WORK_TIE, cheapest_first, tie_group
from ancf.common.inputs import mapping, number
from ancf.common.params import InputError
from ancf.study.sweep import check_table, read_rows, rows_for, run_sweep

MODEL_KEYS = ("element", "integration", "n_elements", "integrator", "rtol", "atol", "dt",
              "load_steps")


def _py(v):
    if isinstance(v, np.generic):
        return v.item()
    if isinstance(v, float) and math.isnan(v):
        return None
    return v


def _params(row, names) -> dict:
    out = {}
    for k in names:
        v = _py(row[k])
        if isinstance(v, float) and v.is_integer() and k in ("n_elements", "load_steps",
                                                              "max_iterations", "max_steps"):
            v = int(v)
        out[k] = v
    return out


def _belt_parts(p: dict) -> list:
    """The mesh and quadrature knobs of the scenes without an element choice (the belt
    scenes: contact and elastic points; the plates: elements across, Gauss points)."""
    parts = [f"n = {p.get('n_elements')}"]
    for key, text in (("n_width", "{} across"), ("gauss_points", "{} contact points"),
                      ("contact_points", "{} contact points per plate"),
                      ("ng", "{0} x {0} Gauss points"), ("elastic_points", "{} elastic points")):
        if _given(p.get(key)):
            parts.append(text.format(p[key]))
    return parts


def _element_parts(p: dict) -> list:
    """The element, its quadrature (where the element takes one), the mesh and the plate's
    Gauss points (where given) of a configuration with an element choice."""
    parts = [f"{p['element']} element"]
    if _given(p.get("integration")):
        parts.append(f"{p['integration']} quadrature")
    parts.append(f"n = {p.get('n_elements')}")
    if _given(p.get("ng")):
        parts.append("{0} x {0} Gauss points".format(p["ng"]))
    return parts


def _given(v) -> bool:
    """A knob value that is set (not None, NaN or the text 'None' of a table cell)."""
    return v is not None and str(v) not in ("None", "nan")


def describe(p: dict, dynamic: bool, quantity: str = "results") -> str:
    """Short text of a model configuration."""
    parts = _element_parts(p) if p.get("element") is not None else _belt_parts(p)
    if quantity == "frequency":
        parts.append("eigen solve about the reference")
    elif dynamic:
        integ = p.get("integrator") or "generalized-alpha"  # a drive file's: its dt
        parts.append(f"{integ}, dt = {p.get('dt'):g}" if integ == "generalized-alpha"
                     else f"{integ}, rtol = {p.get('rtol'):g}")
        if p.get("newton_tol") is not None:
            parts.append(f"Newton tol = {p['newton_tol']:g}")
    elif p.get("rtol") is None:
        parts.append("linear solve")
    elif p.get("load_steps") is None:
        parts.append(f"static Newton, rtol = {p.get('rtol'):g}")
    else:
        parts.append(f"static Newton, rtol = {p.get('rtol'):g}, {p.get('load_steps')} load steps")
    return ", ".join(parts)


def _restrict(grids, fixed_knobs: dict):
    """The grids with every fixed knob set to its value: of the grids that list each fixed
    knob they name with that value among theirs (a fixed element keeps its own family's
    grids, not another family's knobs), or of all when none does."""
    keep = [g for g in grids if all(v in g[k] for k, v in fixed_knobs.items() if k in g)]
    out = []
    for g in keep or grids:
        g = dict(g)
        for k, v in fixed_knobs.items():
            g[k] = [v]
        out.append(g)
    return out


def check_data(data) -> None:
    """``--data`` checked before anything runs: an existing, readable sweep file (one line
    naming the path and what is wrong)."""
    path = Path(data)
    if not path.exists():
        anc = path.parent
        while str(anc) not in ("", ".", "/") and not anc.exists():
            anc = anc.parent
        if anc.exists() and not anc.is_dir():
            raise InputError(f"--data {str(data)!r}: no such file ({str(anc)!r} is a file, "
                             "not a directory)")
        raise InputError(f"--data {str(data)!r}: no such file")
    if path.suffix not in (".parquet", ".csv"):
        raise InputError(f"--data {str(data)!r}: the file name must end in .parquet or .csv "
                         "(a file written by `ancf sweep`)")
    check_table(path, "--data")


def check_reference(scene: str, ref, params: dict) -> None:
    """Before any run: an analytic or published reference must exist for these physical
    parameters (e.g. Bechtel's belt cannot transmit more than its largest torque, published
    values exist for the published problem only); else InputError
    naming why.  Self-references (a much finer model) are not run here: a failure of
    theirs shows in the rows and the message."""
    if ref.kind == "self":
        return
    try:
        ref.values(params)
    except (ReferenceFailed, ValueError) as exc:
        raise InputError(f"reference {ref.name} of scene {scene!r} does not exist for these "
                         f"parameters, so no run can be scored: {exc}") from None


def _missing_reference(df) -> str | None:
    """Why the reference is missing, when converged rows have no error because of it."""
    if not len(df) or "message" not in df:
        return None
    conv = df[df["status"] == "ok"]
    msgs = conv["message"].astype(str)
    miss = msgs[msgs.str.contains("reference unavailable: ", regex=False)]
    if not len(miss):
        return None
    return miss.iloc[0].split("reference unavailable: ", 1)[1]


def recommend(scene: str, tol: float, *, fixed: dict | None = None, reference: str | None = None,
              data=None, workers: int | None = None, scheduler=None, time_limit: float = 300.0,
              progress: bool = True, log=None, quantity: str = "results") -> dict:
    """The cheapest configuration meeting ``tol`` (see the module doc).  ``fixed``:
    parameter overrides (physical parameters define the problem; fixed knobs restrict
    the candidates).  ``quantity = "frequency"``: the error is that of the lowest
    ``count`` bending frequencies (``ancf modes``) against the scene's frequency
    reference (:data:`ancf.study.references.FREQUENCY_SPECS`)."""
    from ancf.scenes import SCENES
    if not isinstance(scene, str) or scene not in SCENES:
        raise InputError(f"scene: unknown name {scene!r}; allowed: {', '.join(SCENES)}")
    number("tol", tol)
    if data is not None and (workers is not None or scheduler is not None):
        raise InputError("--data and --workers / --scheduler: both given; allowed: --data (the "
                         "answer from a sweep file: nothing runs) or --workers / --scheduler")
    s = spec(scene, quantity)
    sc = runner(scene, quantity)
    ref = s.reference(reference)
    fixed = mapping("fixed", fixed)
    base = sc.resolve(fixed)
    physical = s.physical(base)
    fixed_knobs = {k: base[k] for k in fixed if k in s.knobs}
    names = [p.name for p in sc.params]
    check_reference(scene, ref, base)

    if data is not None:
        source = str(data)
        check_data(data)
        df = read_rows(data)
        if len(df) and "reference" in df:
            df = df[df["reference"].astype(str) == ref.name]
        if len(df) and "scene" in df:
            df = df[df["scene"].astype(str) == scene]
        df = rows_for(df, scene, physical) if len(df) else df
        for k, v in fixed_knobs.items():
            df = rows_for(df, scene, {k: v}) if len(df) else df
        if not len(df):
            raise InputError(f"--data {source!r}: no rows of scene {scene!r} with reference "
                             f"{ref.name!r} for these physical parameters")
    else:
        grids = _restrict(s.grids(base), fixed_knobs)
        key = stable_hash({"physical": physical, "reference": ref.name, "grids": grids,
                           **({"quantity": quantity} if quantity != "results" else {})})
        out = cache_root() / "recommend" / f"{scene}-{key}.parquet"
        source = str(out)
        df = run_sweep(scene, grids, out=out, fixed=fixed, reference=ref.name, workers=workers,
                       scheduler=scheduler, time_limit=time_limit, progress=progress, log=log,
                       quantity=quantity)
        df = rows_for(df, scene, physical)

    df = with_work(df)
    needs = s.needs
    df["_provides"] = [model_physics(scene, _params(r, names)) for _, r in df.iterrows()]
    df["_lacks"] = [sorted(needs - p) for p in df["_provides"]]
    ok = df[(df["status"] == "ok") & np.isfinite(df["error"].astype(float))]
    meets = ok[ok["error"] <= tol]
    adequate = meets[[not lacks for lacks in meets["_lacks"]]]
    excluded = meets[[bool(lacks) for lacks in meets["_lacks"]]]

    def entry(row):
        p = _params(row, names)
        return {"model": describe(p, s.dynamic, quantity),
                "params": {k: p[k] for k in s.knobs if k in p},
                "error": float(row["error"]), "cpu_time_s": float(row["cpu_time_s"]),
                "work": float(row["work"])}

    evidence = {"source": source, "reference_doc": ref.doc, "runs": int(len(df)),
                "converged_runs": int(len(ok)), "runs_meeting_tol": int(len(adequate)),
                "needs": sorted(needs)}
    lines = []
    if len(ok):
        best = ok.loc[ok["error"].astype(float).idxmin()]
        evidence["most_accurate"] = entry(best)
    if len(excluded):
        cheap_ex = cheapest_first(excluded).iloc[0]
        evidence["excluded_for_physics"] = {**entry(cheap_ex), "lacks": cheap_ex["_lacks"],
                                            "count": int(len(excluded))}
    result = {"scene": scene, "tol": tol, "reference": ref.name, "found": bool(len(adequate)),
              "quantity": quantity}
    default = _default_model(scene, base, s, ref, df, names, sc)
    evidence["default_model"] = default

    if len(adequate):
        order = cheapest_first(adequate, defaults={k: base[k] for k in s.knobs if k in base})
        row = order.iloc[0]
        params = _params(row, names)
        result.update(params=params, error=float(row["error"]), cpu_time_s=float(row["cpu_time_s"]),
                      work=float(row["work"]))
        evidence["runners_up"] = [entry(r) for _, r in order.iloc[1:4].iterrows()]
        group = adequate["work"][tie_group(adequate["work"])].astype(float)
        evidence["tie_group"] = {"runs": int(len(group)), "least_work": float(group.min()),
                                 "most_work": float(group.max()), "gap": 1.0 + WORK_TIE}
        cheaper = ok[(ok["work"] < row["work"]) & (ok["error"] > tol)]
        if len(cheaper):
            c = cheaper.loc[cheaper["error"].astype(float).idxmin()]
            evidence["best_cheaper_run"] = entry(c)
        provides = sorted(model_physics(scene, params))
        result["model"] = describe(params, s.dynamic, quantity)
        lines.append(f"{scene}: cheapest model with error <= {tol:g} against {ref.name}: "
                     f"{result['model']}; error {result['error']:.3g}, work {result['work']:.3g} "
                     f"units, CPU {result['cpu_time_s']:.3g} s ({len(adequate)} of {len(df)} runs "
                     f"meet the tolerance; ranked by counted work, not by the measured time: the "
                     f"{len(group)} run(s) chained to the least work by gaps below "
                     f"{1 + WORK_TIE:g}x count as equally cheap and the least nominal work, "
                     f"then the smallest model among them is chosen).")
        lines.append(f"Physics needed: {', '.join(sorted(needs)) or 'none declared'}; the model "
                     f"provides {', '.join(provides)}.")
        if len(excluded):
            e = evidence["excluded_for_physics"]
            lines.append(f"{e['count']} run(s) meeting the tolerance were excluded for lacking "
                         f"{', '.join(e['lacks'])}; the cheapest: {e['model']} "
                         f"(error {e['error']:.3g}, {e['cpu_time_s']:.3g} s).")
        if "best_cheaper_run" in evidence:
            c = evidence["best_cheaper_run"]
            lines.append(f"Nothing cheaper meets it: the most accurate cheaper run ({c['model']}) "
                         f"has error {c['error']:.3g} at {c['work']:.3g} work units.")
        if default and default.get("error") is not None:
            dm, de, dc = default["model"], default["error"], default["cpu_time_s"]
            if de <= tol:
                ratio = default["work"] / result["work"]
                lighter = params.get("n_elements", 0) < default["params"].get("n_elements", 0)
                lines.append(f"The scene's default model ({dm}) also meets it (error {de:.3g}, "
                             f"{dc:.3g} s); " + ("a lighter model suffices: " if lighter else "")
                             + f"the recommendation takes {ratio:.2g}x less work.")
            else:
                lines.append(f"The scene's default model ({dm}) does not meet it: error {de:.3g} "
                             f"at {dc:.3g} s.")
        code = 0
    else:
        result.update(params=None, error=None, cpu_time_s=None, work=None)
        if "most_accurate" in evidence:
            b = evidence["most_accurate"]
            result.update(error=b["error"], cpu_time_s=b["cpu_time_s"], work=b["work"])
            lines.append(f"{scene}: tolerance {tol:g} not reached against {ref.name} by any of "
                         f"{len(df)} runs; the most accurate: {b['model']} with error "
                         f"{b['error']:.3g} at {b['cpu_time_s']:.3g} s.")
        elif (why := _missing_reference(df)) is not None:
            n_conv = int((df["status"] == "ok").sum())
            lines.append(f"{scene}: no error could be computed: the reference {ref.name} is "
                         f"missing for these parameters ({why}); {n_conv} of {len(df)} runs "
                         "converged.")
            evidence["reference_missing"] = why
        else:
            lines.append(f"{scene}: no converged run among {len(df)}.")
        if ref.kind != "self":
            others = [n for n, r in s.references.items() if r.kind == "self"]
            if others:
                lines.append(f"Against an {ref.kind} reference the error may have a floor that is "
                             f"not discretisation (see the reference: {ref.doc}); "
                             f"`--reference {others[0]}` measures the discretisation error.")
        code = 3
    cal = calibrate(df[df["status"] == "ok"])
    evidence["cost_model"] = {"ranked_by": "work (ancf.study.cost: counted work, fixed weights)",
                              "ties": "runs chained to the least work by gaps below "
                                      f"{1 + WORK_TIE:g}x, ordered by nominal work, model size, "
                                      "error, defaults (ancf.study.selection)",
                              "calibration": cal.as_dict() if cal else None}
    if scene == "belt-drive":  # a steady question has a route without a march
        from ancf.scenes.belt_steady import steady_route
        evidence["steady_route"] = route = steady_route(base)
        if route["applies"]:
            lines.append(f"The steady state itself: `{route['command']}` ({route['why']}).")
    result["message"] = " ".join(x for x in lines if x)
    result["evidence"] = evidence
    result["exit_code"] = code
    return result


def _default_model(scene, base, s, ref, df, names, sc) -> dict:
    """Error, CPU time and work of the scene's default knobs at these physical parameters
    (from the data when present, else run once here); ``sc``: the scene the sweep runs."""
    p = sc.resolve(s.physical(base))
    rows = rows_for(df, scene, {k: p[k] for k in names if k in df}) if len(df) else df
    out = {"model": describe(p, s.dynamic, s.quantity),
           "params": {k: p[k] for k in s.knobs if k in p}}
    if len(rows):
        r = rows.iloc[0]
        ok = r["status"] == "ok" and math.isfinite(float(r["error"]))
        out.update(error=float(r["error"]) if ok else None, cpu_time_s=float(r["cpu_time_s"]),
                   work=float(r["work"]), status=str(r["status"]))
        return out
    res, _ = sc.execute(p)
    err = None
    if res["converged"]:
        try:
            err = float(ref.error(res["results"], ref.values(p), p))
        except Exception:  # noqa: BLE001 - evidence only
            err = None
    out.update(error=err, cpu_time_s=float(res["cpu_time_s"]),
               work=work(counts(p, res["results"])), status="ok" if res["converged"] else "not-converged")
    return out


def command_sets(scene: str, params: dict) -> dict:
    """The ``--set`` values a command line needs to run ``params``: the model knobs, and
    every other parameter only where it differs from the default the scene derives from the
    rest (so a default such as F = -5e8 h^3 = -500000.0000000001 N is not printed back as
    a number, and the run uses the very same value)."""
    from ancf.scenes import SCENES
    sc, knobs = SCENES[scene], spec(scene).knobs
    given = {k: v for k, v in params.items() if v is not None}
    out = {}
    for k, v in given.items():
        rest = {j: w for j, w in given.items() if j != k}
        if k in knobs or sc.resolve(rest).get(k) != v:
            out[k] = v
    return out


def public(result: dict) -> dict:
    """The JSON printed by ``ancf recommend --json``."""
    keys = ("scene", "tol", "params", "error", "reference", "cpu_time_s", "found", "model",
            "message", "evidence", "work", "quantity")
    return {k: _clean(result.get(k)) for k in keys}


def _clean(v):
    if isinstance(v, dict):
        return {k: _clean(x) for k, x in v.items()}
    if isinstance(v, (list, tuple)):
        return [_clean(x) for x in v]
    v = _py(v)
    if isinstance(v, float) and not math.isfinite(v):
        return None
    return v


def as_frame(result: dict) -> pd.DataFrame:
    return pd.DataFrame([result])
