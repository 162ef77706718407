"""Simply supported beam with a midspan load (thesis Fig. 2.3, Tables 2.1-2.2;
report Tables 1-2).  Supports: x and y of the first node, y of the last node.
"""
import numpy as np

from ancf.scenes import accuracy
from ancf.core.constraints import Elimination
from ancf.scenes import beam_static as bs
from ancf.common.params import InputError, Param
from ancf.scenes.base import STEEL_DENSITY, Scene
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


SCENE = Scene(
    "simply-supported",
    "Simply supported beam, vertical point load at midspan (linear deformation test).",
    bs.element_params(n_elements=8) + (
        Param("F", -1000.0, float, "N", "vertical midspan force (negative = downward)"),),
    run, _check, warn=accuracy.static, modal=modal, modal_params=(STEEL_DENSITY,))
