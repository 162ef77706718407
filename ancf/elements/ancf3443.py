"""The ANCF 3443 shell element: shape functions, consistent mass, gravity force.

A flat rectangular shell of length L (m, along x), width W (m, along y) and
thickness H (m, along z, symmetric about the mid-surface): 4 corner nodes, each
carrying the position r and the three gradients r_x, r_y, r_z (the "fully
parameterised" plate of Dmitrochenko & Pogorelov 2003; Project Chrono's
``ChElementShellANCF_3443``, whose ``SetDimensions(lenX, lenY)`` are our (L, W)
and whose ``AddLayer(thickness, ...)`` calls stack up to our H).

Coordinates e (48,), per node ``[r, r_x, r_y, r_z]``, each (x, y, z), nodes in
the order A (-1, -1), B (1, -1), C (1, 1), D (-1, 1) of (xi_i, eta_i):

    e = [r_A, r_x,A, r_y,A, r_z,A, r_B, ..., r_z,D]

Compact index of a scalar shape function: 4 * node + (0: r, 1: r_x, 2: r_y, 3: r_z).
The position of the material point is r = S(xi, eta, z) e with S = [s_1 I_3, ...,
s_16 I_3] (3, 48), in the reference coordinates xi = 2x/L - 1, eta = 2y/W - 1 in
[-1, 1] and the distance z (m) from the mid-surface, z in [-H/2, H/2].  For node i,
with a = xi_i xi, b = eta_i eta:

    s_r  = (1 + a)(1 + b)(2 + a + b - xi^2 - eta^2) / 8
    s_rx = -L xi_i  (1 + a)^2 (1 - a)(1 + b) / 16
    s_ry = -W eta_i (1 + b)^2 (1 - b)(1 + a) / 16
    s_rz = z (1 + a)(1 + b) / 4

i.e. the incomplete-cubic (non-conforming) plate interpolation of the mid-surface
position and its in-plane slopes, plus the bilinearly interpolated transverse
gradient times z.  Equations:

    M   = int_V rho S^T S dV        (48, 48), kg (kg m, kg m^2 on gradient entries)
    Q_g = int_V rho S^T g dV        (48,),   N  (N m on gradient entries)

with dV = (L/2)(W/2) dxi deta dz for this flat, undistorted reference shape.  Both
are M = m (x) I_3 and Q_g = q (x) g over the 16 scalar functions (m_ij = int rho
s_i s_j dV, q_i = int rho s_i dV).  Through the thickness the integral is a sum
over layers (thickness t_k, density rho_k, stacked from z = -H/2 upward), as in
Chrono's layered shell; a single layer is the homogeneous plate.  s_i s_j has
degree 6 in xi, eta and 2 in z, so 4 in-plane and 2 through-thickness Gauss points
integrate M exactly (Chrono uses 7 x 7 x 3, for distorted reference shapes too);
s_i has degree 3 and 1, so 2 x 2 x 1 points suffice for Q_g.

Internal force (``internal_force``, ``internal_force_jacobians``) and the layer
material (``elasticity``, ``orthotropic``, ``rotate_about_z``): see their section below;
the reference is the flat plate on [0, L] x [0, W] with identity gradients
(``reference_coordinates``).
"""
from __future__ import annotations

import numpy as np

NNODE = 4
NSHAPE = 16  # scalar shape functions, 4 per node
NDOF = 48    # 3 * NSHAPE coordinates
NODE_XI = np.array([-1.0, 1.0, 1.0, -1.0])   # xi_i of nodes A, B, C, D
NODE_ETA = np.array([-1.0, -1.0, 1.0, 1.0])  # eta_i


def scalar_shape(xi, eta, z, L: float, W: float) -> np.ndarray:
    """The 16 scalar shape functions (module docstring) at xi, eta in [-1, 1] and
    z (m) from the mid-surface; arrays broadcast, result (..., 16) ordered
    4 * node + (r, r_x, r_y, r_z).  s_r is dimensionless, the others in m."""
    xi, eta, z = np.broadcast_arrays(*(np.asarray(v, dtype=float) for v in (xi, eta, z)))
    xi, eta, z = xi[..., None], eta[..., None], z[..., None]   # broadcast over the 4 nodes
    a, b = NODE_XI * xi, NODE_ETA * eta
    s_r = (1 + a) * (1 + b) * (2 + a + b - xi**2 - eta**2) / 8
    s_rx = -L * NODE_XI * (1 + a) ** 2 * (1 - a) * (1 + b) / 16
    s_ry = -W * NODE_ETA * (1 + b) ** 2 * (1 - b) * (1 + a) / 16
    s_rz = z * (1 + a) * (1 + b) / 4
    s = np.stack([s_r, s_rx, s_ry, s_rz], axis=-1)             # (..., node, kind)
    return s.reshape(s.shape[:-2] + (NSHAPE,))


def shape(xi: float, eta: float, z: float, L: float, W: float) -> np.ndarray:
    """The shape-function matrix S (3, 48) at one point: S = [s_1 I_3, ..., s_16 I_3],
    so that r(xi, eta, z) = S e with e ordered per node [r, r_x, r_y, r_z]."""
    return np.kron(scalar_shape(xi, eta, z, L, W).reshape(1, NSHAPE), np.eye(3))


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
                n_plane: int = 4, n_thick: int = 2) -> np.ndarray:
    """The compact mass m_ij = int_V rho s_i s_j dV (16, 16), kg; M = m (x) I_3.
    ``layers`` = [(t_k, rho_k), ...] from the bottom face up (default one layer);
    exact for n_plane >= 4, n_thick >= 2."""
    xi, eta, z, w = _points(L, W, H, rho, layers, n_plane, n_thick)
    s = scalar_shape(xi, eta, z, L, W)
    return np.einsum("q,qi,qj->ij", w, s, s)


def mass_matrix(L: float, W: float, H: float, rho: float, layers=None,
                n_plane: int = 4, n_thick: int = 2) -> np.ndarray:
    """The consistent mass matrix M = int_V rho S^T S dV (48, 48); L, W, H in m,
    rho in kg/m^3.  Exact for n_plane >= 4, n_thick >= 2."""
    return np.kron(scalar_mass(L, W, H, rho, layers, n_plane, n_thick), np.eye(3))


def gravity(L: float, W: float, H: float, rho: float, g, layers=None,
            n_plane: int = 2, n_thick: int = 1) -> np.ndarray:
    """The generalised gravity force Q_g = int_V rho S^T g dV (48,), N (N m on the
    gradient entries), for the acceleration g (3,) in m/s^2, e.g. (0, 0, -9.80665).
    Exact for n_plane >= 2, n_thick >= 1."""
    xi, eta, z, w = _points(L, W, H, rho, layers, n_plane, n_thick)
    q = w @ scalar_shape(xi, eta, z, L, W)               # int rho s_i dV, (16,)
    return np.kron(q, np.asarray(g, dtype=float).reshape(3))


# ----------------------------------------------------------------------------------------
# Internal force: Green-Lagrange strain, a 3D (orthotropic) St Venant-Kirchhoff law per
# layer, Kelvin-Voigt damping; no Poisson split and no shear correction.
#
#   F = dr/dX = I + (e - e0) G,  G_aJ = ds_a/dX_J, X = (x, y, z) = (L(1+xi)/2, W(1+eta)/2, z)
#   eps = [E11, E22, E33, 2E23, 2E13, 2E12],  E = (F^T F - I)/2   (Voigt, dimensionless)
#   sigma = D_k (eps + alpha deps/dt),  deps/dt = B(F) de/dt       (2nd Piola-Kirchhoff, Pa)
#   Q = int_V B(F)^T sigma dV                                      (48,), N (N m on gradients)
#   K = dQ/de = int B^T D (B + alpha B(F')) + (G S G^T) (x) I_3 dV,  R = dQ/de' = alpha int B^T D B dV
#
# D_k is the layer's full 6 x 6 stiffness (Chrono's ChMaterialShellANCF, one matrix over
# the whole volume).  Exact Gauss rules: the integrands have degree <= 12 in xi and eta
# and 4 in z, so 7 x 7 in-plane and 3 through-thickness points (per layer); Chrono's
# element uses 4 x 4 x 2, its stored reference data are exact.  Q is the elastic + viscous
# force of M e'' + Q(e, e') = Q_ext; Chrono's ComputeInternalForces returns -Q.
# ----------------------------------------------------------------------------------------

N_PLANE, N_THICK = 7, 3  # exact Gauss points in-plane (per direction) and per layer
_VOIGT = [(0, 0), (1, 1), (2, 2), (1, 2), (0, 2), (0, 1)]
_TENSOR = np.array([[0, 5, 4], [5, 1, 3], [4, 3, 2]])   # Voigt index of S_IJ


def orthotropic(E, nu, G) -> np.ndarray:
    """The 3D orthotropic stiffness D (6, 6), Pa, Voigt order [11, 22, 33, 23, 13, 12]
    (engineering shears), as the inverse of the compliance: E = (E_x, E_y, E_z) in Pa,
    nu = (nu_xy, nu_xz, nu_yz) with nu_ji = nu_ij E_j / E_i, G = (G_xy, G_xz, G_yz) in Pa
    (the arguments of Chrono's orthotropic ``ChMaterialShellANCF``)."""
    (Ex, Ey, Ez), (nxy, nxz, nyz), (Gxy, Gxz, Gyz) = E, nu, G
    C = np.diag([1 / Ex, 1 / Ey, 1 / Ez])
    C[0, 1] = C[1, 0] = -nxy / Ex
    C[0, 2] = C[2, 0] = -nxz / Ex
    C[1, 2] = C[2, 1] = -nyz / Ey
    D = np.zeros((6, 6))
    D[:3, :3] = np.linalg.inv(C)
    D[3:, 3:] = np.diag([Gyz, Gxz, Gxy])
    return D


def elasticity(E: float, nu: float) -> np.ndarray:
    """The isotropic D (6, 6), Pa, order [11, 22, 33, 23, 13, 12]: lambda + 2 mu on the
    diagonal normal block, lambda off it, mu = E/(2(1+nu)) on the shears
    (Chrono's isotropic ``ChMaterialShellANCF(rho, E, nu)``)."""
    mu = E / (2.0 * (1.0 + nu))
    lam = E * nu / ((1.0 + nu) * (1.0 - 2.0 * nu))
    D = np.diag([2 * mu] * 3 + [mu] * 3)
    D[:3, :3] += lam
    return D


def rotate_about_z(D: np.ndarray, theta: float) -> np.ndarray:
    """D (6, 6) of a layer whose material axes 1, 2 are turned by theta (rad) about z
    from the element's x, y (1 along (cos theta, sin theta, 0)): D_elem = T D T^T with
    T the stress transformation sigma_elem = T sigma_mat (order [11, 22, 33, 23, 13, 12]).
    Chrono's 3443 (``RotateReorderStiffnessMatrix``) equals rotate_about_z(D, -theta) on the
    normal/in-plane-shear block but rotate_about_z(D, +theta) on the (23, 13) block: the
    same for isotropic layers or G_xz = G_yz, or theta = 0 (its stored data); unchecked else."""
    c, s = np.cos(theta), np.sin(theta)
    Rm = np.array([[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]])  # columns: material axes
    T = np.array([[Rm[i, k] * Rm[j, l] + (Rm[i, l] * Rm[j, k] if k != l else 0.0)
                   for k, l in _VOIGT] for i, j in _VOIGT])
    return T @ D @ T.T


def reference_coordinates(L: float, W: float) -> np.ndarray:
    """e0 (48,): the flat plate with corners A (0,0,0), B (L,0,0), C (L,W,0), D (0,W,0)
    and r_x, r_y, r_z = the unit axes at every node."""
    corners = [(0, 0), (L, 0), (L, W), (0, W)]
    return np.concatenate([[x, y, 0.0, 1, 0, 0, 0, 1, 0, 0, 0, 1] for x, y in corners]).astype(float)


def shape_gradient(xi, eta, z, L: float, W: float) -> np.ndarray:
    """G_aJ = ds_a/dX_J (..., 16, 3) at xi, eta in [-1, 1], z (m), X = (x, y, z) with
    dx = L dxi / 2, dy = W deta / 2 (the derivatives of ``scalar_shape``); 1/m for s_r,
    dimensionless for s_rx, s_ry, s_rz except ds_rz/dx, ds_rz/dy (m/m = 1) too."""
    xi, eta, z = np.broadcast_arrays(*(np.asarray(v, dtype=float) for v in (xi, eta, z)))
    xi, eta, z = xi[..., None], eta[..., None], z[..., None]
    a, b = NODE_XI * xi, NODE_ETA * eta
    q, o = 2 + a + b - xi**2 - eta**2, np.zeros_like(a)
    d_xi = [(NODE_XI * (1 + b) * q + (1 + a) * (1 + b) * (NODE_XI - 2 * xi)) / 8,
            -L * (1 + a) * (1 - 3 * a) * (1 + b) / 16,
            -W * NODE_XI * NODE_ETA * (1 + b) ** 2 * (1 - b) / 16,
            z * NODE_XI * (1 + b) / 4]
    d_eta = [(NODE_ETA * (1 + a) * q + (1 + a) * (1 + b) * (NODE_ETA - 2 * eta)) / 8,
             -L * NODE_XI * NODE_ETA * (1 + a) ** 2 * (1 - a) / 16,
             -W * (1 + b) * (1 - 3 * b) * (1 + a) / 16,
             z * NODE_ETA * (1 + a) / 4]
    d_z = [o, o, o, (1 + a) * (1 + b) / 4]
    cols = [np.stack(d, axis=-1).reshape(a.shape[:-1] + (NSHAPE,)) * f
            for d, f in ((d_xi, 2 / L), (d_eta, 2 / W), (d_z, 1.0))]
    return np.stack(cols, axis=-1)


def _strain_matrix(F: np.ndarray, G: np.ndarray) -> np.ndarray:
    """B (nq, 6, 48) with d(eps)/dt = B(F) de/dt: row (I, J) = F_kI G_aJ + F_kJ G_aI
    (halved for I = J) at column 3a + k."""
    P = np.einsum("qkI,qaJ->qIJak", F, G)
    rows = [P[:, i, j] + P[:, j, i] if i != j else P[:, i, i] for i, j in _VOIGT]
    return np.stack(rows, axis=1).reshape(F.shape[0], 6, NDOF)


def _layer_rule(L, W, H, layers, n_plane, n_thick):
    """[(D_k, xi, eta, z, w)] per layer, w = dV (m^3) of a tensor Gauss rule; ``layers`` =
    [(t_k, D_k), ...] from z = -H/2 upward (their thicknesses must add up to H)."""
    _layers(H, 1.0, [(t, 1.0) for t, _ in layers])     # checks that the t_k add up to H
    out, z0 = [], -H / 2
    for t, D in layers:
        xi, eta, z, w = _points(L, W, t, 1.0, None, n_plane, n_thick)
        out.append((np.asarray(D, dtype=float), xi, eta, z + z0 + t / 2, w))
        z0 += t
    return out


def _layer(e, edot, L, W, D, alpha, pts, tangent):
    """Q (48,) of one layer and, if ``tangent``, K and R (48, 48) (section equations)."""
    xi, eta, z, w = pts
    G = shape_gradient(xi, eta, z, L, W)
    U = (np.asarray(e, dtype=float) - reference_coordinates(L, W)).reshape(NSHAPE, 3)
    Hu = np.einsum("ak,qaJ->qkJ", U, G)                  # displacement gradient
    Et = 0.5 * (Hu + np.swapaxes(Hu, 1, 2) + np.einsum("qkI,qkJ->qIJ", Hu, Hu))
    eps = np.stack([Et[:, i, j] * (1.0 if i == j else 2.0) for i, j in _VOIGT], axis=1)
    B = _strain_matrix(np.eye(3) + Hu, G)
    edot = np.asarray(edot, dtype=float)
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


def internal_force(e, edot, L, W, H, D, alpha=0.0, *, layers=None,
                   n_plane=N_PLANE, n_thick=N_THICK) -> np.ndarray:
    """The generalised internal force Q(e, e') (48,), N (N m on gradient entries): e (48,)
    in m, edot (48,) in m/s, L, W, H in m, D (6, 6) in Pa (``elasticity``, ``orthotropic``,
    ``rotate_about_z``), alpha in s (sigma = D (eps + alpha eps')); ``layers`` =
    [(t_k, D_k), ...] replaces (H, D).  Exact for n_plane >= 7, n_thick >= 3;
    Chrono's ``ComputeInternalForces`` stores -Q."""
    layers = [(H, D)] if layers is None else layers
    return sum(_layer(e, edot, L, W, Dk, alpha, pts, False)
               for Dk, *pts in _layer_rule(L, W, H, layers, n_plane, n_thick))


def internal_force_jacobians(e, edot, L, W, H, D, alpha=0.0, *, layers=None,
                             n_plane=N_PLANE, n_thick=N_THICK):
    """(K, R) = (dQ/de in N/m, dQ/de' in N s/m), each (48, 48), of ``internal_force``
    (same arguments); Chrono's ``ComputeKRMmatricesGlobal(H, 1, 0, 0)`` and ``(H, 0, 1, 0)``."""
    layers = [(H, D)] if layers is None else layers
    K, R = np.zeros((NDOF, NDOF)), np.zeros((NDOF, NDOF))
    for Dk, *pts in _layer_rule(L, W, H, layers, n_plane, n_thick):
        _, k, r = _layer(e, edot, L, W, Dk, alpha, pts, True)
        K, R = K + k, R + r
    return K, R
