"""What each scene is measured against: its reference, its error, its knobs, its physics.

Every scene of :data:`ancf.scenes.SCENES` gets a :class:`SceneSpec`:

* ``knobs``: the parameters that choose the *model* (element, quadrature, mesh,
  integrator, tolerances). Every other parameter defines the physical problem; a
  reference depends only on those.
* ``needs``: the physics the scene needs (``PHYSICS``); :func:`model_physics` says what a
  configuration provides, and ``ancf recommend`` never proposes one that lacks any.
* ``references``: named :class:`Reference` objects, analytic or a converged
  self-reference (a much finer model, computed once and cached on disk under
  ``reports/.cache/references/`` with the parameters that produced it), each with its
  error definition; ``default_reference`` is the one sweeps use unless told otherwise.
* ``report_grids`` / ``recommend_grids``: the model grids of the speed-accuracy report
  and of ``ancf recommend`` (lists of sub-grids whose union is swept, so that only valid
  element/quadrature pairs are combined).

A new scene plugs in with one entry in :data:`SPECS` (or by setting the optional
``knobs`` / ``needs`` / ``reference`` fields of its :class:`~ancf.scenes.base.Scene`,
which :func:`spec` turns into a spec with a self-reference).  The dynamic scenes
(``pendulum``, ``spinning-beam``) are declared below and become active when they
appear in ``SCENES``.
"""
from __future__ import annotations

import hashlib
import json
import math
import os
import time
from dataclasses import dataclass, field
from functools import lru_cache
from pathlib import Path
from typing import Callable

import numpy as np

from ancf.elements.catalogue import ELEMENTS
from ancf.common.paths import REPORTS

#: Physics a scene may need / a model may provide.
PHYSICS = ("axial", "bending", "shear", "large-rotation", "inertia", "contact", "3D")

#: What each element family provides.  Both planar elements carry extension, bending
#: and shear (Omar-Shabana: also the transverse stretch), in 2D, with large rotations.
ELEMENT_PHYSICS = {
    "linear": frozenset({"axial", "bending", "shear", "large-rotation", "inertia"}),
    "omar-shabana": frozenset({"axial", "bending", "shear", "large-rotation", "inertia"}),
    "linear3d": frozenset({"axial", "bending", "shear", "large-rotation", "inertia", "3D"}),
    "belt3d": frozenset({"axial", "bending", "shear", "large-rotation", "inertia", "3D"}),
}

#: Bump when a change of the code would change a cached self-reference.
REFERENCE_VERSION = 1

STATIC_KNOBS = ("element", "integration", "n_elements", "load_steps", "rtol", "max_iterations",
                "stability_check")
DYNAMIC_KNOBS = ("element", "integration", "n_elements", "integrator", "rtol", "atol", "dt",
                 "rho_inf", "constraints", "baumgarte", "max_steps")


class ReferenceFailed(RuntimeError):
    """The reference could not be computed (message says why)."""


def cache_root() -> Path:
    """``$ANCF_CACHE`` or ``reports/.cache`` (gitignored)."""
    env = os.environ.get("ANCF_CACHE")
    return Path(env) if env else REPORTS / ".cache"


def stable_hash(obj, n: int = 16) -> str:
    """Deterministic short hash of a JSON-serialisable object (float repr, sorted keys)."""
    return hashlib.sha1(json.dumps(obj, sort_keys=True, default=str).encode()).hexdigest()[:n]


# ---------------------------------------------------------------------------------------
# references
# ---------------------------------------------------------------------------------------

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


def _tip_error(res, ref, p):
    """|tip - tip_ref| / |tip_ref - (L, 0)|: tip-position error over the reference deflection."""
    d = math.hypot(ref["tip_x"] - p["L"], ref["tip_y"])
    return math.hypot(res["tip_x"] - ref["tip_x"], res["tip_y"] - ref["tip_y"]) / d


def _rel(key, refkey=None):
    refkey = refkey or key

    def err(res, ref, p):
        return abs(res[key] - ref[refkey]) / abs(ref[refkey])
    err.__doc__ = f"|{key} - ref| / |ref|"
    return err


def _reissner(p):
    from analytic import reissner
    r = reissner.tip_position(p["E"], p["nu"], p["L"], p["h"], p["b"], p["F"], ks=p["ks"])
    if not r.converged:
        raise ReferenceFailed(f"Reissner reference: {r.message}")
    return {"tip_x": r.tip_x, "tip_y": r.tip_y}


def _timoshenko_cantilever(p):
    from analytic import timoshenko
    return {"tip_deflection_m": timoshenko.cantilever_tip_deflection(
        p["E"], p["nu"], p["L"], p["h"], p["b"], p["F"], ks=p["ks"])}


def _timoshenko_cantilever_error(res, ref, p):
    return abs((res["tip_y"]) - ref["tip_deflection_m"]) / abs(ref["tip_deflection_m"])


def _timoshenko_ss(p):
    from analytic import timoshenko
    return {"mid_deflection_m": timoshenko.mid_deflection(p["E"], p["nu"], p["L"], p["h"],
                                                          p["b"], p["F"], ks=p["ks"])}


def _bar_linear(p):
    return {"elongation_m": p["F"] * p["L"] / (p["E"] * p["b"] * p["h"])}


def _bar_svk(p):
    """Uniaxial St-Venant-Kirchhoff bar (Green strain, free lateral contraction):
    nominal stress F/A = E lam (lam^2 - 1)/2, elongation (lam - 1) L."""
    s = p["F"] / (p["E"] * p["b"] * p["h"])
    # lam (lam^2 - 1) / 2 = s, solved for e = lam - 1 by Newton from the linear guess
    e = s
    for _ in range(50):
        f = (1 + e) * ((1 + e) ** 2 - 1) / 2 - s
        df = (3 * (1 + e) ** 2 - 1) / 2
        de = f / df
        e -= de
        if abs(de) <= 1e-16 * max(abs(e), 1e-300):
            break
    return {"elongation_m": e * p["L"]}


def _traj_error(res, ref, p):
    """max over samples of |tip(t) - tip_ref(t)| / L (trajectory error)."""
    t = np.asarray(res["times"], float)
    tr = np.asarray(ref["times"], float)
    if t.size == 0 or t[-1] < tr[-1] - 1e-9:
        return float("nan")
    rx = np.interp(t, tr, np.asarray(ref["tip_x"], float))
    ry = np.interp(t, tr, np.asarray(ref["tip_y"], float))
    d = np.hypot(np.asarray(res["tip_x"], float) - rx, np.asarray(res["tip_y"], float) - ry)
    return float(np.max(d) / p["L"])


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
    from ancf.scenes import SCENES
    sc = SCENES[scene]
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
        raise ReferenceFailed(f"self-reference ({_knob_text(fine)}) did not converge: "
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


def _knob_text(knobs: dict) -> str:
    return ", ".join(f"{k}={v}" for k, v in knobs.items())


# ---------------------------------------------------------------------------------------
# scene specs
# ---------------------------------------------------------------------------------------

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


def _element_grids(ns, **extra) -> tuple:
    """Every catalogue element with every scheme it accepts, times ``ns`` and ``extra``."""
    return tuple({"element": [name], "integration": list(cls.schemes), "n_elements": list(ns), **extra}
                 for name, cls in ELEMENTS.items())


_STATIC_RTOL = {"rtol": [1e-4, 1e-8]}


def _cantilever_spec() -> SceneSpec:
    refs = {
        "reissner": Reference(
            "reissner", "analytic",
            "geometrically exact Reissner rod (`ancf analytic reissner`); error = |tip − tip_ref| / "
            "|tip_ref − (L, 0)|. At large strain it includes the constitutive gap between the ANCF "
            "St-Venant–Kirchhoff continuum and the Reissner rod (5e-4 in Model 1, 1.5e-2 in "
            "Model 2; see static_beams.md)", _reissner, _tip_error, measure="relative tip-position error"),
        "self": self_reference(
            "cantilever", {"element": "linear", "integration": "thesis", "n_elements": 1024,
                           "rtol": 1e-9, "load_steps": 10, "max_iterations": 25},
            ("tip_x", "tip_y"), _tip_error,
            "converged self-reference: linear element, thesis scheme, 1024 elements, Newton rtol "
            "1e-9 (cached); error = |tip − tip_ref| / |tip_ref − (L, 0)|; measures the "
            "discretisation error of the ANCF continuum only",
            check={"n_elements": 512}, measure="relative tip-position error"),
        "timoshenko": Reference(
            "timoshenko", "analytic",
            "linear Timoshenko cantilever F L³/(3EI) + F L/(k_s G A) (SymPy-derived); error = "
            "|tip_y − w| / |w|; valid for small deflections only", _timoshenko_cantilever,
            _timoshenko_cantilever_error, measure="relative tip-deflection error"),
    }
    return SceneSpec(
        "cantilever", STATIC_KNOBS, frozenset({"axial", "bending", "shear", "large-rotation"}),
        refs, "reissner",
        report_grids=_element_grids((1, 2, 4, 8, 16, 32, 64, 128, 256), **_STATIC_RTOL),
        recommend_grids=_element_grids((1, 2, 4, 8, 16, 32, 64, 128), **_STATIC_RTOL),
        notes="Model 1 (defaults h = 0.1 m, ν = 0.3, F = −5e5 N) against the Reissner rod.")


def _simply_supported_spec() -> SceneSpec:
    refs = {
        "timoshenko": Reference(
            "timoshenko", "analytic",
            "Timoshenko beam, midspan load (`ancf analytic timoshenko`, SymPy-derived); error = "
            "|w − w_ref| / |w_ref|", _timoshenko_ss, _rel("mid_deflection_m"),
            measure="relative midspan-deflection error"),
        "self": self_reference(
            "simply-supported", {"element": "linear", "integration": "thesis", "n_elements": 1024,
                                 "rtol": 1e-8},
            ("mid_deflection_m",), _rel("mid_deflection_m"),
            "converged self-reference: linear element, thesis scheme, 1024 elements (cached); "
            "error = |w − w_ref| / |w_ref|", check={"n_elements": 512},
            measure="relative midspan-deflection error"),
    }
    ns = (2, 4, 8, 16, 32, 64, 128, 256)
    return SceneSpec(
        "simply-supported", STATIC_KNOBS, frozenset({"bending", "shear"}), refs, "timoshenko",
        report_grids=_element_grids(ns, **_STATIC_RTOL),
        recommend_grids=_element_grids(ns[:-1], **_STATIC_RTOL),
        notes="Defaults (ν = 0, F = −1000 N) against the Timoshenko beam.")


def _axial_bar_spec() -> SceneSpec:
    refs = {
        "bar": Reference(
            "bar", "analytic",
            "uniaxial St-Venant–Kirchhoff bar (Green strain, the ANCF material law): "
            "F/A = E λ(λ² − 1)/2, elongation (λ − 1) L; error = |u − u_ref| / |u_ref|",
            _bar_svk, _rel("elongation_m"), measure="relative elongation error"),
        "linear-bar": Reference(
            "linear-bar", "analytic",
            "linear bar F L/(E A); error = |u − u_ref| / |u_ref| (differs from the "
            "St-Venant–Kirchhoff bar by 1.5 × strain, 3.6e-5 at the default load)",
            _bar_linear, _rel("elongation_m"), measure="relative elongation error"),
    }
    return SceneSpec(
        "axial-bar", STATIC_KNOBS, frozenset({"axial"}), refs, "bar",
        report_grids=_element_grids((1, 2, 4, 8, 16, 32), **_STATIC_RTOL),
        recommend_grids=_element_grids((1, 2, 4, 8, 16), **_STATIC_RTOL),
        notes="Defaults (F = 5e4 N) against the St-Venant–Kirchhoff bar.")


def _dynamic_grids(ns):
    """Both elements x time integrators x tolerances / step sizes for the dynamic scenes."""
    grids = []
    for element in ("linear", "omar-shabana"):
        grids += [{"element": [element], "integration": ["thesis"], "n_elements": list(ns),
                   "integrator": ["generalized-alpha"], "dt": [1e-2, 3e-3, 1e-3]},
                  {"element": [element], "integration": ["thesis"], "n_elements": list(ns),
                   "integrator": ["rk45", "dop853", "radau", "bdf"], "rtol": [1e-4, 1e-6]}]
    return tuple(grids)


def _dynamic_ref(scene: str, name: str):
    """An analytic trajectory from ``analytic.dynamics_refs.DYNAMIC_REFERENCES`` (as a
    Scene run with the physical parameters it declares)."""

    def values(p):
        from ancf.scenes.analytic import DYNAMIC_REFERENCES
        ref = DYNAMIC_REFERENCES[name]
        names = {q.name for q in ref.params}
        out, _ = ref.execute({k: v for k, v in p.items() if k in names})
        if not out["converged"]:
            raise ReferenceFailed(f"{name} reference: {out['message']}")
        r = out["results"]
        return {"times": r["times"], "tip_x": r["tip_x"], "tip_y": r["tip_y"]}
    return values


def _pendulum_spec() -> SceneSpec:
    # The rigid pendulum is 12 % of L away from this soft (E = 2.07e7 Pa) pendulum, so a
    # 1e-2 question needs a self-reference.  32 elements: 8 -> 16 elements still moves the
    # tip by 1e-2 L, 16 -> 32 by about 1e-3 L (generalized-alpha, dt = 1e-3 s).
    fine = {"element": "linear", "integration": "thesis", "n_elements": 32,
            "integrator": "generalized-alpha", "dt": 1e-3}
    refs = {
        "self": self_reference(
            "pendulum", fine, ("times", "tip_x", "tip_y"), _traj_error,
            "converged self-reference: 32 linear elements, generalized-α, dt = 1e-3 s (computed "
            "once, about a minute, then cached); error = max_t |tip(t) − tip_ref(t)| / L",
            check={"n_elements": 16}, knobs=DYNAMIC_KNOBS, measure="tip-trajectory error max|Δtip| / L"),
        "rigid-pendulum": Reference(
            "rigid-pendulum", "analytic",
            "rigid pendulum (analytic.dynamics_refs); error = max_t |tip(t) − tip_ref(t)| / L; "
            "includes the flexibility of the beam (E = 2.07e7 Pa), so it is a floor, not a "
            "discretisation error", _dynamic_ref("pendulum", "rigid-pendulum"), _traj_error,
            measure="tip-trajectory error max|Δtip| / L"),
    }
    return SceneSpec("pendulum", DYNAMIC_KNOBS,
                     frozenset({"axial", "bending", "large-rotation", "inertia"}), refs, "self",
                     report_grids=_dynamic_grids((2, 4, 8, 16)),
                     recommend_grids=_dynamic_grids((2, 4, 8, 16)), dynamic=True,
                     notes="Flexible pendulum against a converged self-reference.")


def _spinning_ref(p):
    from ancf.scenes.analytic import DYNAMIC_REFERENCES
    ref = DYNAMIC_REFERENCES["spinning-extension"]
    names = {q.name for q in ref.params}
    out, _ = ref.execute({k: v for k, v in p.items() if k in names})
    if not out["converged"]:
        raise ReferenceFailed(f"spinning-extension reference: {out['message']}")
    return {"axial_extension_m": out["results"]["axial_extension_m"]}


def _spinning_spec() -> SceneSpec:
    refs = {
        "spinning-extension": Reference(
            "spinning-extension", "analytic",
            "steady axial extension of the spinning beam (thesis Eq. 2.36, "
            "analytic.dynamics_refs); error = |u − u_ref| / |u_ref| of the extension averaged "
            "over the last mean_window seconds", _spinning_ref, _rel("axial_extension_m"),
            measure="relative axial-extension error"),
    }
    grids = ({"element": ["linear"], "integration": ["thesis"], "n_elements": [2, 3, 4, 8],
              "integrator": ["generalized-alpha"], "dt": [1e-2, 5e-3, 2.5e-3]},
             {"element": ["omar-shabana"], "integration": ["thesis"], "n_elements": [2, 3, 4],
              "integrator": ["generalized-alpha"], "dt": [1e-2, 5e-3]})
    return SceneSpec("spinning-beam", DYNAMIC_KNOBS,
                     frozenset({"axial", "large-rotation", "inertia"}), refs, "spinning-extension",
                     report_grids=grids, recommend_grids=grids, dynamic=True,
                     notes="Spinning beam (thesis Eq. 2.35 spin-up) against the steady extension.")


BELT_STATIC_KNOBS = ("n_elements", "elastic_points", "rtol", "max_iterations")
BELT_KNOBS = ("n_elements", "gauss_points", "elastic_points", "integrator", "dt", "rho_inf",
              "newton_tol", "max_steps")
BELT_PHYSICS = frozenset({"axial", "bending", "shear", "large-rotation"})


def _circle(p):
    return {"radius_m": p["belt_length"] / (2 * math.pi)}


def _roundness_error(res, ref, p):
    """max(|mean radius - R|, max |radius - mean radius|) / R, R = L/(2 pi)."""
    return max(abs(res["radius_mean_m"] - ref["radius_m"]), res["radius_max_dev_m"]) / ref["radius_m"]


def _belt_free_static_spec() -> SceneSpec:
    refs = {"circle": Reference(
        "circle", "analytic",
        "the circle of circumference belt_length, radius R = L/(2π); error = max(|r̄ − R|, "
        "max |r − r̄|) / R over the centreline's distance r from its centroid (r̄ its mean). "
        "The mean radius levels off at 3.0e-6 R from 16 elements on (the ring's own axial "
        "strain under bending), the deviation from roundness falls with the element count",
        _circle, _roundness_error, measure="roundness error / R")}
    grid = ({"n_elements": [4, 6, 8, 10, 16, 20, 40, 80], "elastic_points": [3, 5],
             "rtol": [1e-8, 1e-4]},)
    return SceneSpec("belt-free-static", BELT_STATIC_KNOBS,
                     frozenset({"axial", "bending", "large-rotation"}), refs, "circle",
                     report_grids=grid, recommend_grids=grid, provides=BELT_PHYSICS,
                     notes="Belt released from the pulleys (Dufva elements, Table 3.1) against "
                           "the circle it relaxes to.")


BELT_WINDOW = 0.2  # s before t_end over which the driven speed is averaged


def _mean_driven(res) -> float:
    t, w = np.asarray(res["times"], float), np.asarray(res["omega_driven"], float)
    return float(w[t >= t[-1] - BELT_WINDOW - 1e-12].mean())


def _belt_error(res, ref, p):
    """max of the relative errors of the driven speed averaged over the last BELT_WINDOW
    seconds and of the tight and slack span tensions averaged over the scene's last 0.1 s
    (at one instant they carry the phase of the span and pulley oscillations)."""
    if res.get("tension_tight_mean_N") is None or float(res["times"][-1]) < ref["times"][-1] - 1e-9:
        return float("nan")
    errs = [abs(_mean_driven(res) - _mean_driven(ref)) / abs(_mean_driven(ref))]
    errs += [abs(res[k] - ref[k]) / abs(ref[k])
             for k in ("tension_tight_mean_N", "tension_slack_mean_N")]
    return max(errs)


#: the belt drive's self-reference (its 80-element check is stored with it)
BELT_FINE = {"n_elements": 120, "gauss_points": 11, "elastic_points": 5,
             "integrator": "generalized-alpha", "dt": 1.25e-4, "newton_tol": 1e-10}


def _no_slip(p):
    return {"omega_ratio": p["R1"] / p["R2"]}


def _slip_error(res, ref, p):
    """|omega_ratio_steady - R1/R2| / (R1/R2): the slip of the drive."""
    return abs(res["omega_ratio_steady"] - ref["omega_ratio"]) / ref["omega_ratio"]


def _belt2d_spec() -> SceneSpec:
    refs = {"self": self_reference(
        "belt2d", BELT_FINE, ("times", "omega_driven", "tension_tight_mean_N",
                              "tension_slack_mean_N"),
        _belt_error,
        "converged self-reference: 120 elements, 11 contact points, generalized-α, dt = "
        "1.25e-4 s, Newton tolerance 1e-10 (cached, with an 80-element run's error against it "
        "as self_check_error); "
        f"error = max of the relative errors of the driven speed averaged over the last "
        f"{BELT_WINDOW:g} s and of the tight and slack span tensions averaged over the last "
        "0.1 s",
        check={"n_elements": 80}, knobs=BELT_KNOBS,
        measure="relative error of driven speed, span tensions"),
            "no-slip": Reference(
                "no-slip", "analytic",
                "the inextensible belt without slip: ω_driven / ω_driver = R1/R2; error = "
                "|omega_ratio_steady − R1/R2| / (R1/R2), the slip (creep and spin-up lag) "
                "averaged over the last 0.1 s", _no_slip, _slip_error,
                measure="slip |ω ratio / (R1/R2) − 1|")}
    grids = ({"n_elements": [10, 20, 40, 80], "gauss_points": [5, 7, 11],
              "integrator": ["generalized-alpha"], "dt": [1e-3, 5e-4, 2.5e-4]},
             {"n_elements": [20], "gauss_points": [7], "integrator": ["generalized-alpha"],
              "dt": [2.5e-4], "newton_tol": [1e-4, 1e-5]})
    needs = frozenset({"axial", "bending", "large-rotation", "inertia", "contact"})
    return SceneSpec("belt2d", BELT_KNOBS, needs, refs, "self", report_grids=grids, recommend_grids=grids, dynamic=True,
                     provides=BELT_PHYSICS | {"inertia", "contact"},
                     notes="Two-pulley belt drive (thesis 3.3, Table 3.1, no opposing torque) "
                           "against a converged self-reference.")


BELT3D_KNOBS = ("n_elements", "contact_points", "integrator", "dt", "rho_inf", "newton_tol",
                "max_steps", "strain_measure", "steady_window")


def _bechtel(p):
    """Bechtel's steady belt (analytic.bechtel, inertia included) for the scene's drive."""
    from analytic import bechtel
    try:
        b, top = bechtel.steady({"k": p["E"] * p["h"] * p["width"], "R": p["R"],
                                 "omega": p["omega_final"], "mu": p["mu"], "T_i": p["T_i"],
                                 "T_a": p["Ta_max"], "rhoA": p["rho"] * p["h"] * p["width"]})
    except ValueError as exc:  # Bechtel's names -> the scene's (T_a is Ta_max, omega omega_final)
        text = str(exc)
        for theirs, ours in (("T_a = ", "Ta_max = "), ("omega = ", "omega_final = ")):
            if text.startswith(theirs):
                text = ours + text[len(theirs):]
        raise type(exc)(text) from None
    return bechtel.summary(b, top)


def _bechtel_error(res, ref, p):
    """max relative error of the span membrane tensions against Bechtel's."""
    tn = res.get("tensions")
    if not tn:
        return float("nan")
    return max(abs(tn["membrane"][s] - ref[f"T_{s}_N"]) / abs(ref[f"T_{s}_N"])
               for s in ("tight", "slack"))


def _belt3d_spec() -> SceneSpec:
    refs = {"bechtel": Reference(
        "bechtel", "analytic",
        "Bechtel's steady extensible belt with inertia (`ancf analytic bechtel`, k = E h w, "
        "ρA = ρ h w); error = max relative difference of the span means of the membrane's own "
        "axial force (results.tensions.membrane) from T_tight, T_slack. It includes the model "
        "gap (Bechtel: no slip in the stick arcs, uniform span tension; the FE belt is a "
        "membrane with contact compliance): about 1-3 % for Model 2 at any mesh",
        _bechtel, _bechtel_error, measure="relative span-tension error")}
    grids = ({"n_elements": [20, 30, 40], "contact_points": [25, 49, 81],
              "integrator": ["generalized-alpha"], "dt": [1e-4]},)
    return SceneSpec("belt3d", BELT3D_KNOBS, frozenset({"axial", "large-rotation", "inertia",
                                                        "contact"}),
                     refs, "bechtel", report_grids=grids, recommend_grids=grids, dynamic=True,
                     provides=frozenset({"axial", "large-rotation", "inertia", "contact"}),
                     notes="3D belt drive, Model 2 of Table 4.1 (thin plates, bending off), "
                           "against Bechtel's analytic steady belt.")
PLATE_KNOBS = ("n_elements", "ng")
PLATE_STRIP_KNOBS = ("n_elements", "n_width", "ng", "load_steps", "rtol", "max_iterations",
                     "stability_check")


def _navier(p):
    from analytic import navier_plate
    return {"center_deflection_m": navier_plate.centre_deflection(
        p["a"], p["a"], p["h"], p["E"], p["nu"], p["p"])[0]}


def _plate_square_spec() -> SceneSpec:
    refs = {"navier": Reference(
        "navier", "analytic",
        "Navier's double series of the simply supported Kirchhoff plate (`ancf analytic "
        "navier-plate`, truncation below 1e-10); error = |w − w_ref| / |w_ref| of the centre "
        "deflection", _navier, _rel("center_deflection_m"),
        measure="relative centre-deflection error")}
    grid = ({"n_elements": [2, 4, 8, 16, 32], "ng": [4]},)
    return SceneSpec("plate-square", PLATE_KNOBS, frozenset({"bending", "3D"}), refs, "navier",
                     report_grids=grid, recommend_grids=grid, provides=frozenset({"bending", "3D"}),
                     notes="Simply supported square plate (linear) against Navier's series.")


def _strip_tip_error(res, ref, p):
    """|tip - tip_ref| / |tip_ref - (L, b/2, 0)| over x, y, z."""
    d = math.dist((ref["tip_x"], ref["tip_y"], ref["tip_z"]), (p["L"], p["b"] / 2, 0.0))
    return math.dist((res["tip_x"], res["tip_y"], res["tip_z"]),
                     (ref["tip_x"], ref["tip_y"], ref["tip_z"])) / d


def _plate_strip_spec() -> SceneSpec:
    refs = {"self": self_reference(
        "plate-strip", {"n_elements": 64, "n_width": 1, "ng": 4, "rtol": 1e-9, "load_steps": 10,
                        "max_iterations": 25},
        ("tip_x", "tip_y", "tip_z"), _strip_tip_error,
        "converged self-reference: 64 x 1 plate elements, Newton rtol 1e-9 (cached); error = "
        "|tip − tip_ref| / |tip_ref − (L, b/2, 0)|", check={"n_elements": 32},
        knobs=PLATE_STRIP_KNOBS, measure="relative tip-position error")}
    grid = ({"n_elements": [1, 2, 4, 8, 16], "rtol": [1e-8]},)
    return SceneSpec("plate-strip", PLATE_STRIP_KNOBS,
                     frozenset({"bending", "large-rotation", "3D"}), refs, "self",
                     report_grids=grid, recommend_grids=grid,
                     provides=frozenset({"axial", "bending", "large-rotation", "3D"}),
                     notes="The Model 1 cantilever as a thin-plate strip against a converged "
                           "self-reference.")


def _reissner_3d(p):
    """The Reissner rod in the load plane (h = b, or the load along a principal axis)."""
    if any(p.get(f"M{c}", 0.0) for c in "xyz"):
        raise ReferenceFailed("Reissner reference: a tip force only (Mx = My = Mz = 0)")
    a = math.radians(p["load_angle_deg"])
    c, s = math.cos(a), math.sin(a)
    if abs(p["h"] - p["b"]) > 1e-12 * p["h"] and min(abs(c), abs(s)) > 1e-12:
        raise ReferenceFailed("Reissner reference: a load off the principal axes of a "
                              "non-square section bends the beam out of the load plane")
    h, b = (p["h"], p["b"]) if abs(c) >= abs(s) else (p["b"], p["h"])
    ref = _reissner({**p, "h": h, "b": b})
    return {"tip_x": ref["tip_x"], "tip_y": ref["tip_y"] * c, "tip_z": ref["tip_y"] * s}


def _tip3_error(res, ref, p):
    """|tip - tip_ref| / |tip_ref - (L, 0, 0)|."""
    d = math.dist((ref["tip_x"], ref["tip_y"], ref["tip_z"]), (p["L"], 0.0, 0.0))
    return math.dist((res["tip_x"], res["tip_y"], res["tip_z"]),
                     (ref["tip_x"], ref["tip_y"], ref["tip_z"])) / d


def _beam3d_spec() -> SceneSpec:
    refs = {"reissner": Reference(
        "reissner", "analytic",
        "geometrically exact Reissner rod in the load plane (`ancf analytic reissner`; a square "
        "section or a load along a principal axis); error = |tip − tip_ref| / |tip_ref − (L, 0, "
        "0)|", _reissner_3d, _tip3_error, measure="relative tip-position error")}
    grid = ({"element": ["linear3d"], "integration": ["thesis"], "n_elements": [1, 2, 4, 8, 16],
             "rtol": [1e-8]},
            {"element": ["belt3d"], "n_elements": [1, 2, 4, 8, 16], "rtol": [1e-8]})
    return SceneSpec("beam3d-cantilever", STATIC_KNOBS,
                     frozenset({"axial", "bending", "shear", "large-rotation", "3D"}), refs,
                     "reissner", report_grids=grid, recommend_grids=grid,
                     notes="Model 1 cantilever with the 3D linear element and the 3D belt "
                           "element (alpha1 = alpha2 = 1) against the Reissner rod.")


def _published_problem(p: dict, data: dict, what: str) -> None:
    """ReferenceFailed unless the problem parameters of p are the published ``data``."""
    for k, v in data.items():
        if not math.isclose(p[k], v, rel_tol=1e-12, abs_tol=0.0):
            raise ReferenceFailed(f"{what}: published for {k} = {v:g} only (got {p[k]:g})")


def _princeton(p):
    """The published ANSYS beam tip displacements of the Princeton beam at p's load and
    angle, as signed tip positions y, z of our load (F (0, cos a, sin a))."""
    from ancf.scenes import beam3d_published as pub
    what = "Princeton beam (ANSYS, Obrezkov et al. 2022)"
    _published_problem(p, {**pub.PRINCETON, "Mx": 0.0, "My": 0.0, "Mz": 0.0}, what)
    load = [k for k, f in pub.PRINCETON_LOADS.items() if math.isclose(abs(p["F"]), f,
                                                                     rel_tol=1e-12)]
    a = abs(p["load_angle_deg"])
    at = [i for i, b in enumerate(pub.PRINCETON_ANGLES) if math.isclose(a, b, abs_tol=1e-12)]
    if not load or not at:
        raise ReferenceFailed(f"{what}: published for |F| in {sorted(pub.PRINCETON_LOADS.values())} N "
                              f"and |load_angle_deg| in {list(pub.PRINCETON_ANGLES)} only")
    uy, uz = (c[at[0]] for c in pub.PRINCETON_ANSYS[load[0]][pub.PRINCETON_REFERENCE])
    r = math.radians(p["load_angle_deg"])
    return {"tip_y": math.copysign(uy, p["F"] * math.cos(r)),
            "tip_z": math.copysign(uz, p["F"] * math.sin(r))}


def _yz_error(res, ref, p):
    """|(y, z) - (y, z)_ref| / |(y, z)_ref| of the tip."""
    return (math.hypot(res["tip_y"] - ref["tip_y"], res["tip_z"] - ref["tip_z"])
            / math.hypot(ref["tip_y"], ref["tip_z"]))


def _general_bending(p):
    """Nachbagauer et al. 2013, Table 4, ANSYS: the tip position (it moves to -x, -y, -z)."""
    from ancf.scenes import beam3d_published as pub
    _published_problem(p, {**pub.GENERAL_BENDING, "Mz": 0.0, "F": 0.0},
                       "3D general bending (Nachbagauer et al. 2013, Table 4)")
    ux, uy, uz = pub.GENERAL_BENDING_TABLE_4[pub.GENERAL_BENDING_REFERENCE][1]
    return {"tip_x": p["L"] - ux, "tip_y": -uy, "tip_z": -uz}


def _displacement_error(res, ref, p):
    """Largest relative error of the three tip displacements u = tip - (L, 0, 0)."""
    return max(abs((res[k] - ref[k]) / (ref[k] - o))
               for k, o in (("tip_x", p["L"]), ("tip_y", 0.0), ("tip_z", 0.0)))


_BEAM3D_GRIDS = (
    {"element": ["linear3d"], "integration": ["thesis", "exact", "report-fix"],
     "n_elements": [2, 4, 8, 16, 32, 64], "rtol": [1e-8]},
    {"element": ["belt3d"], "n_elements": [2, 4, 8, 16, 32], "rtol": [1e-8]})


def _self_3d(scene: str, quantities: tuple, error, what: str, measure: str) -> Reference:
    return self_reference(
        scene, {"element": "linear3d", "integration": "thesis", "n_elements": 256,
                "rtol": 1e-10, "load_steps": 10, "max_iterations": 25},
        quantities, error, "converged self-reference: linear3d, thesis scheme, 256 elements, "
        f"Newton rtol 1e-10 (cached); error = {what}; measures the discretisation error only",
        check={"n_elements": 128}, measure=measure)


def _princeton_spec() -> SceneSpec:
    what = "|(y, z) − (y, z)_ref| / |(y, z)_ref| of the tip"
    measure = "relative tip-displacement (y, z) error"
    refs = {"published": Reference(
        "published", "published",
        "ANSYS beam elements (Obrezkov et al. 2022, as Exudyn's TestModels/ANCFBeamTest.py "
        f"lists them; F2, F3 at 0-90° in steps of 15°); error = {what}", _princeton,
        _yz_error, measure=measure),
        "self": _self_3d("princeton-beam", ("tip_x", "tip_y", "tip_z"), _yz_error, what, measure)}
    return SceneSpec("princeton-beam", STATIC_KNOBS,
                     frozenset({"bending", "large-rotation", "3D"}), refs, "published",
                     report_grids=_BEAM3D_GRIDS, recommend_grids=_BEAM3D_GRIDS,
                     notes="The Princeton beam, F2 at 0° (defaults), against ANSYS beam "
                           "elements.")


def _bending_spec() -> SceneSpec:
    what = "largest relative error of the tip displacements u_x, u_y, u_z"
    measure = "largest relative tip-displacement error"
    refs = {"published": Reference(
        "published", "published",
        "Nachbagauer et al. 2013, Table 4, ANSYS (40 elements), as Exudyn's "
        f"TestModels/ANCFBeamTest.py lists it; error = {what}", _general_bending,
        _displacement_error, measure=measure),
        "self": _self_3d("beam3d-bending", ("tip_x", "tip_y", "tip_z"), _displacement_error, what,
                         measure)}
    return SceneSpec("beam3d-bending", STATIC_KNOBS, frozenset({"bending", "large-rotation",
                                                                 "3D"}),
                     refs, "published", report_grids=_BEAM3D_GRIDS,
                     recommend_grids=_BEAM3D_GRIDS,
                     notes="3D general bending (Mx = 0.5e6, My = 2e6 N m) against ANSYS.")


def _drive_steady(p):
    from ancf.scenes.belt_drive import steady_reference
    from ancf.common.params import InputError
    try:
        return steady_reference(p)
    except (InputError, ValueError) as exc:
        raise ReferenceFailed(f"steady reference (analytic/belt_steady.py): {exc}") from None


def _drive_error(res, ref, p):
    """max of the span tensions' |T_mean − T_ref| / |T_ref| and the free pulleys'
    |omega_mean − omega_ref| / |omega_ref| (every pulley but the prescribed and fixed)."""
    spans = [abs(a["tension_mean_N"] - b["tension_N"]) / abs(b["tension_N"])
             for a, b in zip(res["spans"], ref["spans"])]
    speeds = [abs(a["omega_mean"] - b["omega"]) / abs(b["omega"])
              for a, b in zip(res["pulleys"], ref["pulleys"])
              if b["law"] not in ("prescribed", "fixed") and b["omega"]]
    return float(max(spans + speeds))


#: the drive file's model parameters (ancf.scenes.belt_drive.MODEL_KEYS)
DRIVE_KNOBS = ("n_elements", "dt", "gauss_points")
#: the model grids per belt element of the file (contact points: Gauss points along a
#: Dufva element, n x n points over a plate)
DRIVE_GRIDS = {"dufva2d": ({"n_elements": [30, 45, 60], "gauss_points": [5, 7]},),
               "plate36": ({"n_elements": [20, 30, 40], "gauss_points": [25, 49]},)}


def _drive_grids(params: dict) -> tuple:
    from ancf.scenes.belt_drive import description
    return DRIVE_GRIDS[description(params).belt["element"]]


def _belt_drive_spec() -> SceneSpec:
    refs = {"steady": Reference(
        "steady", "analytic",
        "steady extensible belt on the drive's layout (`analytic/belt_steady.py`: Bechtel's "
        "string with the centrifugal term around the N pulleys, Coulomb stick and creep arcs, "
        "the laws' final values); error = max of the spans' |T_mean − T_ref| / |T_ref| (mean "
        "over run.steady_window and the span's middle third) and the free pulleys' |ω_mean − "
        "ω_ref| / |ω_ref|. It includes the model gap (creep-rate against Coulomb friction, "
        "the penalty's penetration: 1-2 % on the shipped examples) and whatever of the "
        "start-up the window still holds", _drive_steady, _drive_error)}
    grids = DRIVE_GRIDS["dufva2d"]
    return SceneSpec("belt-drive", DRIVE_KNOBS, frozenset({"axial", "bending", "inertia",
                                                          "contact"}),
                     refs, "steady", report_grids=grids, recommend_grids=grids, dynamic=True,
                     grids_for=_drive_grids,
                     provides=frozenset({"axial", "bending", "shear", "large-rotation",
                                         "inertia", "contact"}),
                     notes="A drive file (`--set file=PATH`; default the thesis drive) "
                           "against the steady reference on its layout.")


# ---------------------------------------------------------------------------------------
# frequencies (``--quantity frequency``: ``ancf modes`` about the reference)
# ---------------------------------------------------------------------------------------

#: what a sweep computes: the scene's own results, or its natural frequencies
QUANTITIES = ("results", "frequency")


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


def _frequency_error(res, ref, p):
    """max over the first K modes of |f_k / f_ref,k - 1|."""
    f = bending_frequencies(res, int(p["count"]))
    return float(np.max(np.abs(f / np.asarray(ref["frequencies_hz"]) - 1.0)))


def _timoshenko_modes(support: str):
    def values(p):
        from analytic import beam_modes
        return {"frequencies_hz": [float(x) for x in beam_modes.timoshenko(
            support, count=int(p["count"]), L=p["L"], E=p["E"],
            G=p["E"] / (2.0 * (1.0 + p["nu"])), I=p["b"] * p["h"] ** 3 / 12.0,
            A=p["b"] * p["h"], rho=p["rho"], ks=p["ks"])]}
    return values


def _navier_modes(p):
    from analytic import plate_modes
    return {"frequencies_hz": [float(x) for x in plate_modes.navier_frequencies(
        p["a"], p["a"], p["h"], p["E"], p["nu"], p["rho"], int(p["count"]))[0]]}


_FREQUENCY_ERROR = ("error = max over the lowest K = count bending modes of |f_k / f_ref,k − 1| "
                    "(`ancf modes` about the reference, consistent mass)")
_BEAM_FREQUENCY_MESHES = (2, 4, 8, 16, 32, 64, 128)


def _beam_frequency_spec(scene: str, support: str, what: str) -> SceneSpec:
    name = "timoshenko-frequencies"
    refs = {name: Reference(
        name, "analytic", f"Timoshenko beam frequencies, {what} (`analytic/beam_modes.py`: "
        f"shear and rotary inertia, frequency equations solved numerically); {_FREQUENCY_ERROR}",
        _timoshenko_modes(support), _frequency_error)}
    grids = _element_grids(_BEAM_FREQUENCY_MESHES)
    return SceneSpec(scene, STATIC_KNOBS, frozenset({"bending", "shear"}), refs, name,
                     report_grids=grids, recommend_grids=grids, quantity="frequency",
                     notes=f"The {what} beam's lowest bending frequencies against Timoshenko.")


def _plate_frequency_spec() -> SceneSpec:
    name = "navier-frequencies"
    refs = {name: Reference(
        name, "analytic", "Navier's frequencies of the simply supported Kirchhoff plate "
        f"(`analytic/plate_modes.py`); {_FREQUENCY_ERROR}", _navier_modes, _frequency_error)}
    grid = ({"n_elements": [2, 4, 6, 8, 12, 16, 24], "ng": [3, 4]},)
    return SceneSpec("plate-square", PLATE_KNOBS, frozenset({"bending", "3D"}), refs, name,
                     report_grids=grid, recommend_grids=grid,
                     provides=frozenset({"bending", "3D"}), quantity="frequency",
                     notes="The simply supported square plate's lowest frequencies against "
                           "Navier.")


#: Scene name -> spec factory of its frequencies (``--quantity frequency``).
FREQUENCY_SPECS: dict[str, Callable[[], SceneSpec]] = {
    "cantilever": lambda: _beam_frequency_spec("cantilever", "cantilever", "clamped–free"),
    "simply-supported": lambda: _beam_frequency_spec("simply-supported", "simply-supported",
                                                     "simply supported"),
    "plate-square": _plate_frequency_spec,
}


#: Scene name -> spec factory.  One entry per scene; dynamic ones activate with their scene.
SPECS: dict[str, Callable[[], SceneSpec]] = {
    "cantilever": _cantilever_spec,
    "simply-supported": _simply_supported_spec,
    "axial-bar": _axial_bar_spec,
    "pendulum": _pendulum_spec,
    "spinning-beam": _spinning_spec,
    "belt-free-static": _belt_free_static_spec,
    "belt2d": _belt2d_spec,
    "belt3d": _belt3d_spec,
    "plate-square": _plate_square_spec,
    "plate-strip": _plate_strip_spec,
    "beam3d-cantilever": _beam3d_spec,
    "princeton-beam": _princeton_spec,
    "beam3d-bending": _bending_spec,
    "belt-drive": _belt_drive_spec,
}


def runner(scene: str, quantity: str = "results"):
    """The :class:`~ancf.scenes.base.Scene` a sweep runs: the scene itself, or for
    ``quantity = "frequency"`` its ``ancf modes`` about the reference
    (:func:`ancf.scenes.modes.frequency_scene`)."""
    check_quantity(scene, quantity)
    if quantity == "frequency":
        from ancf.scenes.modes import frequency_scene
        return frequency_scene(scene)
    from ancf.scenes import SCENES
    return SCENES[scene]


def check_quantity(scene: str, quantity: str) -> None:
    """InputError unless ``quantity`` is one of :data:`QUANTITIES` that ``scene`` has."""
    from ancf.common.params import InputError
    if quantity not in QUANTITIES:
        raise InputError(f"quantity: {quantity!r} is not valid; allowed: "
                         f"{', '.join(QUANTITIES)}")
    if quantity == "frequency" and scene not in FREQUENCY_SPECS:
        raise InputError(f"quantity frequency: scene {scene!r} has no frequency reference; "
                         f"allowed: the scenes {', '.join(FREQUENCY_SPECS)}")


@lru_cache(maxsize=None)
def spec(scene: str, quantity: str = "results") -> SceneSpec:
    """The spec of a scene of ``SCENES``: its entry in :data:`SPECS` (for ``quantity =
    "frequency"``: in :data:`FREQUENCY_SPECS`), else one built from
    the scene's optional ``knobs`` / ``needs`` / ``reference`` fields with a self-reference
    at 8x the default element count."""
    from ancf.scenes import SCENES
    from ancf.common.params import InputError
    if scene not in SCENES:
        raise InputError(f"scene: unknown name {scene!r}; allowed: {', '.join(SCENES)}")
    check_quantity(scene, quantity)
    if quantity == "frequency":
        return FREQUENCY_SPECS[scene]()
    if scene in SPECS:
        return SPECS[scene]()
    sc = SCENES[scene]
    names = [p.name for p in sc.params]
    knobs = tuple(getattr(sc, "knobs", ()) or [k for k in DYNAMIC_KNOBS + STATIC_KNOBS
                                               if k in names])
    defaults = sc.resolve({})
    fine = {"n_elements": 8 * defaults["n_elements"]} if "n_elements" in names else {}
    quantities = tuple(k for k, v in sc.execute({})[0]["results"].items()
                       if isinstance(v, float))

    def err(res, ref, p):
        return max(abs(res[q] - ref[q]) / max(abs(ref[q]), 1e-300) for q in quantities)
    refs = {"self": self_reference(scene, fine, quantities, err,
                                   f"self-reference at {_knob_text(fine)}; error = max relative "
                                   "difference of the scalar results", knobs=knobs,
                                   measure="largest relative error of the results")}
    return SceneSpec(scene, knobs, frozenset(getattr(sc, "needs", ()) or ()), refs, "self",
                     report_grids=({"n_elements": [1, 2, 4, 8]},) if fine else ({},),
                     recommend_grids=({"n_elements": [1, 2, 4, 8]},) if fine else ({},))


def specs() -> dict:
    """Specs of every swept scene of ``SCENES`` (declaration order of the registry)."""
    from ancf.scenes import SCENES
    return {name: spec(name) for name, s in SCENES.items() if s.swept}


def model_physics(scene: str, params: dict) -> frozenset:
    """The physics a configuration provides."""
    s = spec(scene)
    if s.provides is not None:
        return s.provides
    got = set(ELEMENT_PHYSICS.get(params.get("element", "linear"), frozenset()))
    if not s.dynamic:
        got.discard("inertia")
    return frozenset(got)


def rescore(df, scene: str, reference: str, quantity: str = "results"):
    """Errors of sweep rows (a DataFrame from :mod:`ancf.study.sweep`) against another reference,
    from the stored scalar results (``res_*`` columns); NaN where not converged."""
    s = spec(scene, quantity)
    ref = s.reference(reference)
    names = [p.name for p in runner(scene, quantity).params]
    cache = {}
    out = []
    for _, row in df.iterrows():
        if row.get("status") != "ok":
            out.append(float("nan"))
            continue
        p = {k: _py(row[k]) for k in names}
        pk = stable_hash(s.physical(p))
        if pk not in cache:
            try:
                cache[pk] = ref.values(p)
            except ReferenceFailed:
                cache[pk] = None
        res = {c[4:]: _py(row[c]) for c in row.index if c.startswith("res_")}
        out.append(float("nan") if cache[pk] is None else float(ref.error(res, cache[pk], p)))
    return np.array(out)


def _py(v):
    if isinstance(v, np.generic):
        return v.item()
    return v
