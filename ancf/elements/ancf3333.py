"""The ANCF 3333 beam element: shape functions, consistent mass, gravity force.

A straight 3D beam of length L (m, along x), with a rectangular cross-section of
height H (m, along y) and width W (m, along z): 3 nodes, A at x = 0, B at x = L and
the central node C at x = L/2, each carrying the position r and the two section
gradients r_y, r_z (the "gradient deficient" shear-deformable beam of Nachbagauer,
Gruber & Gerstmayr 2013; Project Chrono's ``ChElementBeamANCF_3333``, whose
``SetNodes(A, B, C)`` takes the central node last and whose
``SetDimensions(L, thicknessY, thicknessZ)`` are our (L, H, W)).

Coordinates e (27,), per node ``[r, r_y, r_z]``, each (x, y, z), nodes in the order
A, B, C (Chrono's order, not the geometric one):

    e = [r_A, r_y,A, r_z,A, r_B, r_y,B, r_z,B, r_C, r_y,C, r_z,C]

The position of the material point (x, y, z) is r = S(xi, eta, zeta) e with
S = [s_1 I_3, ..., s_9 I_3] (3, 27) and the scalar shape functions, in the
reference coordinates xi = x/L in [0, 1], eta = y/H and zeta = z/W in [-1/2, 1/2]:

    s_1 = N_A        s_2 = H eta N_A        s_3 = W zeta N_A
    s_4 = N_B        s_5 = H eta N_B        s_6 = W zeta N_B
    s_7 = N_C        s_8 = H eta N_C        s_9 = W zeta N_C

with the quadratic Lagrange polynomials on the nodes xi = 0, 1, 1/2:

    N_A = (1 - xi)(1 - 2 xi),   N_B = xi (2 xi - 1),   N_C = 4 xi (1 - xi)

i.e. r(x, y, z) = r0(x) + y r_y(x) + z r_z(x), the three fields interpolated
quadratically along the axis.  Equations:

    M   = int_V rho S^T S dV        (27, 27), kg (kg m, kg m^2 on gradient entries)
    Q_g = int_V rho S^T g dV        (27,),   N  (N m on gradient entries)

with dV = L H W dxi deta dzeta, evaluated by tensor Gauss-Legendre quadrature.
s_i s_j has degree 4 in xi and 2 in eta, zeta, so ``ngauss >= 3`` points per
direction integrate M exactly; S^T g has degree 2 in xi and 1 in eta, zeta, so
2 points per direction integrate Q_g exactly.
"""
from __future__ import annotations

import numpy as np

NSHAPE = 9   # scalar shape functions
NDOF = 27    # 3 * NSHAPE coordinates
NODE_XI = (0.0, 1.0, 0.5)  # reference axial coordinate of nodes A, B, C


def lagrange(xi) -> np.ndarray:
    """The quadratic Lagrange polynomials (N_A, N_B, N_C) at xi = x/L in [0, 1]
    (nodes at xi = 0, 1, 1/2); dimensionless, result (..., 3)."""
    xi = np.asarray(xi, dtype=float)
    return np.stack([(1.0 - xi) * (1.0 - 2.0 * xi),
                     xi * (2.0 * xi - 1.0),
                     4.0 * xi * (1.0 - xi)], axis=-1)


def scalar_shape(xi, eta, zeta, L: float, H: float, W: float) -> np.ndarray:
    """The 9 scalar shape functions s_1..s_9 (module docstring) at xi = x/L in [0, 1],
    eta = y/H, zeta = z/W in [-1/2, 1/2]; arrays broadcast, result (..., 9).
    s_1, s_4, s_7 are dimensionless; the others in m (times a section gradient).
    L is not used: a Lagrange interpolation carries no axial gradient."""
    xi, eta, zeta = np.broadcast_arrays(*(np.asarray(v, dtype=float) for v in (xi, eta, zeta)))
    n = lagrange(xi)                                        # (..., 3) nodes A, B, C
    section = np.stack([np.ones_like(eta), H * eta, W * zeta], axis=-1)  # (..., 3): 1, y, z
    return (n[..., :, None] * section[..., None, :]).reshape(*xi.shape, NSHAPE)


def shape(xi: float, eta: float, zeta: float, L: float, H: float, W: float) -> np.ndarray:
    """The shape-function matrix S (3, 27) at one point: S = [s_1 I_3, ..., s_9 I_3],
    so that r(xi, eta, zeta) = S e with e ordered per node [r, r_y, r_z], nodes A, B, C."""
    s = scalar_shape(xi, eta, zeta, L, H, W)
    return np.kron(s.reshape(1, NSHAPE), np.eye(3))


def _points(ngauss: int):
    """Tensor Gauss-Legendre rule of ``ngauss`` points per direction: xi on [0, 1],
    eta and zeta on [-1/2, 1/2], and weights w (nq,) summing to 1 (the reference volume)."""
    t, w1 = np.polynomial.legendre.leggauss(ngauss)
    p01, pc, w1 = 0.5 * (t + 1.0), 0.5 * t, 0.5 * w1
    XI, ET, ZE = np.meshgrid(p01, pc, pc, indexing="ij")
    WW = w1[:, None, None] * w1[None, :, None] * w1[None, None, :]
    return XI.ravel(), ET.ravel(), ZE.ravel(), WW.ravel()


def scalar_mass(L: float, H: float, W: float, rho: float, ngauss: int = 3) -> np.ndarray:
    """The compact mass m_ij = int_V rho s_i s_j dV (9, 9), kg; M = m (x) I_3.
    Exact for ``ngauss >= 3`` (degree 4 along the axis, 2 across)."""
    xi, eta, zeta, w = _points(ngauss)
    s = scalar_shape(xi, eta, zeta, L, H, W)
    return rho * L * H * W * np.einsum("q,qi,qj->ij", w, s, s)


def mass_matrix(L: float, H: float, W: float, rho: float, ngauss: int = 3) -> np.ndarray:
    """The consistent mass matrix M = int_V rho S^T S dV (27, 27) by ``ngauss``
    Gauss points per direction (exact for ngauss >= 3); L, H, W in m, rho in kg/m^3."""
    return np.kron(scalar_mass(L, H, W, rho, ngauss), np.eye(3))


def gravity(L: float, H: float, W: float, rho: float, g, ngauss: int = 2) -> np.ndarray:
    """The generalised gravity force Q_g = int_V rho S^T g dV (27,), N (N m on the
    gradient entries), for the acceleration g (3,) in m/s^2, e.g. (0, 0, -9.80665).
    Exact for ngauss >= 2 (degree 2 along the axis)."""
    xi, eta, zeta, w = _points(ngauss)
    s = scalar_shape(xi, eta, zeta, L, H, W)
    sbar = rho * L * H * W * (w @ s)                     # int rho s_i dV, (9,)
    return np.kron(sbar, np.asarray(g, dtype=float).reshape(3))
