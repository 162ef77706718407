"""The gradient-deficient ANCF cable of Gerstmayr and Shabana (2006), as Project Chrono's
``ChElementCableANCF`` implements it: two nodes, each a position r and one slope r_x
(12 coordinates, order r_A, r_x,A, r_B, r_x,B, each a 3-vector), cubic Hermite shape
functions of the generated family ``cable3d`` (``analytic/shape_functions.py``).

With a = r_x, b = r_xx at a point of the axis (X = xi l, xi in [0, 1]) the axial strain
and the curvature are (Gerstmayr and Shabana 2006, Eqs 17 and 23; Chrono's
``ComputeInternalForces_Impl``)

    eps = (a.a - 1) / 2,    kappa = |a x b| / |a|^3                                    (1)

and the strain energy of an element of length l, section area A, second moment I,

    U = E A l / 2 sum_g w_g eps_g^2 + E I l / 2 sum_h w_h kappa_h^2                     (2)

with Chrono's rules on [0, 1]: 5 Gauss points g for the axial part (exact, the integrand
is a polynomial of degree 8), 3 points h for the bending part (a rational function, so
the rule is part of the element).  Q = dU/de (N) is minus Chrono's internal force; the
tangent K = dQ/de (N/m) is exact (Chrono differentiates Q numerically).  kappa^2 =
|a x b|^2 / (a.a)^3 is smooth where kappa is not (a straight cable), so Eq. (2) is
differentiated through s = kappa^2 = p / q, p = |a x b|^2, q = (a.a)^3.  The straight
reference has eps = kappa = 0, so Chrono's subtraction of the reference force is zero.

Mass: the consistent matrix rho A int S^T S dx of the family (exact).  No damping:
Chrono's optional strain-rate damping (``SetAlphaDamp``) is not modelled.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numba import njit

from ancf.core.quadrature import gauss01
from ancf.elements import basis

NSHAPE, NDOF = 4, 12
AXIAL_POINTS, BENDING_POINTS = 5, 3  # Chrono's Integrate1D orders


@dataclass(frozen=True)
class CircularSection:
    """A solid circular section of diameter ``d`` (m): Chrono's cable section (one
    second moment for both bending planes)."""

    d: float

    @property
    def area(self) -> float:
        return np.pi * self.d**2 / 4.0

    @property
    def second_moment(self) -> float:
        """I = pi d^4 / 64, m^4."""
        return np.pi * self.d**4 / 64.0


def point_rows(l: float, n: int) -> tuple:
    """(weights (n,), S_x (n, 4) 1/m or -, S_xx (n, 4)) of an n-point Gauss rule on
    [0, 1] along an element of length l (m), from the generated family."""
    xi, w = gauss01(n)
    X, zero = xi * l, np.zeros(n)
    return w, basis.cable3d_x(X, zero, zero, l), basis.cable3d_xx(X, zero, zero, l)


@njit(cache=True)
def _cross(u, v):
    return np.array([u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2],
                     u[0] * v[1] - u[1] * v[0]])


@njit(cache=True)
def _skew(u):
    """[u]x: [u]x v = u x v."""
    return np.array([[0.0, -u[2], u[1]], [u[2], 0.0, -u[0]], [-u[1], u[0], 0.0]])


@njit(cache=True)
def _bending_point(a, b, want):
    """s = kappa^2 (Eq. (1)) at a point, its gradient (6,) and, if ``want``, its Hessian
    (6, 6) in (a, b): s = p / q, p = |c|^2, c = a x b, q = (a.a)^3."""
    c = _cross(a, b)
    J = np.zeros((3, 6))
    J[:, :3] = -_skew(b)  # dc/da
    J[:, 3:] = _skew(a)   # dc/db
    p, aa = c @ c, a @ a
    q = aa**3
    dp = 2.0 * (J.T @ c)
    dq = np.zeros(6)
    dq[:3] = 6.0 * aa**2 * a
    s = p / q
    ds = dp / q - p * dq / q**2
    H = np.zeros((6, 6))
    if want:
        d2p = 2.0 * (J.T @ J)
        C = _skew(c)
        d2p[:3, 3:] -= 2.0 * C    # c . (da x db) = da^T (-[c]x) db
        d2p[3:, :3] += 2.0 * C
        d2q = np.zeros((6, 6))
        d2q[:3, :3] = 6.0 * aa**2 * np.eye(3) + 24.0 * aa * np.outer(a, a)
        H = (d2p / q - (np.outer(dp, dq) + np.outer(dq, dp)) / q**2
             + p * (2.0 * np.outer(dq, dq) / q**3 - d2q / q**2))
    return s, ds, H


@njit(cache=True)
def element(e, l, EA, EI, wa, Sa, wb, Sb, Sbb, want, Q, K):
    """Eq. (2) of one element, coordinates e (12,) m: returns U (J), writes Q (12,) N
    and, if ``want``, K (12, 12) N/m.  (wa, Sa): the axial rule's weights and S_x rows,
    (wb, Sb, Sbb) the bending rule's with S_xx."""
    E = e.reshape(NSHAPE, 3)
    Q[:] = 0.0
    if want:
        K[:, :] = 0.0
    U = 0.0
    B = np.zeros((3, NDOF))
    for g in range(wa.size):
        a = Sa[g] @ E
        eps = 0.5 * (a @ a - 1.0)
        c = EA * l * wa[g]
        U += 0.5 * c * eps**2
        for k in range(NSHAPE):
            for d in range(3):
                Q[3 * k + d] += c * eps * Sa[g, k] * a[d]
        if want:
            for k in range(NSHAPE):
                B[:, 3 * k:3 * k + 3] = Sa[g, k] * np.eye(3)
            K += c * (B.T @ (np.outer(a, a) + eps * np.eye(3)) @ B)
    G = np.zeros((6, NDOF))
    for h in range(wb.size):
        a, b = Sb[h] @ E, Sbb[h] @ E
        s, ds, H = _bending_point(a, b, want)
        c = 0.5 * EI * l * wb[h]
        U += c * s
        for k in range(NSHAPE):
            G[:3, 3 * k:3 * k + 3] = Sb[h, k] * np.eye(3)
            G[3:, 3 * k:3 * k + 3] = Sbb[h, k] * np.eye(3)
        Q += c * (G.T @ ds)
        if want:
            K += c * (G.T @ H @ G)
    return U


class Cable3D:
    """``nel`` cables of lengths (nel,) m on reference coordinates e0 (nel, 12) m (a
    straight reference, r_x unit), ``section`` (area, second_moment), E (Pa), density
    rho (kg/m^3).  nu is accepted for the registry's common signature and unused (a cable
    has no cross-section strain)."""

    family = "cable3d"
    slots = ("r", "r_x")
    dim = 3
    schemes: dict = {}

    def __init__(self, lengths, e0, section, E: float, nu: float = 0.0, rho: float = 0.0):
        self.lengths = np.asarray(lengths, dtype=float)
        self.e0 = np.asarray(e0, dtype=float)
        self.nel, self.ndof = self.lengths.size, NDOF
        self.EA, self.EI = E * section.area, E * section.second_moment
        self.rhoA = rho * section.area
        self._rules = [(*point_rows(l, AXIAL_POINTS)[:2], *point_rows(l, BENDING_POINTS))
                       for l in self.lengths]

    def _run(self, e, want: bool) -> tuple:
        e = np.asarray(e, dtype=float)
        U, Q = np.zeros(self.nel), np.zeros((self.nel, NDOF))
        K = np.zeros((self.nel, NDOF, NDOF))
        for i, (l, r) in enumerate(zip(self.lengths, self._rules)):
            U[i] = element(e[i], l, self.EA, self.EI, *r, want, Q[i], K[i])
        return U, Q, K

    def energy(self, e) -> np.ndarray:
        """Eq. (2) of each element (nel,), J."""
        return self._run(e, False)[0]

    def gradient(self, e, tangent: bool = False):
        """Q = dU/de (nel, 12), N, and K (nel, 12, 12), N/m, or None."""
        _, Q, K = self._run(e, tangent)
        return Q, (K if tangent else None)

    def mass(self) -> np.ndarray:
        """Consistent mass (nel, 12, 12), kg: rho A int S_i S_j dx times I_3."""
        return np.array([np.kron(basis.cable3d_mass(self.rhoA, l), np.eye(3))
                         for l in self.lengths])

    def gravity(self, g) -> np.ndarray:
        """Generalised gravity force rho A int S^T g dx (nel, 12), N, of the acceleration
        g (3,) m/s^2 (exact: 2 Gauss points on a cubic)."""
        out = []
        for l in self.lengths:
            xi, w = gauss01(2)
            X, zero = xi * l, np.zeros(2)
            s = l * (w @ basis.cable3d_S(X, zero, zero, l))
            out.append(self.rhoA * np.kron(s, np.asarray(g, dtype=float)))
        return np.array(out)
