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
