"""Supported thin-plate models (``plate36`` on a :class:`~ancf.models.plate_mesh.PlateMesh`),
shared by the scenes ``plate-square`` and ``plate-strip``, the tests and the report.

* :func:`simply_supported_centre`: the simply supported rectangle under uniform pressure,
  a linear (small-deflection) solve at the flat reference with a sparse direct solver.
  In-plane coordinates are fixed (at the flat reference the membrane and bending
  problems decouple), ``w = 0`` and the slope along the edge (``dw/dy`` on x = 0, a;
  ``dw/dx`` on y = 0, b) vanish on the boundary.
* :func:`edge_load`: consistent forces of an end load spread uniformly over the edge x = a.
* :func:`strip_linear_tip` / :func:`strip_model`: the strip clamped at x = 0 (``r``,
  ``r_x`` and ``r_y`` of every root node, all three components).
* :func:`simply_supported_model`: the simply supported rectangle for a nonlinear solve
  or its modes; :func:`grid_points`: the mid surface's nodes of a coordinate vector.

A density ``rho`` (kg/m^3) gives the elements their mass (default 0: statics).
"""
from __future__ import annotations

import numpy as np
import scipy.sparse.linalg as sla

from ancf.core.assembly import Assembly, ElementGroup
from ancf.core.constraints import Elimination
from ancf.elements.basis import plate36_S
from ancf.elements.plate36 import Plate36
from ancf.models.plate_mesh import SLOTS, PlateMesh
from ancf.core.quadrature import gauss01


def assembly(m: PlateMesh, h: float, E: float, nu: float, ng: int = 4,
             rho: float = 0.0) -> Assembly:
    """One group of bending plate elements over the mesh."""
    return Assembly(m.n_dofs, [ElementGroup(Plate36(m.lengths, m.widths, h=h, E=E, nu=nu,
                                                    rho=rho, ng=ng), m.dofmap)])


def _linear_solve(m: PlateMesh, asm: Assembly, fixed: set, f: np.ndarray) -> np.ndarray:
    """Displacements (n_dofs,) of K u = f at the flat reference, ``fixed`` coordinates zero."""
    _, K = asm.gradient_tangent(m.reference())
    free = np.setdiff1d(np.arange(m.n_dofs), sorted(fixed))
    u = np.zeros(m.n_dofs)
    u[free] = sla.spsolve(K[free][:, free].tocsc(), f[free])
    return u


def in_plane(m: PlateMesh) -> set:
    """The x and y components of every nodal coordinate."""
    return {m.dof(k, s, c) for k in range(m.n_nodes) for s in SLOTS for c in (0, 1)}


def simply_supported_centre(n: int, a: float, b: float, h: float, E: float, nu: float,
                            p: float, ng: int = 4) -> float:
    """Centre deflection (m, along +z = along a positive pressure p, Pa) of an n x n mesh
    (n even) of the simply supported a x b plate."""
    m, u = simply_supported(n, a, b, h, E, nu, p, ng)
    return float(u[m.dof(m.node(n // 2, n // 2), "r", 2)])


def simply_supported(n: int, a: float, b: float, h: float, E: float, nu: float,
                     p: float, ng: int = 4) -> tuple:
    """(mesh, displacements u (n_dofs,) from the flat reference) of an n x n mesh of the
    simply supported a x b plate under the pressure p (Pa, along +z)."""
    m = PlateMesh(a, b, n, n)
    return m, _linear_solve(m, assembly(m, h, E, nu, ng), _supports(m), m.pressure_load(p))


def _supports(m: PlateMesh) -> set:
    """The simply supported plate's fixed coordinates: in-plane ones, w and the slope
    along the edge on the boundary."""
    fixed = in_plane(m)
    for k in range(m.n_nodes):
        on_x, on_y = m.X[k] in (0.0, m.a), m.Y[k] in (0.0, m.b)
        fixed |= {m.dof(k, "r", 2)} if on_x or on_y else set()
        fixed |= {m.dof(k, "r_y", 2)} if on_x else set()
        fixed |= {m.dof(k, "r_x", 2)} if on_y else set()
    return fixed


def simply_supported_model(n: int, a: float, b: float, h: float, E: float, nu: float,
                           p: float, ng: int = 4, rho: float = 0.0):
    """(mesh, q0, assembly, elimination, load vector) of the n x n simply supported plate
    under the pressure p (Pa, along +z) for a nonlinear solve or its modes."""
    m = PlateMesh(a, b, n, n)
    q0 = m.reference()
    fixed = sorted(_supports(m))
    return (m, q0, assembly(m, h, E, nu, ng, rho), Elimination(m.n_dofs).fix(fixed, q0[fixed]),
            m.pressure_load(p))


def edge_load(m: PlateMesh, P: float) -> np.ndarray:
    """Consistent forces (n_dofs,) of the end load P (N, along +z) spread uniformly over
    the edge x = a (2-point Gauss rule along y: exact for the cubic shape functions)."""
    t, w = gauss01(2)
    a, b = m.lengths[0], m.widths[0]
    fe = P / m.b * b * (w @ plate36_S(np.full(2, a), t * b, a, b))
    f = np.zeros(m.n_dofs)
    np.add.at(f, m.dofmap[m.nx - 1::m.nx, 2::3], np.broadcast_to(fe, (m.ny, 12)))
    return f


def root(m: PlateMesh) -> list:
    """Every coordinate (r, r_x, r_y; x, y, z) of the nodes at x = 0."""
    return [m.dof(k, s, c) for k in range(m.n_nodes) if m.X[k] == 0.0 for s in SLOTS
            for c in range(3)]


def tip_nodes(m: PlateMesh) -> list:
    """The nodes of the edge x = a."""
    return [m.node(m.nx, j) for j in range(m.ny + 1)]


def strip_linear_tip(nx: int, ny: int, L: float, b: float, h: float, E: float, nu: float,
                     P: float) -> float:
    """Mean tip deflection (m, along +z) of the clamped strip L x b under the end load P
    (N, along +z), linear solve at the reference."""
    m = PlateMesh(L, b, nx, ny)
    u = _linear_solve(m, assembly(m, h, E, nu), in_plane(m) | set(root(m)), edge_load(m, P))
    return float(np.mean([u[m.dof(k, "r", 2)] for k in tip_nodes(m)]))


def strip_model(nx: int, ny: int, L: float, b: float, h: float, E: float, nu: float,
                ng: int = 4, rho: float = 0.0):
    """(mesh, q0, assembly, elimination) of the clamped strip for a nonlinear solve."""
    m = PlateMesh(L, b, nx, ny)
    q0 = m.reference()
    fixed = root(m)
    return m, q0, assembly(m, h, E, nu, ng, rho), Elimination(m.n_dofs).fix(fixed, q0[fixed])


def tip_mean(m: PlateMesh, q: np.ndarray) -> dict:
    """{tip_x, tip_y, tip_z}: the mean position (m) of the nodes of the edge x = a."""
    tips = tip_nodes(m)
    return {f"tip_{c}": float(np.mean([q[m.dof(k, "r", i)] for k in tips]))
            for i, c in enumerate("xyz")}


def grid_points(m: PlateMesh):
    """Global coordinates -> positions r (n_nodes, 3) of the mesh's nodes, m."""
    idx = np.array([[m.dof(k, "r", c) for c in range(3)] for k in range(m.n_nodes)])
    return lambda q: np.asarray(q, float)[idx]
