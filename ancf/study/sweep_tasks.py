"""The tasks of a sweep (:mod:`ancf.study.sweep`) and one run of a task: the grid parsed
and expanded to every combination, each resolved, keyed and given its reference values;
:func:`run_case` runs one in a worker process and turns its outcome into a row (the
columns :mod:`ancf.study.sweep` describes), never raising.
"""
from __future__ import annotations

import itertools
import json
import math
import time
import traceback
from pathlib import Path

import numpy as np

from ancf.common.params import InputError
from ancf.scenes.store import keep
from ancf.study.references import ReferenceFailed, runner, spec, stable_hash


def parse_grid(scene: str, items, quantity: str = "results") -> dict:
    """``["n_elements=2,4,8", "integration=thesis;normal=2x2,shear=1x1"]`` -> {name: [values]}.
    Values are separated by ',' (or by ';' when a value itself holds commas) and parsed
    by the scene's parameter (bad values raise InputError naming the field)."""
    sc = runner(scene, quantity)
    params = {p.name: p for p in sc.params}
    grid = {}
    for item in items or []:
        if "=" not in item:
            raise InputError(f"--grid {item!r}: expected key=v1,v2,...")
        k, v = item.split("=", 1)
        k = k.strip()
        if k not in params:
            raise InputError(f"{k}: unknown parameter of scene {scene!r}; allowed: "
                             f"{', '.join(params)}")
        if k in grid:
            raise InputError(f"--grid {k}: given twice; allowed: one --grid per parameter "
                             f"(list every value in it: {k}=v1,v2,...)")
        vals = [s.strip() for s in (v.split(";") if ";" in v else v.split(",")) if s.strip()]
        if not vals:
            raise InputError(f"--grid {item!r}: no values")
        grid[k] = list(dict.fromkeys(params[k].parse(s) for s in vals))
    return grid


def expand(grids, fixed: dict | None = None) -> list[dict]:
    """Union of the cartesian products of ``grids`` (a dict or a list of dicts), each
    combination merged over ``fixed``; deterministic order, duplicates removed."""
    if isinstance(grids, dict):
        grids = [grids]
    out, seen = [], set()
    for g in grids:
        keys = list(g)
        for combo in itertools.product(*(g[k] for k in keys)):
            ov = dict(fixed or {})
            ov.update(zip(keys, combo))
            h = json.dumps(ov, sort_keys=True, default=str)
            if h not in seen:
                seen.add(h)
                out.append(ov)
    return out


def run_key(scene: str, params: dict, quantity: str = "results") -> str:
    if quantity != "results":  # the scene's own runs keep their keys
        return stable_hash({"scene": scene, "params": params, "quantity": quantity})
    return stable_hash({"scene": scene, "params": params})


def make_tasks(scene: str, overrides: list[dict], reference: str | None = None,
               quantity: str = "results") -> list[dict]:
    """Resolve every combination, key it, and attach the reference values (computed
    once per distinct physical problem, in this process)."""
    sc = runner(scene, quantity)
    s = spec(scene, quantity)
    ref = s.reference(reference)
    refs: dict = {}
    tasks = []
    for i, ov in enumerate(overrides):
        t = {"index": i, "scene": scene, "reference": ref.name, "ref_values": None,
             "ref_error": None, "quantity": quantity}
        try:
            params = sc.resolve(ov)
        except InputError as exc:
            t.update(params=None, overrides={k: _jsonable(v) for k, v in ov.items()},
                     invalid=str(exc), key=stable_hash({"scene": scene, "overrides": ov}))
            tasks.append(t)
            continue
        t.update(params={k: _jsonable(v) for k, v in params.items()},
                 key=run_key(scene, params, quantity), paths=_absolute(params))
        pk = stable_hash(s.physical(params))
        if pk not in refs:
            try:
                refs[pk] = (ref.values(params), None)
            except (ReferenceFailed, ValueError) as exc:
                refs[pk] = (None, str(exc))
        t["ref_values"], t["ref_error"] = refs[pk]
        tasks.append(t)
    return tasks


#: parameters that name a file: a task carries them as absolute paths too (``paths``), so
#: that a worker started in another folder (a Dask worker) reads the file the driver read
PATH_PARAMS = ("file",)


def _absolute(params: dict) -> dict:
    """The file parameters of ``params`` as absolute paths (from this process's folder)."""
    return {k: str(Path(params[k]).absolute()) for k in PATH_PARAMS
            if isinstance(params.get(k), str) and params[k]}


def _jsonable(v):
    if isinstance(v, np.generic):
        return v.item()
    return v


# ---------------------------------------------------------------------------------------
# one run (in a worker process)
# ---------------------------------------------------------------------------------------

def _base_row(task: dict) -> dict:
    row = {"key": task["key"], "scene": task["scene"]}
    if task.get("quantity", "results") != "results":
        row["quantity"] = task["quantity"]
    row.update(task.get("params") or task.get("overrides") or {})
    row.update(status=None, converged=False, message="", error=float("nan"),
               reference=task["reference"], cpu_time_s=float("nan"),
               compile_cpu_s=float("nan"), wall_time_s=float("nan"), steps=None, iterations=None)
    return row


def failure_row(task: dict, status: str, message: str, wall: float = float("nan")) -> dict:
    row = _base_row(task)
    row.update(status=status, message=message, wall_time_s=wall)
    return row


def run_case(task: dict) -> dict:
    """Run one task; never raises (failures become rows)."""
    quantity = task.get("quantity", "results")
    if task.get("invalid"):
        return failure_row(task, "invalid", f"invalid input: {task['invalid']}", 0.0)
    row = _base_row(task)
    t0 = time.perf_counter()
    try:
        with np.errstate(all="ignore"):
            out, _ = runner(task["scene"], quantity).execute({**task["params"],
                                                               **task.get("paths", {})})
    except InputError as exc:
        return failure_row(task, "invalid", f"invalid input: {exc}", time.perf_counter() - t0)
    except Exception as exc:  # noqa: BLE001 - a failing run is data, not a crash
        tb = traceback.extract_tb(exc.__traceback__)
        where = f" at {Path(tb[-1].filename).name}:{tb[-1].lineno}" if tb else ""
        return failure_row(task, "failed", f"{type(exc).__name__}: {exc}{where}",
                           time.perf_counter() - t0)
    wall = time.perf_counter() - t0
    if quantity == "results":  # the run store holds scene runs, keyed by their parameters
        keep(task["scene"], task["params"], out)
    res = out["results"] or {}
    row.update(converged=bool(out["converged"]), message=out["message"],
               cpu_time_s=float(out["cpu_time_s"]),
               compile_cpu_s=float(out.get("compile_cpu_s", float("nan"))), wall_time_s=wall)
    row["steps"] = res.get("steps", res.get("load_steps_taken"))
    row["iterations"] = res.get("newton_iterations")
    for k, v in res.items():
        if isinstance(v, (list, tuple)):
            if v and isinstance(v[-1], (int, float)) and not isinstance(v[-1], bool):
                row[f"res_{k}_final"] = float(v[-1])
        elif v is None or isinstance(v, (bool, int, float, str)):
            row[f"res_{k}"] = v
    if not out["converged"]:
        row["status"] = "not-converged"
        return row
    bad = [k for k, v in res.items() if isinstance(v, float) and not math.isfinite(v)]
    if bad:
        row.update(status="failed", converged=False,
                   message=f"non-finite result ({', '.join(bad)}) reported as converged")
        return row
    row["status"] = "ok"
    if task.get("ref_values") is not None:
        try:
            ref = spec(task["scene"], quantity).reference(task["reference"])
            err = float(ref.error(res, task["ref_values"], out["params"]))
        except Exception as exc:  # noqa: BLE001
            err, row["message"] = float("nan"), f"{out['message']}; error not computed: {exc}"
        if not math.isfinite(err):
            row.update(status="failed", message=f"{out['message']}; error against "
                       f"{task['reference']} is not finite")
        row["error"] = err
    else:
        row["message"] = f"{out['message']}; reference unavailable: {task.get('ref_error')}"
    return row

