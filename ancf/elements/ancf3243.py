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

with dV = L H W dxi deta dzeta (``continuum3d``, eqs. (1)-(3)), evaluated by tensor
Gauss-Legendre quadrature.
s_i s_j has degree 6 in xi and 2 in eta, zeta, so ``ngauss >= 4`` points per
direction integrate M exactly; S^T g has degree 3 in xi and 1 in eta, zeta,
so 2 points per direction integrate Q_g exactly.

Internal force (``internal_force``, ``internal_force_jacobians``): see their section
below; the reference configuration is the straight beam along x with identity
gradients (``reference_coordinates``).
"""
from __future__ import annotations

import numpy as np

from . import continuum3d as c3
from .material import isotropic_3d

NSHAPE = 8   # scalar shape functions
NDOF = 24    # 3 * NSHAPE coordinates


def _coords(*v):
    """xi, eta, zeta as float arrays broadcast to one shape."""
    return np.broadcast_arrays(*(np.asarray(a, dtype=float) for a in v))


def scalar_shape(xi, eta, zeta, L: float, H: float, W: float) -> np.ndarray:
    """The 8 scalar shape functions s_1..s_8 (module docstring) at xi = x/L in [0, 1],
    eta = y/H, zeta = z/W in [-1/2, 1/2]; arrays broadcast, result (..., 8).
    s_1, s_5, s_3, s_4, s_7, s_8 are dimensionless; s_2, s_6 in m (times a gradient)."""
    xi, eta, zeta = _coords(xi, eta, zeta)
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


def natural_gradient(xi, eta, zeta, L: float, H: float, W: float) -> np.ndarray:
    """ds_a/d(xi, eta, zeta) (..., 8, 3), in the units of s_a times m (the derivatives of
    ``scalar_shape`` in its reference coordinates)."""
    xi, eta, zeta = _coords(xi, eta, zeta)
    y, z, o = H * eta, W * zeta, np.zeros_like(xi)
    h = 6.0 * (xi**2 - xi)
    dxi = [h, L * (1 - 4 * xi + 3 * xi**2), -y, -z, -h, L * (3 * xi**2 - 2 * xi), y, z]
    deta = [o, o, H * (1.0 - xi), o, o, o, H * xi, o]
    dzeta = [o, o, o, W * (1.0 - xi), o, o, o, W * xi]
    return np.stack([np.stack(d, axis=-1) for d in (dxi, deta, dzeta)], axis=-1)


def shape(xi: float, eta: float, zeta: float, L: float, H: float, W: float) -> np.ndarray:
    """The shape-function matrix S (3, 24) at one point: S = [s_1 I_3, ..., s_8 I_3],
    so that r(xi, eta, zeta) = S e with e ordered per node [r, r_x, r_y, r_z]."""
    s = scalar_shape(xi, eta, zeta, L, H, W)
    return np.kron(s.reshape(1, NSHAPE), np.eye(3))


def reference_coordinates(L: float) -> np.ndarray:
    """e0 (24,): the straight beam from (0, 0, 0) to (L, 0, 0) with r_x, r_y, r_z = I."""
    node = lambda x: [x, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0]
    return np.array(node(0.0) + node(L))


def basis(L: float, H: float, W: float) -> c3.Basis:
    """The element's basis for ``continuum3d`` (natural points (xi, eta, zeta))."""
    return c3.Basis(lambda p: scalar_shape(*p.T, L, H, W),
                    lambda p: natural_gradient(*p.T, L, H, W), reference_coordinates(L))


def shape_gradient(xi, eta, zeta, L: float, H: float, W: float) -> np.ndarray:
    """G_aJ = ds_a/dX_J (..., 8, 3), 1/m for s_1, s_5, dimensionless otherwise; X = (x, y, z)
    = (L xi, H eta, W zeta) in the straight reference (``continuum3d`` eq. (2))."""
    return c3.physical_gradient(natural_gradient(xi, eta, zeta, L, H, W),
                                reference_coordinates(L))[0]


def rule(naxis: int, nsection: int | None = None):
    """Tensor Gauss rule on the reference box [0, 1] x [-1/2, 1/2]^2: ``naxis`` points
    along xi, ``nsection`` (default ``naxis``) per section direction, nsection = 1 being
    the beam axis eta = zeta = 0; points (nq, 3) and weights summing to 1."""
    ns = naxis if nsection is None else nsection
    return c3.gauss_box((naxis, ns, ns), (0.0, -0.5, -0.5), (1.0, 0.5, 0.5))


def scalar_mass(L: float, H: float, W: float, rho: float, ngauss: int = 4) -> np.ndarray:
    """The compact mass m_ij = int_V rho s_i s_j dV (8, 8), kg; M = m (x) I_3.
    Exact for ``ngauss >= 4`` (degree 6 along the axis)."""
    return c3.scalar_mass(basis(L, H, W), [(rho, *rule(ngauss))])


def mass_matrix(L: float, H: float, W: float, rho: float, ngauss: int = 4) -> np.ndarray:
    """The consistent mass matrix M = int_V rho S^T S dV (24, 24) by ``ngauss``
    Gauss points per direction (exact for ngauss >= 4); L, H, W in m, rho in kg/m^3."""
    return np.kron(scalar_mass(L, H, W, rho, ngauss), np.eye(3))


def gravity(L: float, H: float, W: float, rho: float, g, ngauss: int = 2) -> np.ndarray:
    """The generalised gravity force Q_g = int_V rho S^T g dV (24,), N (N m on the
    gradient entries), for the acceleration g (3,) in m/s^2, e.g. (0, 0, -9.80665).
    Exact for ngauss >= 2 (degree 3 along the axis)."""
    return c3.gravity(basis(L, H, W), [(rho, *rule(ngauss))], g)


# ----------------------------------------------------------------------------------------
# Internal force: ``continuum3d`` (Green-Lagrange strain, Kelvin-Voigt stress
# sigma = D (eps + alpha eps'), Q = int B^T sigma dV, exact K and R) with a St Venant-
# Kirchhoff material with Timoshenko shear correction and the Poisson effect on the axis:
#
# D = D0 + Dv (Nachbagauer, Gruber & Gerstmayr 2012, "enhanced continuum mechanics"):
# D0 = diag(E, E, E, G, k1 G, k2 G) is integrated over the volume; Dv, the Poisson part
# (the upper 3x3 block lambda + 2G delta_ij - E delta_ij, lambda = E nu/((1+nu)(1-2nu))),
# only on the beam axis eta = zeta = 0 times the area H W (against the Poisson locking
# of the linear section field).  Exact Gauss rules: the integrands have degree 8 in xi
# (5 points) and 4 in eta, zeta (3 points); Chrono's element uses 3 points along xi,
# its stored reference data are exact.  Chrono's ComputeInternalForces returns -Q.
# ----------------------------------------------------------------------------------------

NAXIS, NSECTION = 5, 3   # exact Gauss points along xi and per section direction


def elasticity(E: float, nu: float, k1: float, k2: float):
    """(D0, Dv), each (6, 6) in Pa, Voigt order [11, 22, 33, 23, 13, 12]: D0 =
    diag(E, E, E, G, k1 G, k2 G) with G = E/(2(1+nu)) (k1 scales the xz shear 2E13, k2
    the xy shear 2E12), Dv the Poisson part, so D0 + Dv is the isotropic 3D law."""
    G = E / (2.0 * (1.0 + nu))
    D0 = np.diag([E, E, E, G, k1 * G, k2 * G])
    Dv = isotropic_3d(E, nu) - np.diag([E, E, E, G, G, G])
    Dv[3:, 3:] = 0.0
    return D0, Dv


def poisson_rules(E, nu, k1, k2, split_poisson=True, naxis=NAXIS):
    """The beams' constitutive parts [(D, points, weights)] for ``continuum3d``: D0 over
    the volume (naxis x NSECTION^2 points) and Dv on the axis (naxis x 1 x 1), or
    (split_poisson=False) the whole D0 + Dv over the volume.  Also used by ``ancf3333``."""
    D0, Dv = elasticity(E, nu, k1, k2)
    if not split_poisson:
        return [(D0 + Dv, *rule(naxis, NSECTION))]
    return [(D0, *rule(naxis, NSECTION)), (Dv, *rule(naxis, 1))]


def continuum(L, H, W, E, nu, k1, k2, *, split_poisson=True, naxis=NAXIS):
    """(basis, rules) of ``continuum3d`` for ``internal_force`` (same arguments
    after e, edot; no alpha): the element's basis and its constitutive parts."""
    return basis(L, H, W), poisson_rules(E, nu, k1, k2, split_poisson, naxis)


def internal_force(e, edot, L, H, W, E, nu, k1, k2, alpha=0.0, *,
                   split_poisson=True, naxis=NAXIS) -> np.ndarray:
    """The generalised internal force Q(e, e') (24,), N (N m on gradient entries), of the
    section above: e (24,) in m, edot (24,) in m/s, L, H, W in m, E in Pa, nu, k1, k2
    dimensionless, alpha in s (Kelvin-Voigt: sigma = D (eps + alpha eps')).  Exact for
    naxis >= 5; Chrono's ``ComputeInternalForces`` stores -Q."""
    kernel = continuum(L, H, W, E, nu, k1, k2, split_poisson=split_poisson, naxis=naxis)
    return c3.internal_force(e, edot, *kernel, alpha)


def internal_force_jacobians(e, edot, L, H, W, E, nu, k1, k2, alpha=0.0, *,
                             split_poisson=True, naxis=NAXIS):
    """(K, R) = (dQ/de in N/m, dQ/de' in N s/m), each (24, 24), of ``internal_force``
    (same arguments); Chrono's ``ComputeKRMmatricesGlobal(H, 1, 0, 0)`` and ``(H, 0, 1, 0)``."""
    kernel = continuum(L, H, W, E, nu, k1, k2, split_poisson=split_poisson, naxis=naxis)
    return c3.internal_force_jacobians(e, edot, *kernel, alpha)
