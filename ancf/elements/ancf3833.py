"""The ANCF 3833 shell element: shape functions, consistent mass, gravity force.

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
