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

with dV = (L/2)(W/2) dxi deta dz for this flat, undistorted reference shape (``continuum3d``
eqs. (1)-(3), whose ``layer_boxes`` give the rule).  Both
are M = m (x) I_3 and Q_g = q (x) g over the 16 scalar functions (m_ij = int rho
s_i s_j dV, q_i = int rho s_i dV).  Through the thickness the integral is a sum
over layers (thickness t_k, density rho_k, stacked from z = -H/2 upward), as in
Chrono's layered shell; a single layer is the homogeneous plate.  s_i s_j has
degree 6 in xi, eta and 2 in z, so 4 in-plane and 2 through-thickness Gauss points
integrate M exactly (Chrono uses 7 x 7 x 3, for distorted reference shapes too);
s_i has degree 3 and 1, so 2 x 2 x 1 points suffice for Q_g.

Internal force (``internal_force``, ``internal_force_jacobians``) and the layer
material (``elasticity``, ``orthotropic``, ``rotate_about_z``, from ``material``): see
their section below; the reference is the flat plate on [0, L] x [0, W] with identity
gradients (``reference_coordinates``).

Poisson (thickness) locking and the option ``poisson``.  r_z is constant through the
thickness, so E_33 is too and cannot take the contraction -nu/(1 - nu)(E_11 + E_22) that
bending (linear in z) asks for: the full 3D law bends with the plane-strain modulus, stiffer
than the plate's by (1 - nu)^2/(1 - 2 nu) (1.225 at nu = 0.3).  Chrono offers no remedy for
this element (its ``CantileverTipLoadCheck`` allows 15 %).  ``poisson`` names the law:

    "3d"            D_k over the layer's volume (default: Chrono's element, its data)
    "plane_stress"  D0_k over the volume, with the sigma_33 = 0 condensation
                    D0 = D - D e_3 e_3^T D / D_33 + e_3 e_3^T / C_33,   C = D^-1      (P1)
                    (the in-plane and shear rows condensed; E_33 kept, uncoupled, with
                    the uniaxial modulus E_z = 1/C_33, so r_z keeps its stiffness)
    "split"         D0_k over the volume plus Dv_k = D_k - D0_k on the mid-surface z = 0
                    only, with the weight t_k (the beams' Poisson split, ``ancf3243``,
                    for the plate: the full 3D law on the membrane, D0 in bending)   (P2)

For the isotropic law (P1) is the plane-stress block E/(1 - nu^2) [[1, nu], [nu, 1]], the
shear moduli G and E on E_33; both remedies bend with D = E H^3/(12 (1 - nu^2)).
"""
from __future__ import annotations

import numpy as np

from . import continuum3d as c3
from .material import isotropic_3d as elasticity  # noqa: F401 (the isotropic layer)
from .material import orthotropic_3d as orthotropic  # noqa: F401
from .material import rotate_about_z  # noqa: F401

NNODE = 4
NSHAPE = 16  # scalar shape functions, 4 per node
NDOF = 48    # 3 * NSHAPE coordinates
NODE_XI = np.array([-1.0, 1.0, 1.0, -1.0])   # xi_i of nodes A, B, C, D
NODE_ETA = np.array([-1.0, -1.0, 1.0, 1.0])  # eta_i


def _per_node(xi, eta, z):
    """xi, eta, z as float arrays (..., 1) broadcast over the 4 nodes, and a, b."""
    xi, eta, z = np.broadcast_arrays(*(np.asarray(v, dtype=float) for v in (xi, eta, z)))
    xi, eta, z = xi[..., None], eta[..., None], z[..., None]
    return xi, eta, z, NODE_XI * xi, NODE_ETA * eta


def _compact(kinds):
    """(..., 16) ordered 4 * node + kind from the list of the 4 kinds, each (..., 4)."""
    s = np.stack(kinds, axis=-1)                               # (..., node, kind)
    return s.reshape(s.shape[:-2] + (NSHAPE,))


def scalar_shape(xi, eta, z, L: float, W: float) -> np.ndarray:
    """The 16 scalar shape functions (module docstring) at xi, eta in [-1, 1] and
    z (m) from the mid-surface; arrays broadcast, result (..., 16) ordered
    4 * node + (r, r_x, r_y, r_z).  s_r is dimensionless, the others in m."""
    xi, eta, z, a, b = _per_node(xi, eta, z)
    return _compact([(1 + a) * (1 + b) * (2 + a + b - xi**2 - eta**2) / 8,
                     -L * NODE_XI * (1 + a) ** 2 * (1 - a) * (1 + b) / 16,
                     -W * NODE_ETA * (1 + b) ** 2 * (1 - b) * (1 + a) / 16,
                     z * (1 + a) * (1 + b) / 4])


def natural_gradient(xi, eta, z, L: float, W: float) -> np.ndarray:
    """ds_a/d(xi, eta, z) (..., 16, 3) (the derivatives of ``scalar_shape``)."""
    xi, eta, z, a, b = _per_node(xi, eta, z)
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
    return np.stack([_compact(d) for d in (d_xi, d_eta, d_z)], axis=-1)


def shape(xi: float, eta: float, z: float, L: float, W: float) -> np.ndarray:
    """The shape-function matrix S (3, 48) at one point: S = [s_1 I_3, ..., s_16 I_3],
    so that r(xi, eta, z) = S e with e ordered per node [r, r_x, r_y, r_z]."""
    return np.kron(scalar_shape(xi, eta, z, L, W).reshape(1, NSHAPE), np.eye(3))


def reference_coordinates(L: float, W: float) -> np.ndarray:
    """e0 (48,): the flat plate with corners A (0,0,0), B (L,0,0), C (L,W,0), D (0,W,0)
    and r_x, r_y, r_z = the unit axes at every node."""
    corners = [(0, 0), (L, 0), (L, W), (0, W)]
    return np.concatenate([[x, y, 0.0, 1, 0, 0, 0, 1, 0, 0, 0, 1] for x, y in corners]).astype(float)


def basis(L: float, W: float) -> c3.Basis:
    """The element's basis for ``continuum3d`` (natural points (xi, eta, z))."""
    return c3.Basis(lambda p: scalar_shape(*p.T, L, W), lambda p: natural_gradient(*p.T, L, W),
                    reference_coordinates(L, W))


def shape_gradient(xi, eta, z, L: float, W: float) -> np.ndarray:
    """G_aJ = ds_a/dX_J (..., 16, 3) at xi, eta in [-1, 1], z (m), X = (x, y, z) with
    dx = L dxi / 2, dy = W deta / 2 (``continuum3d`` eq. (2)); 1/m for s_r,
    dimensionless for s_rx, s_ry, s_rz."""
    return c3.physical_gradient(natural_gradient(xi, eta, z, L, W), reference_coordinates(L, W))[0]


def scalar_mass(L: float, W: float, H: float, rho: float, layers=None,
                n_plane: int = 4, n_thick: int = 2) -> np.ndarray:
    """The compact mass m_ij = int_V rho s_i s_j dV (16, 16), kg; M = m (x) I_3.
    ``layers`` = [(t_k, rho_k), ...] from the bottom face up (default one layer);
    exact for n_plane >= 4, n_thick >= 2."""
    rules = c3.layer_boxes(H, layers, rho, n_plane, n_thick)
    return c3.scalar_mass(basis(L, W), rules)


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
    return c3.gravity(basis(L, W), c3.layer_boxes(H, layers, rho, n_plane, n_thick), g)


# ----------------------------------------------------------------------------------------
# Internal force: ``continuum3d`` (Green-Lagrange strain, Kelvin-Voigt stress
# sigma = D_k (eps + alpha eps'), Q = int B^T sigma dV, exact K and R) with a 3D
# (orthotropic) St Venant-Kirchhoff law per layer; no shear correction.  By default D_k is
# the layer's full 6 x 6 stiffness (Chrono's ChMaterialShellANCF, one matrix over the
# whole volume); ``poisson`` selects a remedy for the Poisson locking (module docstring,
# eqs. (P1)-(P2); ``poisson_rules``).  Exact Gauss rules: the integrands have degree
# <= 12 in xi and eta and 4 in z, so 7 x 7 in-plane and 3 through-thickness points (per
# layer; the split's mid-surface part 7 x 7 x 1); Chrono's element uses 4 x 4 x 2, its
# stored reference data are exact.  Chrono's ComputeInternalForces returns -Q.
# ----------------------------------------------------------------------------------------

N_PLANE, N_THICK = 7, 3  # exact Gauss points in-plane (per direction) and per layer
POISSON = ("3d", "plane_stress", "split")  # the values of ``poisson`` (module docstring)


def plane_stress(D: np.ndarray) -> np.ndarray:
    """Eq. (P1): D0 (6, 6), Pa, the sigma_33 = 0 condensation of D (6, 6, Pa, Voigt order
    [11, 22, 33, 23, 13, 12]) with E_33 kept uncoupled at the modulus 1/C_33, C = D^-1."""
    D = np.asarray(D, dtype=float)
    D0 = D - np.outer(D[:, 2], D[2, :]) / D[2, 2]
    D0[2, 2] = 1.0 / np.linalg.inv(D)[2, 2]
    return D0


def poisson_rules(H, D, layers=None, poisson="3d", n_plane=N_PLANE, n_thick=N_THICK):
    """The constitutive parts [(D, points, weights)] for ``continuum3d`` of the layers
    ``layers`` = [(t_k, D_k), ...] (or the one layer (H, D)) under the law ``poisson``:
    "3d" D_k per layer; "plane_stress" (P1) per layer; "split" (P1) per layer plus
    D_k - D0_k at z = 0 with the weight t_k (n_plane^2 x 1 points)."""
    if poisson not in POISSON:
        raise ValueError(f"poisson must be one of {POISSON} (got {poisson!r})")
    if poisson == "3d":
        return c3.layer_boxes(H, layers, D, n_plane, n_thick)
    layers = [(H, D)] if layers is None else layers
    condensed = [(t, plane_stress(Dk)) for t, Dk in layers]
    rules = c3.layer_boxes(H, condensed, None, n_plane, n_thick)
    if poisson == "split":
        rules += [(np.asarray(Dk, dtype=float) - D0,
                   *c3.gauss_box((n_plane, n_plane, 1), (-1, -1, -t / 2), (1, 1, t / 2)))
                  for (t, Dk), (_, D0) in zip(layers, condensed)]
    return rules


def continuum(L, W, H, D, *, layers=None, poisson="3d", n_plane=N_PLANE, n_thick=N_THICK):
    """(basis, rules) of ``continuum3d`` for ``internal_force`` (same arguments
    after e, edot; no alpha): the element's basis and its constitutive parts."""
    return basis(L, W), poisson_rules(H, D, layers, poisson, n_plane, n_thick)


def internal_force(e, edot, L, W, H, D, alpha=0.0, *, layers=None, poisson="3d",
                   n_plane=N_PLANE, n_thick=N_THICK) -> np.ndarray:
    """The generalised internal force Q(e, e') (48,), N (N m on gradient entries): e (48,)
    in m, edot (48,) in m/s, L, W, H in m, D (6, 6) in Pa (``elasticity``, ``orthotropic``,
    ``rotate_about_z``), alpha in s (sigma = D (eps + alpha eps')); ``layers`` =
    [(t_k, D_k), ...] replaces (H, D); ``poisson`` the law ("3d", Chrono's, or a remedy,
    ``poisson_rules``).  Exact for n_plane >= 7, n_thick >= 3; Chrono's
    ``ComputeInternalForces`` stores -Q (for poisson="3d")."""
    kernel = continuum(L, W, H, D, layers=layers, poisson=poisson, n_plane=n_plane,
                       n_thick=n_thick)
    return c3.internal_force(e, edot, *kernel, alpha)


def internal_force_jacobians(e, edot, L, W, H, D, alpha=0.0, *, layers=None, poisson="3d",
                             n_plane=N_PLANE, n_thick=N_THICK):
    """(K, R) = (dQ/de in N/m, dQ/de' in N s/m), each (48, 48), of ``internal_force``
    (same arguments); Chrono's ``ComputeKRMmatricesGlobal(H, 1, 0, 0)`` and ``(H, 0, 1, 0)``."""
    kernel = continuum(L, W, H, D, layers=layers, poisson=poisson, n_plane=n_plane,
                       n_thick=n_thick)
    return c3.internal_force_jacobians(e, edot, *kernel, alpha)
