"""The ANCF 3843 brick element: shape functions, consistent mass, gravity force.

A rectangular brick of edge lengths Lx, Ly, Lz (m, along x, y, z): 8 corner
nodes, each carrying the position r and the three gradients r_x, r_y, r_z (the
fully parameterised 8-node solid of Olshevskiy, Dmitrochenko & Milkie 2014,
"Three-dimensional solid brick element using slopes in the absolute nodal
coordinate formulation", J. Comput. Nonlinear Dyn. 9, 021001; Project Chrono's
``ChElementHexaANCF_3843``, whose ``SetDimensions(lenX, lenY, lenZ)`` are our
(Lx, Ly, Lz)).  3 dimensions x 4 vectors x 8 nodes = 96 coordinates.

Reference (natural) coordinates xi, eta, zeta in [-1, 1], with
x = Lx (1 + xi)/2, y = Ly (1 + eta)/2, z = Lz (1 + zeta)/2 in the undeformed
box.  The nodes are the corners, in Chrono's order A..H with the signs
(a, b, c) of (xi, eta, zeta):

    A (-,-,-)  B (+,-,-)  C (+,+,-)  D (-,+,-)
    E (-,-,+)  F (+,-,+)  G (+,+,+)  H (-,+,+)

Coordinates e (96,), node by node, per node ``[r, r_x, r_y, r_z]``, each (x, y, z);
compact index (over the 32 scalar shape functions) = 4 * node + (0: r, 1: r_x,
2: r_y, 3: r_z) and e-index = 3 * compact + component.

The position is r = S e with S = [s_1 I_3, ..., s_32 I_3] (3, 96).  At the node
with signs (a, b, c) put X = a xi, Y = b eta, Z = c zeta (each 1 at that node,
-1 on the opposite faces).  With the trilinear bubble P = (1+X)(1+Y)(1+Z)/8
the node's four scalar shape functions are

    s_r = P [1 + (X (1-X) + Y (1-Y) + Z (1-Z)) / 2]                        (1)
    s_x = a (Lx/2) P (1+X)(X-1)/2                                           (2)
    s_y = b (Ly/2) P (1+Y)(Y-1)/2                                           (3)
    s_z = c (Lz/2) P (1+Z)(Z-1)/2                                           (4)

(1) is 1 at its node, 0 at the others, and has zero x, y, z slopes at all
nodes; (2)-(4) vanish at every node and have unit slope d/dx, d/dy, d/dz
respectively at their own node only (d/dx = (2/Lx) d/dxi).  Each is cubic
in each natural coordinate.  Equations:

    M   = int_V rho S^T S dV        (96, 96), kg (kg m, kg m^2 on gradient entries)   (5)
    Q_g = int_V rho S^T g dV        (96,),   N  (N m on gradient entries)             (6)

with dV = (Lx Ly Lz / 8) dxi deta dzeta (``continuum3d`` eqs. (1)-(3)), by tensor
Gauss-Legendre quadrature.
s_i s_j has degree <= 6 in each natural coordinate, so ``ngauss >= 4`` points per
direction integrate (5) exactly; s_i has degree <= 3, so 2 points integrate (6)
exactly.  M = m (x) I_3 with the compact m (32, 32) over the scalar functions.
"""
from __future__ import annotations

import numpy as np

from . import continuum3d as c3
from .material import isotropic_3d as elasticity  # noqa: F401 (Chrono's ChMaterialHexaANCF)

NNODE = 8
NSHAPE = 32  # scalar shape functions, 4 per node
NDOF = 96    # 3 * NSHAPE coordinates

#: Signs (a, b, c) of (xi, eta, zeta) at nodes A..H (Chrono's node order).
NODE_SIGNS = np.array([
    (-1, -1, -1), (1, -1, -1), (1, 1, -1), (-1, 1, -1),
    (-1, -1, 1), (1, -1, 1), (1, 1, 1), (-1, 1, 1),
], dtype=float)


def scalar_shape(xi, eta, zeta, Lx: float, Ly: float, Lz: float) -> np.ndarray:
    """The 32 scalar shape functions, eqs. (1)-(4), at natural coordinates
    xi, eta, zeta in [-1, 1] (arrays broadcast); result (..., 32), ordered
    node by node [s_r, s_x, s_y, s_z].  s_r is dimensionless; s_x, s_y, s_z
    are in m (they multiply a dimensionless gradient)."""
    xi, eta, zeta = np.broadcast_arrays(*(np.asarray(v, dtype=float) for v in (xi, eta, zeta)))
    half = (0.5 * Lx, 0.5 * Ly, 0.5 * Lz)
    cols = []
    for signs in NODE_SIGNS:
        X, Y, Z = (s * v for s, v in zip(signs, (xi, eta, zeta)))
        P = (1.0 + X) * (1.0 + Y) * (1.0 + Z) / 8.0
        cols.append(P * (1.0 + 0.5 * (X * (1.0 - X) + Y * (1.0 - Y) + Z * (1.0 - Z))))
        for s, h, U in zip(signs, half, (X, Y, Z)):
            cols.append(s * h * P * 0.5 * (1.0 + U) * (U - 1.0))
    return np.stack(cols, axis=-1)


def shape(xi: float, eta: float, zeta: float, Lx: float, Ly: float, Lz: float) -> np.ndarray:
    """The shape-function matrix S (3, 96) at one point: S = [s_1 I_3, ..., s_32 I_3],
    so that r(xi, eta, zeta) = S e with e ordered as in the module docstring."""
    s = scalar_shape(xi, eta, zeta, Lx, Ly, Lz)
    return np.kron(s.reshape(1, NSHAPE), np.eye(3))


def natural_gradient(xi, eta, zeta, Lx: float, Ly: float, Lz: float) -> np.ndarray:
    """ds_a/d(xi, eta, zeta) (..., 32, 3): the derivatives of eqs. (1)-(4) in the
    natural coordinates, dimensionless for s_r, m for s_x, s_y, s_z."""
    xi, eta, zeta = np.broadcast_arrays(*(np.asarray(v, dtype=float) for v in (xi, eta, zeta)))
    half = np.array([0.5 * Lx, 0.5 * Ly, 0.5 * Lz])
    rows = []
    for signs in NODE_SIGNS:
        U = [s * v for s, v in zip(signs, (xi, eta, zeta))]             # X, Y, Z
        p = [1.0 + u for u in U]
        P = p[0] * p[1] * p[2] / 8.0
        dP = [p[1] * p[2] / 8.0, p[0] * p[2] / 8.0, p[0] * p[1] / 8.0]  # dP/dU_J
        g = 1.0 + 0.5 * sum(u * (1.0 - u) for u in U)
        rows.append([(dP[J] * g + P * (0.5 - U[J])) * signs[J] for J in range(3)])
        for k in range(3):
            h = 0.5 * (U[k] ** 2 - 1.0)
            rows.append([signs[k] * half[k] * (dP[J] * h + (P * U[k] if J == k else 0.0))
                         * signs[J] for J in range(3)])
    return np.stack([np.stack(r, axis=-1) for r in rows], axis=-2)


def reference_coordinates(Lx: float, Ly: float, Lz: float) -> np.ndarray:
    """e0 (96,): node positions at the box corners (0..Lx, 0..Ly, 0..Lz) m, gradients = I."""
    corners = (1.0 + NODE_SIGNS) / 2.0 * np.array([Lx, Ly, Lz])
    return np.concatenate([np.concatenate([c, np.eye(3).ravel()]) for c in corners])


def basis(Lx: float, Ly: float, Lz: float) -> c3.Basis:
    """The element's basis for ``continuum3d`` (natural points (xi, eta, zeta))."""
    return c3.Basis(lambda p: scalar_shape(*p.T, Lx, Ly, Lz),
                    lambda p: natural_gradient(*p.T, Lx, Ly, Lz),
                    reference_coordinates(Lx, Ly, Lz))


def shape_gradient(xi, eta, zeta, Lx: float, Ly: float, Lz: float) -> np.ndarray:
    """G_aJ = ds_a/dX_J (..., 32, 3): the derivatives of eqs. (1)-(4) with respect to
    X = (x, y, z), 1/m for s_r, dimensionless for s_x, s_y, s_z (``continuum3d`` eq. (2))."""
    return c3.physical_gradient(natural_gradient(xi, eta, zeta, Lx, Ly, Lz),
                                reference_coordinates(Lx, Ly, Lz))[0]


def rule(ngauss: int):
    """Tensor Gauss-Legendre rule on [-1, 1]^3: points (nq, 3) and weights summing to 8."""
    return c3.gauss_box((ngauss,) * 3, (-1.0,) * 3, (1.0,) * 3)


def scalar_mass(Lx: float, Ly: float, Lz: float, rho: float, ngauss: int = 4) -> np.ndarray:
    """The compact mass m_ij = int_V rho s_i s_j dV (32, 32), kg (times m per gradient
    index); M = m (x) I_3, eq. (5).  Exact for ``ngauss >= 4``."""
    return c3.scalar_mass(basis(Lx, Ly, Lz), [(rho, *rule(ngauss))])


def mass_matrix(Lx: float, Ly: float, Lz: float, rho: float, ngauss: int = 4) -> np.ndarray:
    """The consistent mass matrix M = int_V rho S^T S dV (96, 96), eq. (5), by
    ``ngauss`` Gauss points per direction (exact for ngauss >= 4); lengths in m,
    rho in kg/m^3."""
    return np.kron(scalar_mass(Lx, Ly, Lz, rho, ngauss), np.eye(3))


def gravity(Lx: float, Ly: float, Lz: float, rho: float, g, ngauss: int = 2) -> np.ndarray:
    """The generalised gravity force Q_g = int_V rho S^T g dV (96,), eq. (6), N (N m
    on the gradient entries), for the acceleration g (3,) in m/s^2, e.g.
    (0, 0, -9.80665).  Exact for ngauss >= 2."""
    return c3.gravity(basis(Lx, Ly, Lz), [(rho, *rule(ngauss))], g)


# ----------------------------------------------------------------------------------------
# Internal force: ``continuum3d`` eqs. (4)-(10) (Green-Lagrange strain, Kelvin-Voigt
# stress sigma = D (eps + alpha eps'), Q = int B^T sigma dV, exact K and R) with the
# isotropic law of Chrono's ChMaterialHexaANCF over the whole volume (no Poisson split).
# Degrees: s_a is cubic per direction, so F is cubic, eps of degree 6 and the integrands
# of Q, K, R of degree 12 in each natural coordinate: 7 Gauss points per direction
# integrate them exactly.  Chrono's element uses 4 (its header NP); its stored reference
# data are exact.  Chrono's ComputeInternalForces returns -Q.
# ----------------------------------------------------------------------------------------

NEXACT = 7   # exact Gauss points per direction for Q, K, R


def continuum(Lx, Ly, Lz, E, nu, *, ngauss=NEXACT):
    """(basis, rules) of ``continuum3d`` for ``internal_force`` (same arguments
    after e, edot; no alpha): the element's basis and its constitutive parts."""
    return basis(Lx, Ly, Lz), [(elasticity(E, nu), *rule(ngauss))]


def internal_force(e, edot, Lx, Ly, Lz, E, nu, alpha=0.0, *, ngauss=NEXACT) -> np.ndarray:
    """The generalised internal force Q(e, e') (96,), N (N m on gradient
    entries): e (96,) in m, edot (96,) in m/s, Lx, Ly, Lz in m, E in Pa, nu dimensionless,
    alpha in s (Kelvin-Voigt).  Exact for ngauss >= 7; Chrono's ``ComputeInternalForces``
    stores -Q."""
    kernel = continuum(Lx, Ly, Lz, E, nu, ngauss=ngauss)
    return c3.internal_force(e, edot, *kernel, alpha)


def internal_force_jacobians(e, edot, Lx, Ly, Lz, E, nu, alpha=0.0, *, ngauss=NEXACT):
    """(K, R) = (dQ/de in N/m, dQ/de' in N s/m), each (96, 96), of ``internal_force``
    (same arguments); Chrono's ``ComputeKRMmatricesGlobal(H, 1, 0, 0)``
    and ``(H, 0, 1, 0)``."""
    kernel = continuum(Lx, Ly, Lz, E, nu, ngauss=ngauss)
    return c3.internal_force_jacobians(e, edot, *kernel, alpha)
