"""Chrono's static ANCF beam checks as our own model: a straight clamped beam of n equal
``ancf3243`` or ``ancf3333`` elements along x, Newton's static solve, the tip frame.

Mesh (Project Chrono's ``utest_FEA_ANCFbeam_{3243,3333}_Formulation.cpp``): the beam of
length L (m) from x = 0 to x = L with the section H (m, along y) x W (m, along z), n
elements of length L/n sharing their end nodes; 3243: nodes 0..n at x_i = i L/n, 12
coordinates each [r, r_x, r_y, r_z]; 3333: nodes 0..2n at x_i = i L/(2n) (the element k
takes A = 2k, B = 2k + 2 and its central node C = 2k + 1, in the module's order A, B, C),
9 coordinates each [r, r_y, r_z].  The clamp fixes every coordinate of node 0.

Equilibrium (N; N m on gradient entries):

    R(e) = Q(e) - F = 0,   Q = sum_k A_k^T Q_k(A_k e),   K = dQ/de = sum_k A_k^T K_k A_k   (1)

with A_k the element's selection of the global coordinates, Q_k and K_k the elements'
``internal_force`` and ``internal_force_jacobians`` (no velocity, no damping).  External
forces F (all dead loads, assembled once at the reference, as Chrono's ``DoStaticLinear``
assembles them at its initial state):

    gravity   F = sum_k A_k^T int_V rho S^T g dV                       (2)
    tip force F = S(xi=1, 0, 0)^T f        (the last element's node B position, f in N)
    tip moment F_a = 1/2 m x grad_r s_a    for every shape function a   (3)

Eq. (3): the work of the moment m (N m) on the spin at the tip, m . dtheta with dtheta =
1/2 curl du = 1/2 sum_a grad_r s_a x de_a (Recuero et al. 2016, as Chrono's ``ComputeNF``
uses it); grad_r s_a = (ds_a/dxi) J^-1 with J = dr/dxi (3, 3) on the axis at xi = 1.
Newton: e <- e - K_ff^-1 R_f on the free coordinates until |R_f| <= rtol |F_f| (or the
round-off floor of Q, see ``solve_static``).

Tip frame (Chrono's ``EvaluateSectionFrame`` and ``GetCardanAnglesXYZ``): X along r_x,
Z = X x r_y, Y = Z x X (normalised) at xi = 1 on the axis; R = [X Y Z] = Rz(c) Ry(b) Rx(a)
gives the angles (a, b, c) = (atan2(R_21, R_22), -asin(R_20), atan2(R_10, R_00)) in rad.
"""
from __future__ import annotations

import warnings
from dataclasses import dataclass, field
from functools import lru_cache

import numpy as np

from ancf.core.assembly import Assembly, ElementGroup
from ancf.core.mesh import BeamMesh
from ancf.core.quadrature import RectangularSection
from ancf.elements import ancf3243, ancf3333
from ancf.elements import continuum3d as c3

#: element name -> (module, nodes per element as offsets from its first node, node stride)
ELEMENTS = {"3243": (ancf3243, (0, 1), 1), "3333": (ancf3333, (0, 2, 1), 2)}


@dataclass(frozen=True, kw_only=True)
class Beam:
    """The clamped beam: element name ("3243" or "3333"), n elements, length L (m), section
    H (m, along y) x W (m, along z), density rho (kg/m^3), Young's modulus E (Pa), Poisson's
    ratio nu and the shear corrections k1, k2 (dimensionless); naxis the Gauss points along
    the axis (None: the module's exact ``NAXIS``; Chrono's elements take ``NP`` = 3, at
    least 2)."""

    element: str
    n: int
    L: float
    H: float
    W: float
    rho: float
    E: float
    nu: float
    k1: float
    k2: float
    naxis: int | None = None
    module: object = field(init=False, repr=False)

    def __post_init__(self):
        object.__setattr__(self, "module", ELEMENTS[self.element][0])

    @property
    def Le(self) -> float:
        """Element length L/n, m."""
        return self.L / self.n

    @property
    def ncoord(self) -> int:
        """Coordinates per node (12 for 3243, 9 for 3333)."""
        return self.module.NDOF // len(ELEMENTS[self.element][1])

    @property
    def nnode(self) -> int:
        return self.n * ELEMENTS[self.element][2] + 1

    def dofs(self, k: int) -> np.ndarray:
        """A_k as indices: element k's coordinates in the global vector, module order."""
        _, offsets, stride = ELEMENTS[self.element]
        nodes = [stride * k + o for o in offsets]
        return np.concatenate([np.arange(i * self.ncoord, (i + 1) * self.ncoord) for i in nodes])

    def reference(self) -> np.ndarray:
        """e0 (nnode * ncoord,): the straight beam, node positions x_i = i L/(nnode - 1) (m),
        gradients as the module's reference element."""
        node = self.module.reference_coordinates(self.Le)[:self.ncoord]
        e = np.tile(node, self.nnode)
        e[::self.ncoord] = np.linspace(0.0, self.L, self.nnode)
        return e

    def free(self) -> np.ndarray:
        """Indices of the free coordinates: all but node 0's (the clamp)."""
        return np.arange(self.ncoord, self.nnode * self.ncoord)

    def element_args(self):
        return (self.Le, self.H, self.W, self.E, self.nu, self.k1, self.k2)


@lru_cache(maxsize=16)
def _kernel(module, args: tuple, naxis: int | None = None):
    """(e0 (m,) in m, parts): the element's reference and ``continuum3d`` parts, computed
    once per element, dimensions ``args`` (``Beam.element_args``) and axial rule ``naxis``
    (None: the module's exact rule)."""
    basis, rules = module.continuum(*args, naxis=module.NAXIS if naxis is None else naxis)
    return basis.e0, c3.parts(basis, rules)


def assemble(beam: Beam, e: np.ndarray):
    """(Q, K) of eq. (1) at the global state e (m): Q in N, K in N/m (all elements in one
    ``continuum3d.static_batch``, the same sums as the element's ``internal_force`` and
    ``internal_force_jacobians``)."""
    e0, parts = _kernel(beam.module, beam.element_args(), beam.naxis)
    d = np.array([beam.dofs(k) for k in range(beam.n)])
    Qk, Kk = c3.static_batch(e[d] - e0, parts)
    Q, K = np.zeros(e.size), np.zeros((e.size, e.size))
    np.add.at(Q, d, Qk)
    np.add.at(K, (d[:, :, None], d[:, None, :]), Kk)
    return Q, K


def gravity(beam: Beam, g) -> np.ndarray:
    """The consistent gravity force of eq. (2) (N), for the acceleration g (3,) in m/s^2."""
    F = np.zeros(beam.nnode * beam.ncoord)
    q = beam.module.gravity(beam.Le, beam.H, beam.W, beam.rho, g)
    for k in range(beam.n):
        F[beam.dofs(k)] += q
    return F


def _tip(beam: Beam, e: np.ndarray):
    """(s (nshape,), ds/dxi (nshape, 3), e_bar (nshape, 3)) of the last element at
    (xi, eta, zeta) = (1, 0, 0), e_bar its coordinates as rows of 3."""
    m, args = beam.module, (1.0, 0.0, 0.0, beam.Le, beam.H, beam.W)
    return m.scalar_shape(*args), m.natural_gradient(*args), e[beam.dofs(beam.n - 1)].reshape(-1, 3)


def tip_load(beam: Beam, force=(0.0, 0.0, 0.0), moment=(0.0, 0.0, 0.0), e=None) -> np.ndarray:
    """F (N) of a force (N) and a moment (N m), global axes, at the tip (eq. (3)), evaluated
    at the state e (default the reference)."""
    e = beam.reference() if e is None else e
    s, ds, ebar = _tip(beam, e)
    grad = ds @ np.linalg.inv(ebar.T @ ds)          # grad_r s_a (nshape, 3), 1/m or -
    Fe = np.outer(s, force) + 0.5 * np.cross(np.asarray(moment, dtype=float), grad)
    F = np.zeros(beam.nnode * beam.ncoord)
    F[beam.dofs(beam.n - 1)] = Fe.ravel()
    return F


@dataclass(frozen=True)
class Solution:
    """Newton's answer: the state e (m), iterations, the final |R_f| / |F_f| (residual),
    the round-off floor |Q_f(e0)| / |F_f| (floor; Q(e0) = 0 in exact arithmetic) and
    converged (residual <= rtol)."""

    e: np.ndarray
    iterations: int
    residual: float
    floor: float
    converged: bool


def solve_static(beam: Beam, F: np.ndarray, rtol: float = 1e-10, maxiter: int = 30,
                 floor_factor: float = 10.0, start: np.ndarray | None = None) -> Solution:
    """Newton on eq. (1) from ``start`` (m; default the reference, e.g. the previous load
    step's state) until |R_f| <= rtol |F_f| on the free coordinates, or, earlier, until
    |R_f| <= floor_factor |Q_f(e0)|: the round-off of Q (cancellation in E eps over the
    section, ~1e-8 N for Chrono's aluminium beams) is larger than 1e-10 |F| for loads of a
    few N, and then converged=False says that the solve stopped at the round-off floor.
    Warns if maxiter iterations do not reach either."""
    e0, f = beam.reference(), beam.free()
    scale = np.linalg.norm(F[f])
    floor = np.linalg.norm(assemble(beam, e0)[0][f]) / scale
    e = e0 if start is None else np.array(start, dtype=float)
    for it in range(maxiter + 1):
        Q, K = assemble(beam, e)
        r = Q[f] - F[f]
        res = np.linalg.norm(r) / scale
        if res <= max(rtol, floor_factor * floor):
            return Solution(e, it, res, floor, bool(res <= rtol))
        if it < maxiter:
            e[f] -= np.linalg.solve(K[np.ix_(f, f)], r)
    warnings.warn(f"chrono_beam: Newton stopped at {maxiter} iterations, residual {res:.2e}")
    return Solution(e, maxiter, res, floor, False)


def tip_frame(beam: Beam, e: np.ndarray):
    """(point (3,) in m, R (3, 3)) of the tip section (module docstring, Chrono's frame)."""
    s, ds, ebar = _tip(beam, e)
    tangent, guide = ebar.T @ ds[:, 0], ebar.T @ ds[:, 1]
    X = tangent / np.linalg.norm(tangent)
    Z = np.cross(X, guide)
    Z /= np.linalg.norm(Z)
    return ebar.T @ s, np.column_stack([X, np.cross(Z, X), Z])


def cardan_xyz(R: np.ndarray) -> np.ndarray:
    """Chrono's Cardan angles (a, b, c) in rad of R = Rz(c) Ry(b) Rx(a)."""
    return np.array([np.arctan2(R[2, 1], R[2, 2]), -np.arcsin(np.clip(R[2, 0], -1, 1)),
                     np.arctan2(R[1, 0], R[0, 0])])


def quadratic_model(p: dict, cls, kw: dict):
    """(mesh, q0, assembly) of the beam scenes (``beam3d-cantilever``) with a 3-node element
    class ``cls`` (``ancf3333``'s registry class, keyword arguments ``kw``): the mesh above,
    a :class:`~ancf.core.mesh.BeamMesh` of 2n segments (nodes at x_i = i L/(2n), slots
    r, r_y, r_z, the tip its last node), element k on the nodes A, B, C = 2k, 2k + 2,
    2k + 1.  p: L, n_elements, b (z), h (y), E, nu (Pa, -), rho (kg/m^3, default 0)."""
    n = p["n_elements"]
    m = BeamMesh(p["L"], 2 * n, cls.slots, dim=3)
    q0 = m.reference()
    k = np.arange(n)
    nodes = np.stack([2 * k, 2 * k + 2, 2 * k + 1], axis=1)
    dofmap = m.block.start + (nodes[:, :, None] * m.per_node + np.arange(m.per_node))
    dofmap = dofmap.reshape(n, -1)
    el = cls(np.full(n, p["L"] / n), q0[dofmap], RectangularSection(p["b"], p["h"]), p["E"],
             p["nu"], rho=p.get("rho", 0.0), **kw)
    return m, q0, Assembly(m.n_dofs, [ElementGroup(el, dofmap)])
