"""Simply supported beam with a midspan load (thesis Fig. 2.3, Tables 2.1-2.2;
report Tables 1-2).  Supports: x and y of the first node, y of the last node.
"""
import numpy as np

from ancf.scenes import accuracy
from ancf.core.constraints import Elimination
from ancf.scenes import beam_static as bs
from ancf.common.params import InputError, Param
from ancf.scenes.base import STATIC_RESULTS, STEEL_DENSITY, Scene, nullable
from ancf.core.validity import check_static


def _check(p):
    bs.check_integration(p)
    if p["n_elements"] % 2:
        raise InputError(f"n_elements = {p['n_elements']} is out of range for simply-supported; "
                         "allowed: an even integer >= 2 (the load acts on the middle node)")


def setup(p):
    """(mesh, q0, assembly, elimination, load vector) of the beam (density ``p["rho"]``
    if given)."""
    mesh, q0, asm = bs.build(p)
    n, mid = p["n_elements"], p["n_elements"] // 2
    elim = Elimination(mesh.n_dofs)
    for d in (mesh.dof(0, "r", 0), mesh.dof(0, "r", 1), mesh.dof(n, "r", 1)):
        elim.fix(d, q0[d])
    Qk = np.zeros(mesh.n_dofs)
    Qk[mesh.dof(mid, "r", 1)] = p["F"]
    return mesh, q0, asm, elim, Qk


def run(p):
    mesh, q0, asm, elim, Qk = setup(p)
    iy = mesh.dof(p["n_elements"] // 2, "r", 1)
    res = bs.solve(p, mesh, q0, asm, elim, Qk, lambda q: {"mid_deflection_m": float(q[iy] - q0[iy])})
    return check_static(res, asm, q0)


def modal(p):
    return bs.modal(p, *setup(p))


def _timoshenko_ss(p):
    from analytic import timoshenko
    return {"mid_deflection_m": timoshenko.mid_deflection(p["E"], p["nu"], p["L"], p["h"],
                                                          p["b"], p["F"], ks=p["ks"])}


RESULTS = {**STATIC_RESULTS, "mid_deflection_m": nullable("midpoint deflection, m")}


def study():
    """What sweeps measure this scene against: its references, errors and grids."""
    from ancf.scenes.spec import (STATIC_KNOBS, STATIC_RTOL, Reference, SceneSpec, element_grids,
                                  relative, self_reference)
    refs = {
        "timoshenko": Reference(
            "timoshenko", "analytic",
            "Timoshenko beam, midspan load (`ancf analytic timoshenko`, SymPy-derived); error = "
            "|w − w_ref| / |w_ref|", _timoshenko_ss, relative("mid_deflection_m"),
            measure="relative midspan-deflection error"),
        "self": self_reference(
            "simply-supported", {"element": "linear", "integration": "thesis", "n_elements": 1024,
                                 "rtol": 1e-8},
            ("mid_deflection_m",), relative("mid_deflection_m"),
            "converged self-reference: linear element, thesis scheme, 1024 elements (cached); "
            "error = |w − w_ref| / |w_ref|", check={"n_elements": 512},
            measure="relative midspan-deflection error"),
    }
    ns = (2, 4, 8, 16, 32, 64, 128, 256)
    return SceneSpec(
        "simply-supported", STATIC_KNOBS, frozenset({"bending", "shear"}), refs, "timoshenko",
        report_grids=element_grids(ns, **STATIC_RTOL),
        recommend_grids=element_grids(ns[:-1], **STATIC_RTOL),
        notes="Defaults (ν = 0, F = −1000 N) against the Timoshenko beam.")


def frequency_study():
    """What ``--quantity frequency`` measures: the bending frequencies against Timoshenko."""
    return bs.frequency_study("simply-supported", "simply-supported", "simply supported")


#: the scene's place in the scene list (ancf.scenes.MODULES, ancf scenes, reports/schemas.md)
ORDER = 10
#: its place among the scenes with a frequency reference (FREQUENCY_SPECS)
FREQUENCY_ORDER = 20
SCENE = Scene(
    "simply-supported",
    "Simply supported beam, vertical point load at midspan (linear deformation test).",
    bs.element_params(n_elements=8) + (
        Param("F", -1000.0, float, "N", "vertical midspan force (negative = downward)"),),
    run, _check, warn=accuracy.static, modal=modal, modal_params=(STEEL_DENSITY,),
    results=RESULTS, study=study, frequency_study=frequency_study)
