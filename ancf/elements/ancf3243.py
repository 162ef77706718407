"""The ANCF 3243 beam element: shape functions, consistent mass, gravity force.

A straight 3D beam of length L (m, along x), with a rectangular cross-section of
height H (m, along y) and width W (m, along z): 2 nodes, each carrying the
position r and the three gradients r_x, r_y, r_z (the "fully parameterised"
beam of Shabana & Yakoub 2001; Project Chrono's ``ChElementBeamANCF_3243``,
whose ``SetDimensions(L, thicknessY, thicknessZ)`` are our (L, H, W)).

Coordinates e (24,), per node ``[r, r_x, r_y, r_z]``, each (x, y, z):

    e = [r_A, r_x,A, r_y,A, r_z,A, r_B, r_x,B, r_y,B, r_z,B]

The position of the material point (x, y, z) is r = S(xi, eta, zeta) e with
S = [s_1 I_3, ..., s_8 I_3] (3, 24) and the scalar shape functions, in the
reference coordinates xi = x/L in [0, 1], eta = y/H and zeta = z/W in [-1/2, 1/2]:

    s_1 = 1 - 3 xi^2 + 2 xi^3          s_5 = 3 xi^2 - 2 xi^3
    s_2 = L (xi - 2 xi^2 + xi^3)       s_6 = L (xi^3 - xi^2)
    s_3 = H eta (1 - xi)               s_7 = H eta xi
    s_4 = W zeta (1 - xi)              s_8 = W zeta xi

i.e. the cubic Hermite polynomials along the axis for (r, r_x), and the
section gradients (r_y, r_z) interpolated linearly along the axis and
multiplied by y = H eta, z = W zeta.  Equations:

    M   = int_V rho S^T S dV        (24, 24), kg (kg m, kg m^2 on gradient entries)
    Q_g = int_V rho S^T g dV        (24,),   N  (N m on gradient entries)

with dV = L H W dxi deta dzeta, evaluated by tensor Gauss-Legendre quadrature.
s_i s_j has degree 6 in xi and 2 in eta, zeta, so ``ngauss >= 4`` points per
direction integrate M exactly; S^T g has degree 3 in xi and 1 in eta, zeta,
so 2 points per direction integrate Q_g exactly.
"""
from __future__ import annotations

import numpy as np

NSHAPE = 8   # scalar shape functions
NDOF = 24    # 3 * NSHAPE coordinates


def scalar_shape(xi, eta, zeta, L: float, H: float, W: float) -> np.ndarray:
    """The 8 scalar shape functions s_1..s_8 (module docstring) at xi = x/L in [0, 1],
    eta = y/H, zeta = z/W in [-1/2, 1/2]; arrays broadcast, result (..., 8).
    s_1, s_5, s_3, s_4, s_7, s_8 are dimensionless; s_2, s_6 in m (times a gradient)."""
    xi, eta, zeta = np.broadcast_arrays(*(np.asarray(v, dtype=float) for v in (xi, eta, zeta)))
    y, z = H * eta, W * zeta
    return np.stack([
        1.0 - 3.0 * xi**2 + 2.0 * xi**3,
        L * (xi - 2.0 * xi**2 + xi**3),
        y * (1.0 - xi),
        z * (1.0 - xi),
        3.0 * xi**2 - 2.0 * xi**3,
        L * (xi**3 - xi**2),
        y * xi,
        z * xi,
    ], axis=-1)


def shape(xi: float, eta: float, zeta: float, L: float, H: float, W: float) -> np.ndarray:
    """The shape-function matrix S (3, 24) at one point: S = [s_1 I_3, ..., s_8 I_3],
    so that r(xi, eta, zeta) = S e with e ordered per node [r, r_x, r_y, r_z]."""
    s = scalar_shape(xi, eta, zeta, L, H, W)
    return np.kron(s.reshape(1, NSHAPE), np.eye(3))


def _rule(ngauss: int):
    """Gauss-Legendre points and weights of ``ngauss`` points on [0, 1] (xi) and on
    [-1/2, 1/2] (eta, zeta); the weights sum to 1."""
    t, w = np.polynomial.legendre.leggauss(ngauss)
    return 0.5 * (t + 1.0), 0.5 * t, 0.5 * w


def _points(ngauss: int):
    """Tensor rule: s (nq, 8)-ready coordinates xi, eta, zeta and weights w (nq,)
    summing to 1 (the reference volume)."""
    p01, pc, w = _rule(ngauss)
    XI, ET, ZE = np.meshgrid(p01, pc, pc, indexing="ij")
    WW = w[:, None, None] * w[None, :, None] * w[None, None, :]
    return XI.ravel(), ET.ravel(), ZE.ravel(), WW.ravel()


def scalar_mass(L: float, H: float, W: float, rho: float, ngauss: int = 4) -> np.ndarray:
    """The compact mass m_ij = int_V rho s_i s_j dV (8, 8), kg; M = m (x) I_3.
    Exact for ``ngauss >= 4`` (degree 6 along the axis)."""
    xi, eta, zeta, w = _points(ngauss)
    s = scalar_shape(xi, eta, zeta, L, H, W)
    return rho * L * H * W * np.einsum("q,qi,qj->ij", w, s, s)


def mass_matrix(L: float, H: float, W: float, rho: float, ngauss: int = 4) -> np.ndarray:
    """The consistent mass matrix M = int_V rho S^T S dV (24, 24) by ``ngauss``
    Gauss points per direction (exact for ngauss >= 4); L, H, W in m, rho in kg/m^3."""
    return np.kron(scalar_mass(L, H, W, rho, ngauss), np.eye(3))


def gravity(L: float, H: float, W: float, rho: float, g, ngauss: int = 2) -> np.ndarray:
    """The generalised gravity force Q_g = int_V rho S^T g dV (24,), N (N m on the
    gradient entries), for the acceleration g (3,) in m/s^2, e.g. (0, 0, -9.80665).
    Exact for ngauss >= 2 (degree 3 along the axis)."""
    xi, eta, zeta, w = _points(ngauss)
    s = scalar_shape(xi, eta, zeta, L, H, W)
    sbar = rho * L * H * W * (w @ s)                     # int rho s_i dV, (8,)
    return np.kron(sbar, np.asarray(g, dtype=float).reshape(3))
