"""Cantilever under a large tip load (thesis Fig. 2.4, Tables 2.3-2.4; report
Tables 3-5).  Clamp: position and the slope dr/dy of the first node, as the papers
state.  ``clamp_x_slope = fixed`` also fixes dr/dx (Omar-Shabana): with it the thesis's
Omar-Shabana columns are reproduced to the printed digits (reports/static_beams.md).
Model 1: h = 0.1 m, nu = 0.3 (defaults); Model 2: h = 0.5 m, nu = 0.
"""
import math
from functools import lru_cache

import numpy as np

from ancf.scenes import accuracy
from ancf.core.constraints import Elimination
from ancf.scenes import beam_static as bs
from ancf.common.params import Param
from ancf.scenes.base import STATIC_RESULTS, STEEL_DENSITY, ReferenceFailed, Scene, nullable
from ancf.core.validity import check_static


def setup(p):
    """(mesh, q0, assembly, elimination, load vector) of the cantilever (density
    ``p["rho"]`` if given).  The elimination (read-only) is built once per clamp
    (:func:`_clamp`), as the mesh and assembly are (``beam_static.build``)."""
    mesh, q0, asm = bs.build(p)
    n = p["n_elements"]
    slots = ("r", "r_y") + (("r_x",) if p["clamp_x_slope"] == "fixed" else ())
    dofs = [mesh.dof(0, slot, k) for slot in slots if slot in mesh.slots for k in (0, 1)]
    elim = _clamp(mesh.n_dofs, tuple((d, float(q0[d])) for d in dofs))
    Qk = np.zeros(mesh.n_dofs)
    Qk[mesh.dof(n, "r", 1)] = p["F"]
    return mesh, q0, asm, elim, Qk


@lru_cache(maxsize=32)
def _clamp(n_dofs: int, pins: tuple) -> Elimination:
    """The elimination of ``n_dofs`` coordinates fixing those of ``pins`` (pairs of
    coordinate and value)."""
    elim = Elimination(n_dofs)
    for d, value in pins:
        elim.fix(d, value)
    return elim


def run(p):
    mesh, q0, asm, elim, Qk = setup(p)
    ix, iy = mesh.dof(p["n_elements"], "r", 0), mesh.dof(p["n_elements"], "r", 1)
    res = bs.solve(p, mesh, q0, asm, elim, Qk, lambda q: {"tip_x": float(q[ix]), "tip_y": float(q[iy])})
    return check_static(res, asm, q0)


def modal(p):
    return bs.modal(p, *setup(p))


def cantilever_params():
    base = {q.name: q for q in bs.element_params(nu=0.3, h=0.1, n_elements=8)}
    base["load_steps"] = Param("load_steps", 10, int, doc=base["load_steps"].doc, lo=1, hi=10000)
    return tuple(base.values()) + (
        Param("F", lambda v: -5e8 * v["h"] ** 3, float, "N",
              "vertical tip force (default -5e8 h^3, negative = downward)"),
        Param("clamp_x_slope", "free", str,
              doc="'fixed' also clamps the slope dr/dx of the first node (Omar-Shabana; the "
                  "linear element has no dr/dx coordinate, so both values give the same model); "
                  "'free' clamps r and dr/dy only, as the papers state",
              choices=("free", "fixed")),)


def _tip_error(res, ref, p):
    """|tip - tip_ref| / |tip_ref - (L, 0)|: tip-position error over the reference deflection."""
    d = math.hypot(ref["tip_x"] - p["L"], ref["tip_y"])
    return math.hypot(res["tip_x"] - ref["tip_x"], res["tip_y"] - ref["tip_y"]) / d


def reissner_tip(p):
    """The Reissner rod's tip (``ancf analytic reissner``) under the scene's load."""
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


RESULTS = {**STATIC_RESULTS, "tip_x": nullable("tip x, m"), "tip_y": nullable("tip y, m")}


def study():
    """What sweeps measure this scene against: its references, errors and grids."""
    from ancf.scenes.spec import (STATIC_KNOBS, STATIC_RTOL, Reference, SceneSpec, element_grids,
                                  relative, self_reference)
    refs = {
        "reissner": Reference(
            "reissner", "analytic",
            "geometrically exact Reissner rod (`ancf analytic reissner`); error = |tip − tip_ref| / "
            "|tip_ref − (L, 0)|. At large strain it includes the constitutive gap between the ANCF "
            "St-Venant–Kirchhoff continuum and the Reissner rod (5e-4 in Model 1, 1.5e-2 in "
            "Model 2; see static_beams.md)", reissner_tip, _tip_error, measure="relative tip-position error"),
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
        report_grids=element_grids((1, 2, 4, 8, 16, 32, 64, 128, 256), **STATIC_RTOL),
        recommend_grids=element_grids((1, 2, 4, 8, 16, 32, 64, 128), **STATIC_RTOL),
        notes="Model 1 (defaults h = 0.1 m, ν = 0.3, F = −5e5 N) against the Reissner rod.")


def frequency_study():
    """What ``--quantity frequency`` measures: the bending frequencies against Timoshenko."""
    return bs.frequency_study("cantilever", "cantilever", "clamped–free")


#: the scene's place in the scene list (ancf.scenes.MODULES, ancf scenes, reports/schemas.md)
ORDER = 20
#: its place among the scenes with a frequency reference (FREQUENCY_SPECS)
FREQUENCY_ORDER = 10
SCENE = Scene(
    "cantilever",
    "Cantilever with a vertical tip force, large deflection (Models 1 and 2 via h, nu).",
    cantilever_params(), run, bs.check_integration, warn=accuracy.static, modal=modal,
    modal_params=(STEEL_DENSITY,),
    results=RESULTS, study=study, frequency_study=frequency_study)
