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
from ancf.scenes.base import STATIC_RESULTS, STEEL_DENSITY, Scene, nullable
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


RESULTS = {**STATIC_RESULTS, "elongation_m": nullable("elongation, m"),
           "tip_reaction_y_N": nullable("transverse reaction at the tip support, N")}


def study():
    """What sweeps measure this scene against: its references, errors and grids."""
    from ancf.scenes.spec import (STATIC_KNOBS, STATIC_RTOL, Reference, SceneSpec, element_grids,
                                  relative)
    refs = {
        "bar": Reference(
            "bar", "analytic",
            "uniaxial St-Venant–Kirchhoff bar (Green strain, the ANCF material law): "
            "F/A = E λ(λ² − 1)/2, elongation (λ − 1) L; error = |u − u_ref| / |u_ref|",
            _bar_svk, relative("elongation_m"), measure="relative elongation error"),
        "linear-bar": Reference(
            "linear-bar", "analytic",
            "linear bar F L/(E A); error = |u − u_ref| / |u_ref| (differs from the "
            "St-Venant–Kirchhoff bar by 1.5 × strain, 3.6e-5 at the default load)",
            _bar_linear, relative("elongation_m"), measure="relative elongation error"),
    }
    return SceneSpec(
        "axial-bar", STATIC_KNOBS, frozenset({"axial"}), refs, "bar",
        report_grids=element_grids((1, 2, 4, 8, 16, 32), **STATIC_RTOL),
        recommend_grids=element_grids((1, 2, 4, 8, 16), **STATIC_RTOL),
        notes="Defaults (F = 5e4 N) against the St-Venant–Kirchhoff bar.")


#: the scene's place in the scene list (ancf.scenes.MODULES, ancf scenes, reports/schemas.md)
ORDER = 30
SCENE = Scene(
    "axial-bar",
    "Pinned bar pulled by an axial tip force (linear axial deformation test).",
    bs.element_params(n_elements=4) + (Param("F", 5.0e4, float, "N", "axial tip force"),),
    run, bs.check_integration, warn=accuracy.static, modal=modal,
    modal_params=(STEEL_DENSITY,),
    results=RESULTS, study=study)
