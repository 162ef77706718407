"""The ANCF 3833 shell element: shape functions, mass, gravity, internal force.

A flat rectangular higher-order shell of length L (m, along x), width W (m, along
y) and thickness H (m, along z, symmetric about the mid-surface): 8 nodes (4
corners, 4 mid-sides), each carrying the position r, the transverse gradient
r_z and its derivative r_zz (Project Chrono's ``ChElementShellANCF_3833`` with
``ChNodeFEAxyzDD`` nodes: position, D, DD; ``SetDimensions(lenX, lenY)`` are our
(L, W) and its ``AddLayer(thickness, ...)`` calls stack up to our H).

Coordinates e (72,), per node ``[r, r_z, r_zz]``, each (x, y, z), nodes in the
order A (-1, -1), B (1, -1), C (1, 1), D (-1, 1), E (0, -1), F (1, 0), G (0, 1),
H (-1, 0) of (xi_i, eta_i):

    e = [r_A, r_z,A, r_zz,A, r_B, ..., r_zz,H]

Compact index of a scalar shape function: 3 * node + (0: r, 1: r_z, 2: r_zz).
The position of the material point is r = S(xi, eta, z) e with S = [s_1 I_3, ...,
s_24 I_3] (3, 72), in the reference coordinates xi = 2x/L - 1, eta = 2y/W - 1 in
[-1, 1] and the distance z (m) from the mid-surface, z in [-H/2, H/2]:

    s_r = N_i(xi, eta),   s_rz = z N_i,   s_rzz = (z^2 / 2) N_i

with the 8-node serendipity functions N_i (a = xi_i xi, b = eta_i eta):

    corners:                N_i = (1 + a)(1 + b)(a + b - 1) / 4
    mid-sides, xi_i = 0:    N_i = (1 - xi^2)(1 + b) / 2
    mid-sides, eta_i = 0:   N_i = (1 + a)(1 - eta^2) / 2

i.e. a quadratic mid-surface with a quadratic fibre r(z) = r + z r_z + z^2/2 r_zz.
Equations:

    M   = int_V rho S^T S dV        (72, 72), kg (kg m^2, kg m^4 on r_z, r_zz)
    Q_g = int_V rho S^T g dV        (72,),   N  (N m, N m^2 on r_z, r_zz)

with dV = (L/2)(W/2) dxi deta dz for this flat, undistorted reference shape.  Both
are M = m (x) I_3 and Q_g = q (x) g over the 24 scalar functions.  Through the
thickness the integral is a sum over layers (thickness t_k, density rho_k,
stacked from z = -H/2 upward), as in Chrono's layered shell; a single layer is the
homogeneous plate.  s_i s_j has degree 4 in xi, eta and 4 in z, so 3 x 3 x 3 Gauss
points integrate M exactly (Chrono uses 5 x 5 x 5, for distorted reference shapes
too); s_i has degree 2 in each, so 2 x 2 x 2 points suffice for Q_g.

Internal force (``internal_force``, ``internal_force_jacobians``): see their section
below; the reference configuration is the flat plate with r_z = e_z, r_zz = 0
(``reference_coordinates``).
"""
from __future__ import annotations

import numpy as np

NNODE = 8
NSHAPE = 24  # scalar shape functions, 3 per node
NDOF = 72    # 3 * NSHAPE coordinates
NODE_XI = np.array([-1.0, 1.0, 1.0, -1.0, 0.0, 1.0, 0.0, -1.0])   # xi_i of nodes A..H
NODE_ETA = np.array([-1.0, -1.0, 1.0, 1.0, -1.0, 0.0, 1.0, 0.0])  # eta_i


def serendipity(xi, eta) -> np.ndarray:
    """The 8 serendipity functions N_i (module docstring) at xi, eta in [-1, 1];
    arrays broadcast, result (..., 8) in the node order A..H; dimensionless."""
    xi, eta = np.broadcast_arrays(*(np.asarray(v, dtype=float)[..., None] for v in (xi, eta)))
    a, b = NODE_XI * xi, NODE_ETA * eta
    corner = (1 + a) * (1 + b) * (a + b - 1) / 4
    mid_x = (1 - xi**2) * (1 + b) / 2      # nodes on eta = +-1 (xi_i = 0)
    mid_y = (1 + a) * (1 - eta**2) / 2     # nodes on xi = +-1 (eta_i = 0)
    return np.where(NODE_XI == 0, mid_x, np.where(NODE_ETA == 0, mid_y, corner))


def scalar_shape(xi, eta, z) -> np.ndarray:
    """The 24 scalar shape functions at xi, eta in [-1, 1] and z (m) from the
    mid-surface; arrays broadcast, result (..., 24) ordered 3 * node + (r, r_z, r_zz).
    s_r is dimensionless, s_rz in m, s_rzz in m^2."""
    xi, eta, z = np.broadcast_arrays(*(np.asarray(v, dtype=float) for v in (xi, eta, z)))
    n = serendipity(xi, eta)
    z = z[..., None]
    s = np.stack([n, z * n, z**2 / 2 * n], axis=-1)          # (..., node, kind)
    return s.reshape(s.shape[:-2] + (NSHAPE,))


def shape(xi: float, eta: float, z: float) -> np.ndarray:
    """The shape-function matrix S (3, 72) at one point: S = [s_1 I_3, ..., s_24 I_3],
    so that r(xi, eta, z) = S e with e ordered per node [r, r_z, r_zz]."""
    return np.kron(scalar_shape(xi, eta, z).reshape(1, NSHAPE), np.eye(3))


def _layers(H: float, rho: float, layers):
    """The layers as a list of (thickness t_k in m, density rho_k in kg/m^3); by
    default one layer (H, rho).  Their thicknesses must add up to H."""
    layers = [(H, rho)] if layers is None else [(float(t), float(r)) for t, r in layers]
    if not np.isclose(sum(t for t, _ in layers), H, rtol=1e-12, atol=0.0):
        raise ValueError("layer thicknesses must add up to H")
    return layers


def _points(L: float, W: float, H: float, rho: float, layers, n_plane: int, n_thick: int):
    """Tensor Gauss-Legendre rule over the shell: coordinates xi, eta (-), z (m) and
    weights w (kg) = rho_k dV, summing to the shell's mass rho L W H (one layer)."""
    t_p, w_p = np.polynomial.legendre.leggauss(n_plane)
    t_z, w_z = np.polynomial.legendre.leggauss(n_thick)
    xi, eta, z, w = [], [], [], []
    z0 = -H / 2
    for t, r in _layers(H, rho, layers):
        XI, ET, ZE = np.meshgrid(t_p, t_p, z0 + t * (t_z + 1) / 2, indexing="ij")
        WW = w_p[:, None, None] * w_p[None, :, None] * w_z[None, None, :]
        xi.append(XI.ravel()), eta.append(ET.ravel()), z.append(ZE.ravel())
        w.append(r * (L / 2) * (W / 2) * (t / 2) * WW.ravel())
        z0 += t
    return np.concatenate(xi), np.concatenate(eta), np.concatenate(z), np.concatenate(w)


def scalar_mass(L: float, W: float, H: float, rho: float, layers=None,
                n_plane: int = 3, n_thick: int = 3) -> np.ndarray:
    """The compact mass m_ij = int_V rho s_i s_j dV (24, 24); M = m (x) I_3.
    ``layers`` = [(t_k, rho_k), ...] from the bottom face up (default one layer);
    exact for n_plane >= 3, n_thick >= 3."""
    xi, eta, z, w = _points(L, W, H, rho, layers, n_plane, n_thick)
    s = scalar_shape(xi, eta, z)
    return np.einsum("q,qi,qj->ij", w, s, s)


def mass_matrix(L: float, W: float, H: float, rho: float, layers=None,
                n_plane: int = 3, n_thick: int = 3) -> np.ndarray:
    """The consistent mass matrix M = int_V rho S^T S dV (72, 72); L, W, H in m,
    rho in kg/m^3.  Exact for n_plane >= 3, n_thick >= 3."""
    return np.kron(scalar_mass(L, W, H, rho, layers, n_plane, n_thick), np.eye(3))


def gravity(L: float, W: float, H: float, rho: float, g, layers=None,
            n_plane: int = 2, n_thick: int = 2) -> np.ndarray:
    """The generalised gravity force Q_g = int_V rho S^T g dV (72,), N (N m, N m^2 on
    r_z, r_zz), for the acceleration g (3,) in m/s^2, e.g. (0, 0, -9.80665).
    Exact for n_plane >= 2, n_thick >= 2."""
    xi, eta, z, w = _points(L, W, H, rho, layers, n_plane, n_thick)
    q = w @ scalar_shape(xi, eta, z)                      # int rho s_i dV, (24,)
    return np.kron(q, np.asarray(g, dtype=float).reshape(3))


# ----------------------------------------------------------------------------------------
# Internal force: Green-Lagrange strain, isotropic St Venant-Kirchhoff material (the full
# 3D law over the whole volume, no Poisson split: Chrono's ChMaterialShellANCF, one layer
# with fibre angle 0), Kelvin-Voigt damping.
#
#   F = dr/dX = I + (e - e0) G,  G_aJ = ds_a/dX_J  (X = (x, y, z) in the flat reference)
#   eps = [E11, E22, E33, 2E23, 2E13, 2E12],  E = (F^T F - I)/2   (Voigt, dimensionless)
#   sigma = D (eps + alpha deps/dt),  deps/dt = B(F) de/dt       (2nd Piola-Kirchhoff, Pa)
#   Q = int_V B(F)^T sigma dV                                     (72,), N (N m, N m^2)
#   K = dQ/de = int_V B^T D (B + alpha B(F')) + (G S G^T) (x) I_3 dV,  R = dQ/de' = alpha int_V B^T D B dV
#
# Exact Gauss rules: with r_zz free the integrands have degree <= 8 in xi, eta and z, so
# 5 x 5 x 5 points are exact (Chrono's element uses 3 x 3 x 2; its stored reference data
# are exact).  Q is the elastic + viscous force of M e'' + Q(e, e') = Q_ext; Chrono's
# ComputeInternalForces returns -Q.
# ----------------------------------------------------------------------------------------

NGAUSS = 5   # exact Gauss points per direction (xi, eta, z)
_VOIGT = [(0, 0), (1, 1), (2, 2), (1, 2), (0, 2), (0, 1)]
_TENSOR = np.array([[0, 5, 4], [5, 1, 3], [4, 3, 2]])   # Voigt index of S_IJ


def reference_coordinates(L: float, W: float) -> np.ndarray:
    """e0 (72,): the flat L x W plate in z = 0 with corner A at the origin, r_z = (0, 0, 1)
    and r_zz = 0 at every node (Chrono's test setup)."""
    e0 = np.zeros((NNODE, 3, 3))
    e0[:, 0, 0], e0[:, 0, 1] = L * (NODE_XI + 1) / 2, W * (NODE_ETA + 1) / 2
    e0[:, 1, 2] = 1.0
    return e0.ravel()


def elasticity(E: float, nu: float) -> np.ndarray:
    """The isotropic 3D law D (6, 6), Pa, Voigt order [11, 22, 33, 23, 13, 12] (shear
    rows act on the engineering strains 2E_IJ): lambda + 2G on the diagonal of the normal
    block, lambda off it, G on the shear diagonal."""
    G = E / (2.0 * (1.0 + nu))
    lam = E * nu / ((1.0 + nu) * (1.0 - 2.0 * nu))
    D = np.diag([2 * G, 2 * G, 2 * G, G, G, G])
    D[:3, :3] += lam
    return D


def serendipity_gradient(xi, eta) -> np.ndarray:
    """(dN_i/dxi, dN_i/deta) (..., 8, 2) of ``serendipity``; dimensionless."""
    xi, eta = np.broadcast_arrays(*(np.asarray(v, dtype=float)[..., None] for v in (xi, eta)))
    a, b = NODE_XI * xi, NODE_ETA * eta
    corner = (NODE_XI * (1 + b) * (2 * a + b) / 4, NODE_ETA * (1 + a) * (a + 2 * b) / 4)
    mid_x = (-xi * (1 + b), NODE_ETA * (1 - xi**2) / 2)
    mid_y = (NODE_XI * (1 - eta**2) / 2, -eta * (1 + a))
    return np.stack([np.where(NODE_XI == 0, mx, np.where(NODE_ETA == 0, my, c))
                     for c, mx, my in zip(corner, mid_x, mid_y)], axis=-1)


def shape_gradient(xi, eta, z, L: float, W: float) -> np.ndarray:
    """G_aJ = ds_a/dX_J (..., 24, 3) in the flat reference, X = (x, y, z) = (L (xi + 1)/2,
    W (eta + 1)/2, z): per node (dN/dx, dN/dy, 0), z (dN/dx, dN/dy, N/z), and
    z^2/2 (dN/dx, dN/dy, 2N/z); 1/m on r, dimensionless on r_z, m on r_zz."""
    xi, eta, z = np.broadcast_arrays(*(np.asarray(v, dtype=float) for v in (xi, eta, z)))
    n, dn = serendipity(xi, eta), serendipity_gradient(xi, eta)
    dx, dy, z = dn[..., 0] * 2 / L, dn[..., 1] * 2 / W, z[..., None]
    g = np.stack([np.stack([dx, dy, 0 * n], -1), np.stack([z * dx, z * dy, n], -1),
                  np.stack([z**2 / 2 * dx, z**2 / 2 * dy, z * n], -1)], axis=-2)
    return g.reshape(g.shape[:-3] + (NSHAPE, 3))


def _strain_matrix(F: np.ndarray, G: np.ndarray) -> np.ndarray:
    """B (nq, 6, 72) with d(eps)/dt = B(F) de/dt: row (I, J) = (F_kI G_aJ + F_kJ G_aI)
    (halved for I = J) at column 3a + k."""
    P = np.einsum("qkI,qaJ->qIJak", F, G)
    rows = [P[:, i, j] + P[:, j, i] if i != j else P[:, i, i] for i, j in _VOIGT]
    return np.stack(rows, axis=1).reshape(F.shape[0], 6, NDOF)


def _kinematics(e, G, L, W):
    """F (nq, 3, 3) and the Voigt Green-Lagrange strain eps (nq, 6) at the points, from
    the displacement gradient so that eps = 0 exactly at e = e0."""
    U = (np.asarray(e, dtype=float) - reference_coordinates(L, W)).reshape(NSHAPE, 3)
    Hu = np.einsum("ak,qaJ->qkJ", U, G)
    Et = 0.5 * (Hu + np.swapaxes(Hu, 1, 2) + np.einsum("qkI,qkJ->qIJ", Hu, Hu))
    eps = np.stack([Et[:, i, j] * (1.0 if i == j else 2.0) for i, j in _VOIGT], axis=1)
    return np.eye(3) + Hu, eps


def _evaluate(e, edot, L, W, H, E, nu, alpha, ngauss, tangent):
    """Q (72,), and if ``tangent`` also K and R (72, 72), by ngauss^3 Gauss points."""
    edot = np.asarray(edot, dtype=float)
    xi, eta, z, w = _points(L, W, H, 1.0, None, ngauss, ngauss)   # w: volume, m^3
    D = elasticity(E, nu)
    G = shape_gradient(xi, eta, z, L, W)
    F, eps = _kinematics(e, G, L, W)
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


def internal_force(e, edot, L, W, H, E, nu, alpha=0.0, *, ngauss=NGAUSS) -> np.ndarray:
    """The generalised internal force Q(e, e') (72,), N (N m, N m^2 on r_z, r_zz), of the
    section above: e (72,) in m, edot (72,) in m/s, L, W, H in m, E in Pa, nu
    dimensionless, alpha in s (Kelvin-Voigt: sigma = D (eps + alpha eps')).  One
    homogeneous layer; exact for ngauss >= 5.  Chrono's ``ComputeInternalForces`` stores -Q."""
    return _evaluate(e, edot, L, W, H, E, nu, alpha, ngauss, False)


def internal_force_jacobians(e, edot, L, W, H, E, nu, alpha=0.0, *, ngauss=NGAUSS):
    """(K, R) = (dQ/de in N/m, dQ/de' in N s/m), each (72, 72), of ``internal_force``
    (same arguments); Chrono's ``ComputeKRMmatricesGlobal(H, 1, 0, 0)`` and ``(H, 0, 1, 0)``."""
    _, K, R = _evaluate(e, edot, L, W, H, E, nu, alpha, ngauss, True)
    return K, R
