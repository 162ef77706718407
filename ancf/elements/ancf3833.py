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

with dV = (L/2)(W/2) dxi deta dz for this flat, undistorted reference shape (``continuum3d``
eqs. (1)-(3), whose ``layer_boxes`` give the rule).  Both
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

from . import continuum3d as c3
from .material import isotropic_3d as elasticity  # noqa: F401 (Chrono's isotropic layer)

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


def serendipity_gradient(xi, eta) -> np.ndarray:
    """(dN_i/dxi, dN_i/deta) (..., 8, 2) of ``serendipity``; dimensionless."""
    xi, eta = np.broadcast_arrays(*(np.asarray(v, dtype=float)[..., None] for v in (xi, eta)))
    a, b = NODE_XI * xi, NODE_ETA * eta
    corner = (NODE_XI * (1 + b) * (2 * a + b) / 4, NODE_ETA * (1 + a) * (a + 2 * b) / 4)
    mid_x = (-xi * (1 + b), NODE_ETA * (1 - xi**2) / 2)
    mid_y = (NODE_XI * (1 - eta**2) / 2, -eta * (1 + a))
    return np.stack([np.where(NODE_XI == 0, mx, np.where(NODE_ETA == 0, my, c))
                     for c, mx, my in zip(corner, mid_x, mid_y)], axis=-1)


def natural_gradient(xi, eta, z) -> np.ndarray:
    """ds_a/d(xi, eta, z) (..., 24, 3): per node (dN/dxi, dN/deta, 0), z (dN/dxi,
    dN/deta, N/z) and z^2/2 (dN/dxi, dN/deta, 2N/z) (the derivatives of ``scalar_shape``)."""
    xi, eta, z = np.broadcast_arrays(*(np.asarray(v, dtype=float) for v in (xi, eta, z)))
    n, dn = serendipity(xi, eta), serendipity_gradient(xi, eta)
    dx, dy, z = dn[..., 0], dn[..., 1], z[..., None]
    g = np.stack([np.stack([dx, dy, 0 * n], -1), np.stack([z * dx, z * dy, n], -1),
                  np.stack([z**2 / 2 * dx, z**2 / 2 * dy, z * n], -1)], axis=-2)
    return g.reshape(g.shape[:-3] + (NSHAPE, 3))


def reference_coordinates(L: float, W: float) -> np.ndarray:
    """e0 (72,): the flat L x W plate in z = 0 with corner A at the origin, r_z = (0, 0, 1)
    and r_zz = 0 at every node (Chrono's test setup)."""
    e0 = np.zeros((NNODE, 3, 3))
    e0[:, 0, 0], e0[:, 0, 1] = L * (NODE_XI + 1) / 2, W * (NODE_ETA + 1) / 2
    e0[:, 1, 2] = 1.0
    return e0.ravel()


def basis(L: float, W: float) -> c3.Basis:
    """The element's basis for ``continuum3d`` (natural points (xi, eta, z))."""
    return c3.Basis(lambda p: scalar_shape(*p.T), lambda p: natural_gradient(*p.T),
                    reference_coordinates(L, W))


def shape_gradient(xi, eta, z, L: float, W: float) -> np.ndarray:
    """G_aJ = ds_a/dX_J (..., 24, 3) in the flat reference, X = (x, y, z) = (L (xi + 1)/2,
    W (eta + 1)/2, z) (``continuum3d`` eq. (2)); 1/m on r, dimensionless on r_z, m on r_zz."""
    return c3.physical_gradient(natural_gradient(xi, eta, z), reference_coordinates(L, W))[0]


def scalar_mass(L: float, W: float, H: float, rho: float, layers=None,
                n_plane: int = 3, n_thick: int = 3) -> np.ndarray:
    """m (24, 24) over the scalar functions (kg, kg m^2 and kg m^4 on r_z, r_zz), layered
    as ``layers`` = [(t_k, rho_k), ...] from z = -H/2 up, or homogeneous (None); the
    default 3 x 3 x 3 rule is exact."""
    return c3.scalar_mass(basis(L, W), c3.layer_boxes(H, layers, rho, n_plane, n_thick))


def mass_matrix(L: float, W: float, H: float, rho: float, layers=None,
                n_plane: int = 3, n_thick: int = 3) -> np.ndarray:
    """M = m (x) I_3 (72, 72) of ``scalar_mass`` (same arguments; lengths m, rho kg/m^3)."""
    return np.kron(scalar_mass(L, W, H, rho, layers, n_plane, n_thick), np.eye(3))


def gravity(L: float, W: float, H: float, rho: float, g, layers=None,
            n_plane: int = 2, n_thick: int = 2) -> np.ndarray:
    """Q_g = q (x) g (72,), N (N m, N m^2 on r_z, r_zz), for g (3,) in m/s^2; the default
    2 x 2 x 2 rule is exact (s_i is quadratic in each of xi, eta, z)."""
    return c3.gravity(basis(L, W), c3.layer_boxes(H, layers, rho, n_plane, n_thick), g)


# ----------------------------------------------------------------------------------------
# Internal force: ``continuum3d`` (Green-Lagrange strain, Kelvin-Voigt stress
# sigma = D (eps + alpha eps'), Q = int B^T sigma dV, exact K and R) with the isotropic
# St Venant-Kirchhoff material (the full 3D law over the whole volume, no Poisson split:
# Chrono's ChMaterialShellANCF, one layer with fibre angle 0).  Exact Gauss rules: with
# r_zz free the integrands have degree <= 8 in xi, eta and z, so 5 x 5 x 5 points are
# exact (Chrono's element uses 3 x 3 x 2; its stored reference data are exact).
# Chrono's ComputeInternalForces returns -Q.
# ----------------------------------------------------------------------------------------

NGAUSS = 5   # exact Gauss points per direction (xi, eta, z)


def _rules(H, E, nu, ngauss):
    """One homogeneous isotropic layer, ngauss^3 points."""
    return c3.layer_boxes(H, None, elasticity(E, nu), ngauss, ngauss)


def continuum(L, W, H, E, nu, *, ngauss=NGAUSS):
    """(basis, rules) of ``continuum3d`` for ``internal_force`` (same arguments
    after e, edot; no alpha): the element's basis and its constitutive parts."""
    return basis(L, W), _rules(H, E, nu, ngauss)


def internal_force(e, edot, L, W, H, E, nu, alpha=0.0, *, ngauss=NGAUSS) -> np.ndarray:
    """The generalised internal force Q(e, e') (72,), N (N m, N m^2 on r_z, r_zz), of the
    section above: e (72,) in m, edot (72,) in m/s, L, W, H in m, E in Pa, nu
    dimensionless, alpha in s (Kelvin-Voigt: sigma = D (eps + alpha eps')).  One
    homogeneous layer; exact for ngauss >= 5.  Chrono's ``ComputeInternalForces`` stores -Q."""
    kernel = continuum(L, W, H, E, nu, ngauss=ngauss)
    return c3.internal_force(e, edot, *kernel, alpha)


def internal_force_jacobians(e, edot, L, W, H, E, nu, alpha=0.0, *, ngauss=NGAUSS):
    """(K, R) = (dQ/de in N/m, dQ/de' in N s/m), each (72, 72), of ``internal_force``
    (same arguments); Chrono's ``ComputeKRMmatricesGlobal(H, 1, 0, 0)`` and ``(H, 0, 1, 0)``."""
    kernel = continuum(L, W, H, E, nu, ngauss=ngauss)
    return c3.internal_force_jacobians(e, edot, *kernel, alpha)
