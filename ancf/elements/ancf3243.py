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

Internal force (``internal_force``, ``internal_force_jacobians``): see their section
below; the reference configuration is the straight beam along x with identity
gradients (``reference_coordinates``).
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


def _points(ngauss: int, nsection: int | None = None):
    """Tensor rule: coordinates xi, eta, zeta and weights w (nq,) summing to 1 (the
    reference volume); ``ngauss`` points along xi, ``nsection`` (default ``ngauss``)
    per section direction, nsection = 1 being the beam axis eta = zeta = 0."""
    p01, _, w = _rule(ngauss)
    _, pc, wc = _rule(ngauss if nsection is None else nsection)
    XI, ET, ZE = np.meshgrid(p01, pc, pc, indexing="ij")
    WW = w[:, None, None] * wc[None, :, None] * wc[None, None, :]
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


# ----------------------------------------------------------------------------------------
# Internal force: Green-Lagrange strain, St Venant-Kirchhoff material with Timoshenko shear
# correction and the Poisson effect on the beam axis, Kelvin-Voigt damping.
#
#   F = dr/dX = I + (e - e0) G,  G_aJ = ds_a/dX_J  (X = (x, y, z) in the straight reference)
#   eps = [E11, E22, E33, 2E23, 2E13, 2E12],  E = (F^T F - I)/2   (Voigt, dimensionless)
#   sigma = D (eps + alpha deps/dt),  deps/dt = B(F) de/dt       (2nd Piola-Kirchhoff, Pa)
#   Q = int_V B(F)^T sigma dV = int_V F S G^T dV                  (24,), N (N m on gradients)
#
# D = D0 + Dv (Nachbagauer, Gruber & Gerstmayr 2012, "enhanced continuum mechanics"):
# D0 = diag(E, E, E, G, k1 G, k2 G) is integrated over the volume; Dv, the Poisson part
# (the upper 3x3 block lambda + 2G delta_ij - E delta_ij, lambda = E nu/((1+nu)(1-2nu))),
# only on the beam axis eta = zeta = 0 times the area H W (against the Poisson locking
# of the linear section field).  Exact Gauss rules: the integrands have degree 8 in xi
# (5 points) and 4 in eta, zeta (3 points); Chrono's element uses 3 points along xi,
# its stored reference data are exact.  Q is the elastic + viscous force of
# M e'' + Q(e, e') = Q_ext; Chrono's ComputeInternalForces returns -Q.
# ----------------------------------------------------------------------------------------

NAXIS, NSECTION = 5, 3   # exact Gauss points along xi and per section direction
_VOIGT = [(0, 0), (1, 1), (2, 2), (1, 2), (0, 2), (0, 1)]
_TENSOR = np.array([[0, 5, 4], [5, 1, 3], [4, 3, 2]])   # Voigt index of S_IJ


def reference_coordinates(L: float) -> np.ndarray:
    """e0 (24,): the straight beam from (0, 0, 0) to (L, 0, 0) with r_x, r_y, r_z = I."""
    node = lambda x: [x, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0]
    return np.array(node(0.0) + node(L))


def elasticity(E: float, nu: float, k1: float, k2: float):
    """(D0, Dv), each (6, 6) in Pa, Voigt order [11, 22, 33, 23, 13, 12]: D0 =
    diag(E, E, E, G, k1 G, k2 G) with G = E/(2(1+nu)) (k1 scales the xz shear 2E13, k2
    the xy shear 2E12), Dv the Poisson part, so D0 + Dv is the isotropic 3D law."""
    G = E / (2.0 * (1.0 + nu))
    lam = E * nu / ((1.0 + nu) * (1.0 - 2.0 * nu))
    D0 = np.diag([E, E, E, G, k1 * G, k2 * G])
    Dv = np.zeros((6, 6))
    Dv[:3, :3] = lam + (2.0 * G - E) * np.eye(3)
    return D0, Dv


def shape_gradient(xi, eta, zeta, L: float, H: float, W: float) -> np.ndarray:
    """G_aJ = ds_a/dX_J (..., 8, 3), 1/m for s_1, s_5, dimensionless otherwise; X = (x, y, z)
    = (L xi, H eta, W zeta) in the straight reference (the derivatives of ``scalar_shape``)."""
    xi, eta, zeta = np.broadcast_arrays(*(np.asarray(v, dtype=float) for v in (xi, eta, zeta)))
    y, z, o = H * eta, W * zeta, np.zeros_like(xi)
    h = 6.0 * (xi**2 - xi) / L
    dx = [h, 1 - 4 * xi + 3 * xi**2, -y / L, -z / L, -h, 3 * xi**2 - 2 * xi, y / L, z / L]
    dy = [o, o, 1.0 - xi, o, o, o, xi, o]
    dz = [o, o, o, 1.0 - xi, o, o, o, xi]
    return np.stack([np.stack(d, axis=-1) for d in (dx, dy, dz)], axis=-1)


def _strain_matrix(F: np.ndarray, G: np.ndarray) -> np.ndarray:
    """B (nq, 6, 24) with d(eps)/dt = B(F) de/dt: row (I, J) = (F_kI G_aJ + F_kJ G_aI)
    (halved for I = J) at column 3a + k."""
    P = np.einsum("qkI,qaJ->qIJak", F, G)
    rows = [P[:, i, j] + P[:, j, i] if i != j else P[:, i, i] for i, j in _VOIGT]
    return np.stack(rows, axis=1).reshape(F.shape[0], 6, NDOF)


def _kinematics(e, L, H, W, xi, eta, zeta):
    """At the points: G (nq, 8, 3), F (nq, 3, 3) and the Voigt Green-Lagrange strain eps
    (nq, 6), from the displacement gradient so that eps = 0 exactly at e = e0."""
    G = shape_gradient(xi, eta, zeta, L, H, W)
    U = (np.asarray(e, dtype=float) - reference_coordinates(L)).reshape(NSHAPE, 3)
    Hu = np.einsum("ak,qaJ->qkJ", U, G)
    Et = 0.5 * (Hu + np.swapaxes(Hu, 1, 2) + np.einsum("qkI,qkJ->qIJ", Hu, Hu))
    eps = np.stack([Et[:, i, j] * (1.0 if i == j else 2.0) for i, j in _VOIGT], axis=1)
    return G, np.eye(3) + Hu, eps


def _part(e, edot, L, H, W, D, alpha, rule, tangent):
    """Q (24,), and if ``tangent`` also K = dQ/de and R = dQ/de' (24, 24), of one
    constitutive part D integrated by ``rule`` = (naxis, nsection):
    Q = int B^T sigma dV, R = alpha int B^T D B dV,
    K = int B^T D (B + alpha B(Fdot)) + (G S G^T) (x) I_3 dV  (S = sigma as a 3x3 tensor)."""
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
    """[(D, rule)]: D0 over the volume and Dv on the axis, or (split_poisson=False)
    the whole D0 + Dv over the volume."""
    D0, Dv = elasticity(E, nu, k1, k2)
    if not split_poisson:
        return [(D0 + Dv, (naxis, NSECTION))]
    return [(D0, (naxis, NSECTION)), (Dv, (naxis, 1))]


def internal_force(e, edot, L, H, W, E, nu, k1, k2, alpha=0.0, *,
                   split_poisson=True, naxis=NAXIS) -> np.ndarray:
    """The generalised internal force Q(e, e') (24,), N (N m on gradient entries), of the
    section above: e (24,) in m, edot (24,) in m/s, L, H, W in m, E in Pa, nu, k1, k2
    dimensionless, alpha in s (Kelvin-Voigt: sigma = D (eps + alpha eps')).  Exact for
    naxis >= 5; Chrono's ``ComputeInternalForces`` stores -Q."""
    return sum(_part(e, edot, L, H, W, D, alpha, rule, False)
               for D, rule in _parts(E, nu, k1, k2, split_poisson, naxis))


def internal_force_jacobians(e, edot, L, H, W, E, nu, k1, k2, alpha=0.0, *,
                             split_poisson=True, naxis=NAXIS):
    """(K, R) = (dQ/de in N/m, dQ/de' in N s/m), each (24, 24), of ``internal_force``
    (same arguments); Chrono's ``ComputeKRMmatricesGlobal(H, 1, 0, 0)`` and ``(H, 0, 1, 0)``."""
    K, R = np.zeros((NDOF, NDOF)), np.zeros((NDOF, NDOF))
    for D, rule in _parts(E, nu, k1, k2, split_poisson, naxis):
        _, k, r = _part(e, edot, L, H, W, D, alpha, rule, True)
        K, R = K + k, R + r
    return K, R
