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

with dV = (Lx Ly Lz / 8) dxi deta dzeta, by tensor Gauss-Legendre quadrature.
s_i s_j has degree <= 6 in each natural coordinate, so ``ngauss >= 4`` points per
direction integrate (5) exactly; s_i has degree <= 3, so 2 points integrate (6)
exactly.  M = m (x) I_3 with the compact m (32, 32) over the scalar functions.
"""
from __future__ import annotations

import numpy as np

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


def _points(ngauss: int):
    """Tensor Gauss-Legendre rule on [-1, 1]^3: coordinates xi, eta, zeta (nq,) and
    weights w (nq,) summing to 8 (the natural volume)."""
    t, w = np.polynomial.legendre.leggauss(ngauss)
    XI, ET, ZE = np.meshgrid(t, t, t, indexing="ij")
    WW = w[:, None, None] * w[None, :, None] * w[None, None, :]
    return XI.ravel(), ET.ravel(), ZE.ravel(), WW.ravel()


def scalar_mass(Lx: float, Ly: float, Lz: float, rho: float, ngauss: int = 4) -> np.ndarray:
    """The compact mass m_ij = int_V rho s_i s_j dV (32, 32), kg (times m per gradient
    index); M = m (x) I_3, eq. (5).  Exact for ``ngauss >= 4``."""
    xi, eta, zeta, w = _points(ngauss)
    s = scalar_shape(xi, eta, zeta, Lx, Ly, Lz)
    return rho * (Lx * Ly * Lz / 8.0) * np.einsum("q,qi,qj->ij", w, s, s)


def mass_matrix(Lx: float, Ly: float, Lz: float, rho: float, ngauss: int = 4) -> np.ndarray:
    """The consistent mass matrix M = int_V rho S^T S dV (96, 96), eq. (5), by
    ``ngauss`` Gauss points per direction (exact for ngauss >= 4); lengths in m,
    rho in kg/m^3."""
    return np.kron(scalar_mass(Lx, Ly, Lz, rho, ngauss), np.eye(3))


def gravity(Lx: float, Ly: float, Lz: float, rho: float, g, ngauss: int = 2) -> np.ndarray:
    """The generalised gravity force Q_g = int_V rho S^T g dV (96,), eq. (6), N (N m
    on the gradient entries), for the acceleration g (3,) in m/s^2, e.g.
    (0, 0, -9.80665).  Exact for ngauss >= 2."""
    xi, eta, zeta, w = _points(ngauss)
    s = scalar_shape(xi, eta, zeta, Lx, Ly, Lz)
    sbar = rho * (Lx * Ly * Lz / 8.0) * (w @ s)          # int rho s_i dV, (32,)
    return np.kron(sbar, np.asarray(g, dtype=float).reshape(3))
