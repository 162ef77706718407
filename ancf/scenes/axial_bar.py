"""Bar under an axial tip force (report Fig. 4, Table 6).

Pinned at the first node (x and y).  A pinned bar is a mechanism at zero load
(rigid rotation about the pin makes the first Newton tangent singular), so the
loaded end is held in y by a roller; under a purely axial load its reaction is
zero, which the scene reports (``results.tip_reaction_y_N``) as evidence.
"""
import numpy as np

from ancf.scenes import accuracy
from ancf.core.constraints import Elimination
from ancf.scenes import beam_static as bs
from ancf.common.params import Param
from ancf.scenes.base import STEEL_DENSITY, Scene
from ancf.core.validity import check_static


def setup(p):
    """(mesh, q0, assembly, elimination, load vector) of the bar (density ``p["rho"]`` if
    given)."""
    mesh, q0, asm = bs.build(p)
    n = p["n_elements"]
    elim = Elimination(mesh.n_dofs)
    for d in (mesh.dof(0, "r", 0), mesh.dof(0, "r", 1), mesh.dof(n, "r", 1)):
        elim.fix(d, q0[d])
    Qk = np.zeros(mesh.n_dofs)
    Qk[mesh.dof(n, "r", 0)] = p["F"]
    return mesh, q0, asm, elim, Qk


def run(p):
    mesh, q0, asm, elim, Qk = setup(p)
    ix, iy_tip = mesh.dof(p["n_elements"], "r", 0), mesh.dof(p["n_elements"], "r", 1)

    def results(q):
        return {"elongation_m": float(q[ix] - q0[ix]),
                "tip_reaction_y_N": float(asm.gradient(q)[iy_tip] - Qk[iy_tip])}
    return check_static(bs.solve(p, mesh, q0, asm, elim, Qk, results), asm, q0)


def modal(p):
    return bs.modal(p, *setup(p))


SCENE = Scene(
    "axial-bar",
    "Pinned bar pulled by an axial tip force (linear axial deformation test).",
    bs.element_params(n_elements=4) + (Param("F", 5.0e4, float, "N", "axial tip force"),),
    run, bs.check_integration, warn=accuracy.static, modal=modal,
    modal_params=(STEEL_DENSITY,))
