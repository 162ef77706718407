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


# ----------------------------------------------------------------------------------------
# Internal force: Green-Lagrange strain, isotropic St Venant-Kirchhoff material over the
# whole volume (no Poisson split), Kelvin-Voigt damping.
#
#   F = dr/dX = I + (e - e0) G,  G_aJ = ds_a/dX_J  (X = (x, y, z) in the undeformed box)  (7)
#   eps = [E11, E22, E33, 2E23, 2E13, 2E12],  E = (F^T F - I)/2   (Voigt, dimensionless)  (8)
#   sigma = D (eps + alpha deps/dt),  deps/dt = B(F) de/dt   (2nd Piola-Kirchhoff, Pa)    (9)
#   Q = int_V B(F)^T sigma dV                                  (96,), N (N m on gradients) (10)
#   K = dQ/de = int_V B^T D (B + alpha B(F')) + (G S G^T) (x) I_3 dV,  R = dQ/de'
#     = alpha int_V B^T D B dV                                  (96, 96), N/m and N s/m   (11)
#
# with S the 3x3 tensor form of sigma and B(F) (6, 96) the strain-rate matrix, row IJ =
# F_kI G_aJ + F_kJ G_aI (halved for I = J) at column 3a + k.  D is the isotropic law of
# Chrono's ChMaterialHexaANCF (lambda + 2 mu on the normal diagonal, lambda off it, mu on
# the three shears).  Degrees: s_a is cubic per direction, so F is cubic, eps of degree 6
# and the integrands of (10), (11) of degree 12 in each natural coordinate: 7 Gauss
# points per direction integrate them exactly.  Chrono's element uses 4 (its header NP);
# its stored reference data are exact.  Chrono's ComputeInternalForces returns -Q.
# ----------------------------------------------------------------------------------------

NEXACT = 7   # exact Gauss points per direction for (10), (11)
_VOIGT = [(0, 0), (1, 1), (2, 2), (1, 2), (0, 2), (0, 1)]
_TENSOR = np.array([[0, 5, 4], [5, 1, 3], [4, 3, 2]])   # Voigt index of S_IJ


def reference_coordinates(Lx: float, Ly: float, Lz: float) -> np.ndarray:
    """e0 (96,): node positions at the box corners (0..Lx, 0..Ly, 0..Lz) m, gradients = I."""
    corners = (1.0 + NODE_SIGNS) / 2.0 * np.array([Lx, Ly, Lz])
    return np.concatenate([np.concatenate([c, np.eye(3).ravel()]) for c in corners])


def elasticity(E: float, nu: float) -> np.ndarray:
    """The isotropic D (6, 6), Pa, Voigt order [11, 22, 33, 23, 13, 12]: lambda + 2 mu,
    lambda, mu with lambda = E nu/((1+nu)(1-2nu)), mu = E/(2(1+nu))."""
    mu = E / (2.0 * (1.0 + nu))
    lam = E * nu / ((1.0 + nu) * (1.0 - 2.0 * nu))
    D = np.diag([2.0 * mu] * 3 + [mu] * 3)
    D[:3, :3] += lam
    return D


def shape_gradient(xi, eta, zeta, Lx: float, Ly: float, Lz: float) -> np.ndarray:
    """G_aJ = ds_a/dX_J (..., 32, 3): the derivatives of eqs. (1)-(4) with respect to
    X = (x, y, z), 1/m for s_r, dimensionless for s_x, s_y, s_z (d/dX_J = (2/L_J) d/dxi_J)."""
    xi, eta, zeta = np.broadcast_arrays(*(np.asarray(v, dtype=float) for v in (xi, eta, zeta)))
    half = np.array([0.5 * Lx, 0.5 * Ly, 0.5 * Lz])
    rows = []
    for signs in NODE_SIGNS:
        U = [s * v for s, v in zip(signs, (xi, eta, zeta))]             # X, Y, Z
        p = [1.0 + u for u in U]
        P = p[0] * p[1] * p[2] / 8.0
        dP = [p[1] * p[2] / 8.0, p[0] * p[2] / 8.0, p[0] * p[1] / 8.0]  # dP/dU_J
        g = 1.0 + 0.5 * sum(u * (1.0 - u) for u in U)
        dU = signs / half                                               # dU_J/dX_J
        rows.append([(dP[J] * g + P * (0.5 - U[J])) * dU[J] for J in range(3)])
        for k in range(3):
            h = 0.5 * (U[k] ** 2 - 1.0)
            rows.append([signs[k] * half[k] * (dP[J] * h + (P * U[k] if J == k else 0.0))
                         * dU[J] for J in range(3)])
    return np.stack([np.stack(r, axis=-1) for r in rows], axis=-2)


def _strain_matrix(F: np.ndarray, G: np.ndarray) -> np.ndarray:
    """B (nq, 6, 96), eq. (9): row IJ = F_kI G_aJ + F_kJ G_aI (halved for I = J) at 3a + k."""
    P = np.einsum("qkI,qaJ->qIJak", F, G)
    rows = [P[:, i, j] + P[:, j, i] if i != j else P[:, i, i] for i, j in _VOIGT]
    return np.stack(rows, axis=1).reshape(F.shape[0], 6, NDOF)


def _kinematics(e, dims, xi, eta, zeta):
    """G (nq, 32, 3), F (nq, 3, 3) and eps (nq, 6), eqs. (7)-(8), from the displacement
    gradient so that eps = 0 exactly at e = e0."""
    G = shape_gradient(xi, eta, zeta, *dims)
    U = (np.asarray(e, dtype=float) - reference_coordinates(*dims)).reshape(NSHAPE, 3)
    Hu = np.einsum("ak,qaJ->qkJ", U, G)
    Et = 0.5 * (Hu + np.swapaxes(Hu, 1, 2) + np.einsum("qkI,qkJ->qIJ", Hu, Hu))
    eps = np.stack([Et[:, i, j] * (1.0 if i == j else 2.0) for i, j in _VOIGT], axis=1)
    return G, np.eye(3) + Hu, eps


def _evaluate(e, edot, Lx, Ly, Lz, E, nu, alpha, ngauss, tangent):
    """Q, eq. (10), and if ``tangent`` also (K, R), eq. (11), by ngauss^3 Gauss points."""
    edot = np.asarray(edot, dtype=float)
    xi, eta, zeta, w = _points(ngauss)
    w = w * (Lx * Ly * Lz / 8.0)
    D = elasticity(E, nu)
    G, F, eps = _kinematics(e, (Lx, Ly, Lz), xi, eta, zeta)
    B = _strain_matrix(F, G)
    sig = (eps + alpha * B @ edot) @ D
    Q = np.einsum("q,qvi,qv->i", w, B, sig)
    if not tangent:
        return Q
    DB = np.einsum("ij,qjn->qin", D, B)
    Km = np.einsum("q,qvm,qvn->mn", w, B, DB)
    Bdot = _strain_matrix(np.einsum("ak,qaJ->qkJ", edot.reshape(NSHAPE, 3), G), G)
    Kd = np.einsum("q,qvm,qvn->mn", w, DB, Bdot)
    Kg = np.einsum("q,qaI,qIJ,qbJ->ab", w, G, sig[:, _TENSOR], G)
    return Q, Km + alpha * Kd + np.kron(Kg, np.eye(3)), alpha * Km


def internal_force(e, edot, Lx, Ly, Lz, E, nu, alpha=0.0, *, ngauss=NEXACT) -> np.ndarray:
    """The generalised internal force Q(e, e') (96,), eq. (10), N (N m on gradient
    entries): e (96,) in m, edot (96,) in m/s, Lx, Ly, Lz in m, E in Pa, nu dimensionless,
    alpha in s (Kelvin-Voigt).  Exact for ngauss >= 7; Chrono's ``ComputeInternalForces``
    stores -Q."""
    return _evaluate(e, edot, Lx, Ly, Lz, E, nu, alpha, ngauss, False)


def internal_force_jacobians(e, edot, Lx, Ly, Lz, E, nu, alpha=0.0, *, ngauss=NEXACT):
    """(K, R) = (dQ/de in N/m, dQ/de' in N s/m), each (96, 96), eq. (11), of
    ``internal_force`` (same arguments); Chrono's ``ComputeKRMmatricesGlobal(H, 1, 0, 0)``
    and ``(H, 0, 1, 0)``."""
    _, K, R = _evaluate(e, edot, Lx, Ly, Lz, E, nu, alpha, ngauss, True)
    return K, R
