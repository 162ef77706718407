"""Spatial beam models: a straight beam along +x of a 3D element, its supports and a
static solve, shared by the scene ``beam3d-cantilever``, the tests and the report.

:data:`BUILDERS` maps an element name to a function ``p -> element class`` plus
keyword arguments, a view of the element registry (:mod:`ancf.elements.registry`): a
new 3D element is one record there.  The mesh is a
:class:`~ancf.core.mesh.BeamMesh` with ``dim=3`` (reference r = (x, 0, 0), the slopes the
unit vectors of their names).
"""
from __future__ import annotations

import numpy as np

from ancf.core.assembly import Assembly, ElementGroup
from ancf.core.constraints import Elimination
from ancf.core.forces import Forces, SectionMoment
from ancf.elements.registry import ELEMENTS
from ancf.core.mesh import BeamMesh
from ancf.core.quadrature import RectangularSection
from ancf.solvers.static import NewtonOptions, solve_static


#: element name -> (p -> (element class, extra keyword arguments)): the registry's 3D
#: elements of a two-node (beam) mesh with a section's three directions (not the cable)
BUILDERS = {name: t.build for name, t in ELEMENTS.items()
            if t.dim == 3 and t.nodes == 2 and t.kind != "cable"}


def model(p: dict):
    """(mesh, q0, assembly) for the resolved parameters p (L, n_elements, b, h, E, nu,
    element and the element's own parameters; rho optional, default 0)."""
    cls, kw = BUILDERS[p.get("element", "linear3d")](p)
    m = BeamMesh(p["L"], p["n_elements"], cls.slots, dim=3)
    q0 = m.reference()
    el = cls(m.lengths, q0[m.dofmap], RectangularSection(p["b"], p["h"]), p["E"], p["nu"],
             rho=p.get("rho", 0.0), **kw)
    return m, q0, Assembly(m.n_dofs, [ElementGroup(el, m.dofmap)])


def clamp(m: BeamMesh) -> list:
    """Every slot of the first node but r_x (if the element has it), all components:
    position and the section's orientation, as the planar cantilever's clamp."""
    return [(0, s, k) for s in m.slots if s != "r_x" for k in range(3)]


def pins(m: BeamMesh) -> list:
    """The planar simply supported beam's supports (x, y of the first node, y of the
    last) in both bending planes, and the twist of the first node (z of its r_y)."""
    n = m.n_nodes - 1
    return [(0, "r", 0), (0, "r", 1), (0, "r", 2), (n, "r", 1), (n, "r", 2), (0, "r_y", 2)]


def load_vector(m: BeamMesh, loads: dict) -> np.ndarray:
    """Generalised forces from {(node, slot, component): N}."""
    Qk = np.zeros(m.n_dofs)
    for (node, slot, k), f in loads.items():
        Qk[m.dof(node, slot, k)] += f
    return Qk


def elimination(m: BeamMesh, q0: np.ndarray, supports) -> Elimination:
    """The coordinates [(node, slot, component)] of ``supports`` fixed at the reference."""
    elim = Elimination(m.n_dofs)
    for node, slot, k in supports:
        d = m.dof(node, slot, k)
        elim.fix(d, q0[d])
    return elim


def solve(p: dict, supports, loads: dict, moments=None):
    """(static result, mesh, q0, assembly) with ``supports`` (mesh -> [(node, slot,
    component)]), ``loads`` and the moment terms ``moments`` (mesh -> Forces or None, as
    :func:`tip_moment`); Newton options from p (load_steps, rtol, max_iterations)."""
    m, q0, asm = model(p)
    res = solve_static(asm, elimination(m, q0, supports(m)), load_vector(m, loads), q0,
                       NewtonOptions(n_steps=p["load_steps"], rtol=p["rtol"],
                                     max_iter=p["max_iterations"]),
                       forces=moments(m) if moments else None)
    return res, m, q0, asm


def torsion_constant_rectangle(h: float, b: float, terms: int = 50) -> float:
    """St-Venant's J of an h x b rectangle, m^4, from the series (Timoshenko and Goodier),
    with c >= d its long and short sides:
    J = c d^3/3 (1 - 192/pi^5 (d/c) sum_{n odd} tanh(n pi c/(2 d))/n^5)."""
    c, d = max(h, b), min(h, b)
    n = np.arange(1, 2 * terms, 2)
    return c * d**3 / 3.0 * (1.0 - 192.0 / np.pi**5 * d / c
                             * np.sum(np.tanh(n * np.pi * c / (2.0 * d)) / n**5))


def torsion_constant_square(a: float, terms: int = 50) -> float:
    """St-Venant's J of a square of side a, m^4 (0.1406 a^4)."""
    return torsion_constant_rectangle(a, a, terms)


def torsion_factor(h: float, b: float) -> float:
    """k_s = J/(I_y + I_z) (-): the shear correction that gives the 3D beams, whose
    torsional stiffness is k_s G (I_y + I_z) (no warping), St-Venant's G J."""
    return float(torsion_constant_rectangle(h, b) / (b * h * (h * h + b * b) / 12.0))


def tip_load(p: dict) -> dict:
    """The tip force F (N) at ``load_angle_deg`` in the section plane, from -y towards -z
    for a negative F: F (0, cos a, sin a) on r of the last node."""
    a = np.radians(p["load_angle_deg"])
    n = p["n_elements"]
    return {(n, "r", 1): p["F"] * float(np.cos(a)), (n, "r", 2): p["F"] * float(np.sin(a))}


def tip_moment(m: BeamMesh, p: dict):
    """The tip moment (``Mx``, ``My``, ``Mz`` of p, N m, fixed global axes) on the section
    slopes r_y, r_z of the last node, weighted by the section's int y^2 dA, int z^2 dA
    (:class:`~ancf.core.forces.SectionMoment`), as a :class:`~ancf.core.forces.Forces`;
    None when all three are zero."""
    M = [float(p.get(k, 0.0)) for k in ("Mx", "My", "Mz")]
    if not any(M):
        return None
    n = m.n_nodes - 1
    dofs = [m.dof(n, s, k) for s in ("r_y", "r_z") for k in range(3)]
    moments = RectangularSection(p["b"], p["h"]).moments_yz()
    return Forces(m.n_dofs, [SectionMoment(m.n_dofs, dofs, M, (moments["Q2_0"],
                                                                moments["Q0_2"]))])
