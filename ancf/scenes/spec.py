"""What a scene is measured against: the classes its ``study`` declaration returns.

A scene's ``study()`` (:class:`~ancf.scenes.base.Scene`) returns a :class:`SceneSpec`:

* ``knobs``: the parameters that choose the *model* (element, quadrature, mesh,
  integrator, tolerances). Every other parameter defines the physical problem; a
  reference depends only on those.
* ``needs``: the physics the scene needs (:data:`PHYSICS`); a configuration provides
  some (``ancf.study.references.model_physics``), and ``ancf recommend`` never proposes
  one that lacks any.
* ``references``: named :class:`Reference` objects, analytic or a converged
  self-reference (:func:`self_reference`: a much finer model, computed once and cached on
  disk under ``reports/.cache/references/`` with the parameters that produced it), each
  with its error definition; ``default_reference`` is the one sweeps use unless told
  otherwise.
* ``report_grids`` / ``recommend_grids``: the model grids of the speed-accuracy report
  and of ``ancf recommend`` (lists of sub-grids whose union is swept, so that only valid
  element/quadrature pairs are combined).

The study layer (:mod:`ancf.study.references`) collects them from the scenes.
"""
from __future__ import annotations

import hashlib
import json
import os
import time
from dataclasses import dataclass, field
from pathlib import Path
from typing import Callable

import numpy as np

from ancf.common.paths import REPORTS
from ancf.elements.catalogue import ELEMENTS
from ancf.elements.registry import PHYSICS
from ancf.scenes.base import ReferenceFailed

__all__ = ["DYNAMIC_KNOBS", "FREQUENCY_ERROR", "PHYSICS", "REFERENCE_VERSION", "STATIC_KNOBS",
           "STATIC_RTOL", "Reference", "ReferenceFailed", "SceneSpec", "analytic_values",
           "bending_frequencies", "cache_root", "computed_self_reference", "element_grids",
           "frequency_error", "knob_text", "relative", "self_reference", "stable_hash"]

#: Physics a scene may need / a model may provide.


#: Bump when a change of the code would change a cached self-reference.
REFERENCE_VERSION = 1

STATIC_KNOBS = ("element", "integration", "n_elements", "load_steps", "rtol", "max_iterations",
                "stability_check")

DYNAMIC_KNOBS = ("element", "integration", "n_elements", "integrator", "rtol", "atol", "dt",
                 "rho_inf", "constraints", "baumgarte", "max_steps")
#: the Newton tolerances of the static beams' grids
STATIC_RTOL = {"rtol": [1e-4, 1e-8]}


def cache_root() -> Path:
    """``$ANCF_CACHE`` or ``reports/.cache`` (gitignored)."""
    env = os.environ.get("ANCF_CACHE")
    return Path(env) if env else REPORTS / ".cache"


def stable_hash(obj, n: int = 16) -> str:
    """Deterministic short hash of a JSON-serialisable object (float repr, sorted keys)."""
    return hashlib.sha1(json.dumps(obj, sort_keys=True, default=str).encode()).hexdigest()[:n]


@dataclass(frozen=True)
class Reference:
    """A reference solution of a scene and the error of a run against it.

    ``values(params) -> dict`` (JSON-serialisable; raises :class:`ReferenceFailed`);
    ``error(results, values, params) -> float`` (dimensionless); ``kind`` is
    ``analytic``, ``published`` (transcribed values of another code, for the published
    problem only) or ``self``; ``doc`` names the reference and defines the error.
    ``fine`` (self-references): the knob values of the much finer model.  ``measure``:
    a short name of the error (the y-axis label of the Pareto plots).
    """

    name: str
    kind: str
    doc: str
    values: Callable[[dict], dict]
    error: Callable[[dict, dict, dict], float]
    fine: dict = field(default_factory=dict)
    measure: str = "relative error"


def relative(key, refkey=None):
    """The error |results[key] - ref[refkey]| / |ref[refkey]| (refkey defaults to key)."""
    refkey = refkey or key

    def err(res, ref, p):
        return abs(res[key] - ref[refkey]) / abs(ref[refkey])
    err.__doc__ = f"|{key} - ref| / |ref|"
    return err


def self_reference(scene: str, fine: dict, quantities: tuple, error, doc: str,
                   check: dict | None = None, knobs: tuple = STATIC_KNOBS,
                   measure: str = "relative error") -> Reference:
    """A converged self-reference: the scene run with the ``fine`` knobs (and the run's
    physical parameters), cached on disk.  ``check``: knobs of a coarser run whose
    difference to the fine one is stored as ``self_check`` (an estimate of the
    reference's own error, same error definition)."""

    def values(p):
        physical = {k: v for k, v in p.items() if k not in knobs}
        return computed_self_reference(scene, physical, fine, quantities, error, check)
    return Reference("self", "self", doc, values, error, dict(fine), measure)


def computed_self_reference(scene, p, fine, quantities, error, check=None) -> dict:
    from ancf.scenes import scene as named
    sc = named(scene)
    params = dict(p)
    params.update(fine)
    params = sc.resolve(params)
    key = stable_hash({"v": REFERENCE_VERSION, "scene": scene, "params": params,
                       "check": check})
    path = cache_root() / "references" / f"{scene}-{key}.json"
    if path.exists():
        try:
            data = json.loads(path.read_text())
            if all(q in data["values"] for q in quantities):
                return data["values"]
        except (OSError, ValueError, KeyError):
            pass
    out, _ = sc.execute(params)
    if not out["converged"]:
        raise ReferenceFailed(f"self-reference ({knob_text(fine)}) did not converge: "
                              f"{out['message']}")
    vals = {q: out["results"][q] for q in quantities}
    meta = {}
    if check:
        cp = dict(params)
        cp.update(check)
        cout, _ = sc.execute(cp)
        if cout["converged"]:
            meta["self_check"] = {"knobs": check, "error_vs_fine": float(
                error({q: cout["results"][q] for q in quantities}, vals, params))}
    data = {"scene": scene, "params": params, "values": vals, "cpu_time_s": out["cpu_time_s"],
            "created": time.strftime("%Y-%m-%dT%H:%M:%S"), "reference_version": REFERENCE_VERSION,
            **meta}
    vals = dict(vals)
    if "self_check" in meta:
        vals["self_check_error"] = meta["self_check"]["error_vs_fine"]
    data["values"] = vals
    path.parent.mkdir(parents=True, exist_ok=True)
    tmp = path.with_suffix(f".tmp{os.getpid()}")
    tmp.write_text(json.dumps(data, indent=1))
    os.replace(tmp, path)
    return vals


def knob_text(knobs: dict) -> str:
    return ", ".join(f"{k}={v}" for k, v in knobs.items())


@dataclass(frozen=True)
class SceneSpec:
    scene: str
    knobs: tuple
    needs: frozenset
    references: dict
    default_reference: str
    report_grids: tuple = ()
    recommend_grids: tuple = ()
    dynamic: bool = False
    notes: str = ""
    provides: frozenset | None = None  # physics of a scene without an element choice
    quantity: str = "results"  # what the runs compute: the scene's results or frequencies
    grids_for: object = None  # resolved params -> model grids, where they depend on the problem

    def grids(self, params: dict | None, which: str = "recommend") -> tuple:
        """The model grids of ``recommend`` or the ``report``, for the problem of the
        resolved ``params`` where the scene's grids depend on it (a drive file's element)."""
        if self.grids_for is not None and params is not None:
            return self.grids_for(params)
        return self.recommend_grids if which == "recommend" else self.report_grids

    def reference(self, name: str | None = None) -> Reference:
        name = name or self.default_reference
        if name not in self.references:
            from ancf.common.params import InputError
            raise InputError(f"reference: {name!r} is not a reference of scene {self.scene!r}; "
                             f"allowed: {', '.join(self.references)}")
        return self.references[name]

    def physical(self, params: dict) -> dict:
        """The parameters that define the problem (all but the model knobs)."""
        return {k: v for k, v in params.items() if k not in self.knobs}


def element_grids(ns, **extra) -> tuple:
    """Every catalogue element with every scheme it accepts, times ``ns`` and ``extra``."""
    return tuple({"element": [name], "integration": list(cls.schemes), "n_elements": list(ns), **extra}
                 for name, cls in ELEMENTS.items())


def analytic_values(name: str, p: dict, keys: tuple) -> dict:
    """The results ``keys`` of the analytic reference ``name`` (``ancf analytic NAME``) run
    with the parameters of ``p`` it declares; ReferenceFailed when it does not converge."""
    from ancf.scenes.analytic import REFERENCES
    ref = REFERENCES[name]
    names = {q.name for q in ref.params}
    out, _ = ref.execute({k: v for k, v in p.items() if k in names})
    if not out["converged"]:
        raise ReferenceFailed(f"{name} reference: {out['message']}")
    return {k: out["results"][k] for k in keys}


def bending_frequencies(res: dict, count: int) -> np.ndarray:
    """The lowest ``count`` bending frequencies (Hz) of ``ancf modes`` results: the modes
    with more than half their sampled motion across the first axis (beams: off the
    centreline; the plate, its in-plane coordinates fixed: every mode).  ValueError when
    fewer were computed."""
    f = [x for x, s in zip(res["frequencies_hz"] or [], res["mode_direction_shares"] or [])
         if 1.0 - s[0] > 0.5][:count]
    if len(f) < count:
        raise ValueError(f"{len(f)} bending mode(s) among the lowest {len(res['frequencies_hz'] or [])}"
                         f", {count} compared: the mesh is too coarse")
    return np.array(f)


def frequency_error(res, ref, p):
    """max over the first K modes of |f_k / f_ref,k - 1|."""
    f = bending_frequencies(res, int(p["count"]))
    return float(np.max(np.abs(f / np.asarray(ref["frequencies_hz"]) - 1.0)))


#: the frequency references' error, as their docs state it
FREQUENCY_ERROR = ("error = max over the lowest K = count bending modes of |f_k / f_ref,k − 1| "
                    "(`ancf modes` about the reference, consistent mass)")
