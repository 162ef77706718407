"""Cantilever under a large tip load (thesis Fig. 2.4, Tables 2.3-2.4; report
Tables 3-5).  Clamp: position and the slope dr/dy of the first node, as the papers
state.  ``clamp_x_slope = fixed`` also fixes dr/dx (Omar-Shabana): with it the thesis's
Omar-Shabana columns are reproduced to the printed digits (reports/static_beams.md).
Model 1: h = 0.1 m, nu = 0.3 (defaults); Model 2: h = 0.5 m, nu = 0.
"""
import numpy as np

from ancf.scenes import accuracy
from ancf.core.constraints import Elimination
from ancf.scenes import beam_static as bs
from ancf.common.params import Param
from ancf.scenes.base import STEEL_DENSITY, Scene
from ancf.core.validity import check_static


def setup(p):
    """(mesh, q0, assembly, elimination, load vector) of the cantilever (density
    ``p["rho"]`` if given)."""
    mesh, q0, asm = bs.build(p)
    n = p["n_elements"]
    elim = Elimination(mesh.n_dofs)
    slots = ("r", "r_y") + (("r_x",) if p["clamp_x_slope"] == "fixed" else ())
    for slot in (name for name in slots if name in mesh.slots):
        for k in (0, 1):
            d = mesh.dof(0, slot, k)
            elim.fix(d, q0[d])
    Qk = np.zeros(mesh.n_dofs)
    Qk[mesh.dof(n, "r", 1)] = p["F"]
    return mesh, q0, asm, elim, Qk


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


SCENE = Scene(
    "cantilever",
    "Cantilever with a vertical tip force, large deflection (Models 1 and 2 via h, nu).",
    cantilever_params(), run, bs.check_integration, warn=accuracy.static, modal=modal,
    modal_params=(STEEL_DENSITY,))
