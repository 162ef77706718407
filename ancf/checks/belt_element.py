"""Dufva's belt element on its own (thesis 3.1, ref. [54]): a cantilever of the element
clamped at the root, under a dead tip force or an end moment.  Shared by
``tests/elements/test_belt_element.py`` and the belt chapter of the reports.

Clamp: position and r_y (the cross-section) of the root node, as the papers state
(ancf/scenes/cantilever.py); clamping r_x as well would force sin(gamma) = 0 there.
"""
from __future__ import annotations

import numpy as np

from analytic import reissner
from ancf.core.assembly import Assembly, ElementGroup
from ancf.core.constraints import Elimination
from ancf.elements.dufva2d import DufvaBelt2D
from ancf.core.forces import EndMoment, Forces
from ancf.core.mesh import BeamMesh
from ancf.core.quadrature import RectangularSection
from ancf.solvers.static import NewtonOptions, solve_static

MODEL1 = reissner.MODELS["model1"]  # L = 2 m, b = h = 0.1 m, E = 2.07e11 Pa, nu = 0.3, F = -5e5 N
SECTION1 = RectangularSection(MODEL1["b"], MODEL1["h"])
CIRCLE_LOAD_STEPS = 8
CIRCLE_H_FOUR = 0.08   # m, the section where four elements close the circle (see the belt chapter)
REISSNER_TOL = 4e-4    # m, Model 1 tip against the Reissner rod (model difference 3.1e-4 m + 30 %)


def cantilever(n: int, section=SECTION1, L: float = MODEL1["L"], **kw):
    """(mesh, q0, assembly, elimination) of a straight n-element cantilever along +x
    clamped at the root in r and r_y; kw go to the element (E, nu default to Model 1)."""
    kw = {"E": MODEL1["E"], "nu": MODEL1["nu"], **kw}
    m = BeamMesh(L, n, DufvaBelt2D.slots)
    q0 = m.reference()
    el = DufvaBelt2D(m.lengths, q0[m.dofmap], section, **kw)
    root = [m.dof(0, s, c) for s in ("r", "r_y") for c in (0, 1)]
    return m, q0, Assembly(m.n_dofs, [ElementGroup(el, m.dofmap)]), Elimination(m.n_dofs).fix(root, q0[root])


def circle_gap(n: int, h: float, L: float = 2.0, **kw) -> float:
    """|tip - root| / L of an n-element cantilever (b = h, m) under the end moment
    M = 2 pi E I / L that bends a linear elastic beam into a full circle (nan if Newton
    fails)."""
    section = RectangularSection(h, h)
    m, q0, asm, elim = cantilever(n, section=section, L=L, **kw)
    E = kw.get("E", MODEL1["E"])
    M = 2 * np.pi * E * section.second_moment / L
    tip_slope = [m.dof(n, "r_x", 0), m.dof(n, "r_x", 1)]
    forces = Forces(m.n_dofs, [EndMoment(m.n_dofs, tip_slope, M)])
    res = solve_static(asm, elim, np.zeros(m.n_dofs), q0, NewtonOptions(n_steps=CIRCLE_LOAD_STEPS),
                       forces=forces)
    if not res.converged:
        return float("nan")
    return float(np.linalg.norm(res.q[[m.dof(n, "r", 0), m.dof(n, "r", 1)]]) / L)


def tip_under(n: int, F, n_steps: int = 4, **kw) -> np.ndarray:
    """Tip position (x, y), m, of an n-element cantilever under the dead tip force
    F = (Fx, Fy), N (Model 1 section and material unless kw say otherwise)."""
    m, q0, asm, elim = cantilever(n, **kw)
    tip = [m.dof(n, "r", 0), m.dof(n, "r", 1)]
    Qk = np.zeros(m.n_dofs)
    Qk[tip] = F
    res = solve_static(asm, elim, Qk, q0, NewtonOptions(n_steps=n_steps, rtol=1e-10))
    if not res.converged:
        return np.full(2, np.nan)
    return res.q[tip]
