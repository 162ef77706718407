"""The ANCF 3333 beam element: shape functions, mass, gravity, internal force and Jacobians.

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

Internal force (``internal_force``, ``internal_force_jacobians``): see their section
below; the reference configuration is the straight beam along x with r_y, r_z = e_y, e_z
at every node (``reference_coordinates``).
"""
from __future__ import annotations

import numpy as np

from .ancf3243 import elasticity

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


def _points(ngauss: int, nsection: int | None = None):
    """Tensor Gauss-Legendre rule: ``ngauss`` points along xi on [0, 1], ``nsection``
    (default ``ngauss``) per section direction eta, zeta on [-1/2, 1/2] (nsection = 1 is
    the beam axis eta = zeta = 0), and weights w (nq,) summing to 1 (the reference volume)."""
    t, w1 = np.polynomial.legendre.leggauss(ngauss)
    tc, wc = np.polynomial.legendre.leggauss(ngauss if nsection is None else nsection)
    p01, w1, pc, wc = 0.5 * (t + 1.0), 0.5 * w1, 0.5 * tc, 0.5 * wc
    XI, ET, ZE = np.meshgrid(p01, pc, pc, indexing="ij")
    WW = w1[:, None, None] * wc[None, :, None] * wc[None, None, :]
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


# ----------------------------------------------------------------------------------------
# Internal force: Green-Lagrange strain, St Venant-Kirchhoff material with Timoshenko shear
# correction and the Poisson effect on the beam axis, Kelvin-Voigt damping (the same
# continuum formulation as ``ancf3243``, Nachbagauer, Gruber & Gerstmayr 2013):
#
#   F = dr/dX = I + (e - e0) G,  G_aJ = ds_a/dX_J  (X = (x, y, z) in the straight reference)
#   eps = [E11, E22, E33, 2E23, 2E13, 2E12],  E = (F^T F - I)/2   (Voigt, dimensionless)
#   sigma = D (eps + alpha deps/dt),  deps/dt = B(F) de/dt       (2nd Piola-Kirchhoff, Pa)
#   Q = int_V B(F)^T sigma dV                                     (27,), N (N m on gradients)
#   K = dQ/de = int_V B^T D (B + alpha B(dF/dt)) + (G S G^T) (x) I_3 dV,  R = dQ/de' =
#       alpha int_V B^T D B dV                                    (27, 27), N/m and N s/m
#
# D = D0 + Dv (``ancf3243.elasticity``): D0 = diag(E, E, E, G, k1 G, k2 G) over the volume,
# the Poisson block Dv only on the axis eta = zeta = 0 times the area H W.  F has degree
# 2 in xi and 1 in eta, zeta, so the integrands have degree 8 in xi and 4 in eta, zeta:
# 5 x 3 x 3 Gauss points are exact.  Chrono's element uses 3 x 2 x 2 (NP, NT); its stored
# reference data are exact (at their small states the 3-point rule is 3e-8 off K).  Q is the force of M e'' + Q(e, e') = Q_ext; Chrono's
# ``ComputeInternalForces`` returns -Q.
# ----------------------------------------------------------------------------------------

NAXIS, NSECTION = 5, 3   # exact Gauss points along xi and per section direction
_VOIGT = [(0, 0), (1, 1), (2, 2), (1, 2), (0, 2), (0, 1)]
_TENSOR = np.array([[0, 5, 4], [5, 1, 3], [4, 3, 2]])   # Voigt index of S_IJ


def reference_coordinates(L: float) -> np.ndarray:
    """e0 (27,): the straight beam along x, nodes A, B, C at x = 0, L, L/2 (m) with
    r_y = (0, 1, 0) and r_z = (0, 0, 1)."""
    return np.array([[x * L, 0, 0, 0, 1, 0, 0, 0, 1] for x in NODE_XI], dtype=float).ravel()


def shape_gradient(xi, eta, zeta, L: float, H: float, W: float) -> np.ndarray:
    """G_aJ = ds_a/dX_J (..., 9, 3), 1/m for s_1, s_4, s_7 and dimensionless otherwise,
    X = (x, y, z) = (L xi, H eta, W zeta) (the derivatives of ``scalar_shape``):
    d/dx = N_k'(xi)/L [1, y, z], d/dy = N_k [0, 1, 0], d/dz = N_k [0, 0, 1]."""
    xi, eta, zeta = np.broadcast_arrays(*(np.asarray(v, dtype=float) for v in (xi, eta, zeta)))
    n = lagrange(xi)[..., :, None]                                       # (..., 3, 1)
    dn = np.stack([4 * xi - 3, 4 * xi - 1, 4 - 8 * xi], axis=-1)[..., :, None] / L
    one, o = np.ones_like(xi), np.zeros_like(xi)
    sec = lambda *c: np.stack(c, axis=-1)[..., None, :]                  # (..., 1, 3)
    cols = [dn * sec(one, H * eta, W * zeta), n * sec(o, one, o), n * sec(o, o, one)]
    return np.stack([c.reshape(*xi.shape, NSHAPE) for c in cols], axis=-1)


def _strain_matrix(F: np.ndarray, G: np.ndarray) -> np.ndarray:
    """B (nq, 6, 27) with deps/dt = B(F) de/dt: row (I, J) = F_kI G_aJ + F_kJ G_aI
    (halved for I = J) at column 3a + k."""
    P = np.einsum("qkI,qaJ->qIJak", F, G)
    rows = [P[:, i, j] + P[:, j, i] if i != j else P[:, i, i] for i, j in _VOIGT]
    return np.stack(rows, axis=1).reshape(F.shape[0], 6, NDOF)


def _kinematics(e, L, H, W, xi, eta, zeta):
    """G (nq, 9, 3), F (nq, 3, 3) and the Voigt strain eps (nq, 6) at the points, from the
    displacement gradient so that eps = 0 exactly at e = e0."""
    G = shape_gradient(xi, eta, zeta, L, H, W)
    U = (np.asarray(e, dtype=float) - reference_coordinates(L)).reshape(NSHAPE, 3)
    Hu = np.einsum("ak,qaJ->qkJ", U, G)
    Et = 0.5 * (Hu + np.swapaxes(Hu, 1, 2) + np.einsum("qkI,qkJ->qIJ", Hu, Hu))
    eps = np.stack([Et[:, i, j] * (1.0 if i == j else 2.0) for i, j in _VOIGT], axis=1)
    return G, np.eye(3) + Hu, eps


def _part(e, edot, L, H, W, D, alpha, rule, tangent):
    """Q (27,), and if ``tangent`` also K and R (27, 27), of the constitutive part D (6, 6)
    integrated by the Gauss ``rule`` = (naxis, nsection) (equations of the section)."""
    edot = np.asarray(edot, dtype=float)
    xi, eta, zeta, w = _points(*rule)
    w = w * L * H * W
    G, F, eps = _kinematics(e, L, H, W, xi, eta, zeta)
    B = _strain_matrix(F, G)
    sig = (eps + alpha * B @ edot) @ D.T
    Q = np.einsum("q,qvi,qv->i", w, B, sig)
    if not tangent:
        return Q
    DB = np.einsum("ij,qjn->qin", D, B)
    Km = np.einsum("q,qvm,qvn->mn", w, B, DB)
    Bdot = _strain_matrix(np.einsum("ak,qaJ->qkJ", edot.reshape(NSHAPE, 3), G), G)
    Kd = np.einsum("q,qvm,qvn->mn", w, DB, Bdot)
    Kg = np.einsum("q,qaI,qIJ,qbJ->ab", w, G, sig[:, _TENSOR], G)
    return Q, Km + alpha * Kd + np.kron(Kg, np.eye(3)), alpha * Km


def _parts(E, nu, k1, k2, split_poisson, naxis):
    """[(D, rule)]: D0 over the volume and Dv on the axis, or (split_poisson=False) the
    whole isotropic D0 + Dv over the volume."""
    D0, Dv = elasticity(E, nu, k1, k2)
    if not split_poisson:
        return [(D0 + Dv, (naxis, NSECTION))]
    return [(D0, (naxis, NSECTION)), (Dv, (naxis, 1))]


def internal_force(e, edot, L, H, W, E, nu, k1, k2, alpha=0.0, *,
                   split_poisson=True, naxis=NAXIS) -> np.ndarray:
    """The generalised internal force Q(e, e') (27,), N (N m on gradient entries): e (27,)
    in m, edot (27,) in m/s, L, H, W in m, E in Pa, nu, k1 (xz shear), k2 (xy shear)
    dimensionless, alpha in s (sigma = D (eps + alpha eps')).  Exact for naxis >= 5;
    Chrono's ``ComputeInternalForces`` stores -Q."""
    return sum(_part(e, edot, L, H, W, D, alpha, rule, False)
               for D, rule in _parts(E, nu, k1, k2, split_poisson, naxis))


def internal_force_jacobians(e, edot, L, H, W, E, nu, k1, k2, alpha=0.0, *,
                             split_poisson=True, naxis=NAXIS):
    """(K, R) = (dQ/de in N/m, dQ/de' in N s/m), each (27, 27), of ``internal_force``
    (same arguments); Chrono's ``ComputeKRMmatricesGlobal(H, 1, 0, 0)`` and ``(H, 0, 1, 0)``."""
    K, R = np.zeros((NDOF, NDOF)), np.zeros((NDOF, NDOF))
    for D, rule in _parts(E, nu, k1, k2, split_poisson, naxis):
        _, k, r = _part(e, edot, L, H, W, D, alpha, rule, True)
        K, R = K + k, R + r
    return K, R
