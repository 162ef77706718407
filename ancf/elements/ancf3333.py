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

with dV = L H W dxi deta dzeta (``continuum3d``, eqs. (1)-(3)), evaluated by tensor
Gauss-Legendre quadrature on the reference box of ``ancf3243.rule``.
s_i s_j has degree 4 in xi and 2 in eta, zeta, so ``ngauss >= 3`` points per
direction integrate M exactly; S^T g has degree 2 in xi and 1 in eta, zeta, so
2 points per direction integrate Q_g exactly.

Internal force (``internal_force``, ``internal_force_jacobians``): see their section
below; the reference configuration is the straight beam along x with r_y, r_z = e_y, e_z
at every node (``reference_coordinates``).
"""
from __future__ import annotations

import numpy as np

from . import continuum3d as c3
# the beams' shared material and rule (NSECTION, elasticity re-exported for callers)
from .ancf3243 import NAXIS, NSECTION, elasticity, poisson_rules, rule  # noqa: F401

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


def _section(n, *fields):
    """(..., 9): the node functions n (..., 3) times the section fields (..., 3)."""
    section = np.stack(fields, axis=-1)
    return (n[..., :, None] * section[..., None, :]).reshape(*n.shape[:-1], NSHAPE)


def scalar_shape(xi, eta, zeta, L: float, H: float, W: float) -> np.ndarray:
    """The 9 scalar shape functions s_1..s_9 (module docstring) at xi = x/L in [0, 1],
    eta = y/H, zeta = z/W in [-1/2, 1/2]; arrays broadcast, result (..., 9).
    s_1, s_4, s_7 are dimensionless; the others in m (times a section gradient).
    L is not used: a Lagrange interpolation carries no axial gradient."""
    xi, eta, zeta = np.broadcast_arrays(*(np.asarray(v, dtype=float) for v in (xi, eta, zeta)))
    return _section(lagrange(xi), np.ones_like(eta), H * eta, W * zeta)


def natural_gradient(xi, eta, zeta, L: float, H: float, W: float) -> np.ndarray:
    """ds_a/d(xi, eta, zeta) (..., 9, 3) (the derivatives of ``scalar_shape``):
    d/dxi = N_k'(xi) [1, y, z], d/deta = N_k [0, H, 0], d/dzeta = N_k [0, 0, W]."""
    xi, eta, zeta = np.broadcast_arrays(*(np.asarray(v, dtype=float) for v in (xi, eta, zeta)))
    n, one, o = lagrange(xi), np.ones_like(xi), np.zeros_like(xi)
    dn = np.stack([4 * xi - 3, 4 * xi - 1, 4 - 8 * xi], axis=-1)
    cols = [_section(dn, one, H * eta, W * zeta), _section(n, o, H * one, o),
            _section(n, o, o, W * one)]
    return np.stack(cols, axis=-1)


def shape(xi: float, eta: float, zeta: float, L: float, H: float, W: float) -> np.ndarray:
    """The shape-function matrix S (3, 27) at one point: S = [s_1 I_3, ..., s_9 I_3],
    so that r(xi, eta, zeta) = S e with e ordered per node [r, r_y, r_z], nodes A, B, C."""
    s = scalar_shape(xi, eta, zeta, L, H, W)
    return np.kron(s.reshape(1, NSHAPE), np.eye(3))


def reference_coordinates(L: float) -> np.ndarray:
    """e0 (27,): the straight beam along x, nodes A, B, C at x = 0, L, L/2 (m) with
    r_y = (0, 1, 0) and r_z = (0, 0, 1)."""
    return np.array([[x * L, 0, 0, 0, 1, 0, 0, 0, 1] for x in NODE_XI], dtype=float).ravel()


def basis(L: float, H: float, W: float) -> c3.Basis:
    """The element's basis for ``continuum3d`` (natural points (xi, eta, zeta))."""
    return c3.Basis(lambda p: scalar_shape(*p.T, L, H, W),
                    lambda p: natural_gradient(*p.T, L, H, W), reference_coordinates(L))


def shape_gradient(xi, eta, zeta, L: float, H: float, W: float) -> np.ndarray:
    """G_aJ = ds_a/dX_J (..., 9, 3), 1/m for s_1, s_4, s_7 and dimensionless otherwise,
    X = (x, y, z) = (L xi, H eta, W zeta) (``continuum3d`` eq. (2))."""
    return c3.physical_gradient(natural_gradient(xi, eta, zeta, L, H, W),
                                reference_coordinates(L))[0]


def scalar_mass(L: float, H: float, W: float, rho: float, ngauss: int = 3) -> np.ndarray:
    """m (9, 9) over the scalar functions, kg (kg m, kg m^2 on r_y, r_z); ``ngauss`` >= 3
    points per direction are exact (degree 4 along the axis, 2 across)."""
    return c3.scalar_mass(basis(L, H, W), [(rho, *rule(ngauss))])


def mass_matrix(L: float, H: float, W: float, rho: float, ngauss: int = 3) -> np.ndarray:
    """M = m (x) I_3 (27, 27) of ``scalar_mass`` (same arguments; L, H, W in m, rho in kg/m^3)."""
    return np.kron(scalar_mass(L, H, W, rho, ngauss), np.eye(3))


def gravity(L: float, H: float, W: float, rho: float, g, ngauss: int = 2) -> np.ndarray:
    """Q_g = q (x) g (27,), N (N m on r_y, r_z), for g (3,) in m/s^2, e.g. (0, 0, -9.80665);
    ``ngauss`` >= 2 is exact (degree 2 along the axis)."""
    return c3.gravity(basis(L, H, W), [(rho, *rule(ngauss))], g)


# ----------------------------------------------------------------------------------------
# Internal force: ``continuum3d`` with the beams' material of ``ancf3243`` (Nachbagauer,
# Gruber & Gerstmayr 2013): D0 = diag(E, E, E, G, k1 G, k2 G) over the volume, the Poisson
# block Dv only on the axis eta = zeta = 0 times the area H W (``ancf3243.poisson_rules``),
# Kelvin-Voigt damping sigma = D (eps + alpha eps').  F has degree 2 in xi and 1 in eta,
# zeta, so the integrands have degree 8 in xi and 4 in eta, zeta: 5 x 3 x 3 Gauss points
# are exact.  Chrono's element uses 3 x 2 x 2 (NP, NT); its stored reference data are
# exact (at their small states the 3-point rule is 3e-8 off K).  Chrono's
# ``ComputeInternalForces`` returns -Q.
# ----------------------------------------------------------------------------------------


def continuum(L, H, W, E, nu, k1, k2, *, split_poisson=True, naxis=NAXIS):
    """(basis, rules) of ``continuum3d`` for ``internal_force`` (same arguments
    after e, edot; no alpha): the element's basis and its constitutive parts."""
    return basis(L, H, W), poisson_rules(E, nu, k1, k2, split_poisson, naxis)


def internal_force(e, edot, L, H, W, E, nu, k1, k2, alpha=0.0, *,
                   split_poisson=True, naxis=NAXIS) -> np.ndarray:
    """Q(e, e') (27,), N (N m on r_y, r_z entries), as ``ancf3243.internal_force`` (the
    same arguments and units) on this element's basis; exact for naxis >= 5.  Chrono
    stores -Q."""
    kernel = continuum(L, H, W, E, nu, k1, k2, split_poisson=split_poisson, naxis=naxis)
    return c3.internal_force(e, edot, *kernel, alpha)


def internal_force_jacobians(e, edot, L, H, W, E, nu, k1, k2, alpha=0.0, *,
                             split_poisson=True, naxis=NAXIS):
    """K = dQ/de (N/m) and R = dQ/de' (N s/m), (27, 27) each, of ``internal_force``."""
    kernel = continuum(L, H, W, E, nu, k1, k2, split_poisson=split_poisson, naxis=naxis)
    return c3.internal_force_jacobians(e, edot, *kernel, alpha)
