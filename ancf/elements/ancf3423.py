"""The ANCF 3423 shell: 4 nodes, position and one transverse gradient each, with assumed
natural strains (ANS) and enhanced assumed strains (EAS) against locking.

The bilinear shear-deformable shell of Yamashita, Valkeapaa, Jayakumar & Sugiyama, ASME
JCND 10(5) 051012 (2015) (Project Chrono's ``ChElementShellANCF_3423``, formerly
``ChElementShellANCF``).  A flat rectangular element of sides a (x) and b (y), thickness
h (z); nodes A (-1, -1), B (1, -1), C (1, 1), D (-1, 1) in (xi, eta), each with e_i =
[r_i, d_i] (m, -), d_i = dr/dz; coordinates e (24,) = [r_A, d_A, r_B, ..., d_D].  The
shape functions (SymPy, ``analytic/ancf3423.py`` -> ``_ancf3423_generated.py``):

    r(xi, eta, zeta) = sum_a s_a e_a,  s_{2i} = N_i,  s_{2i+1} = (h zeta / 2) N_i       (1)

Strains, in the Voigt order [11, 22, 33, 23, 13, 12] with engineering shears, of the
element's reference frame (the paper's contravariant transformation is the identity for
the flat rectangular references this module takes, reference_coordinates: r0_x, r0_y,
d0 orthonormal, so the local frame A_i and J0 coincide):

    E11 = (r_x.r_x - r0_x.r0_x)/2,  E22 = (r_y.r_y - ...)/2,  2E12 = r_x.r_y - r0_x.r0_y (2)
    E33 = sum_i N_i(xi, eta) E33(node_i),  E33(node) = (d.d - d0.d0)/2 at zeta = 0       (3)
    2E23 = (1 - xi)/2 g_yz(-1, 0) + (1 + xi)/2 g_yz(1, 0),  g_yz = r_y.r_z - r0_y.r0_z  (4)
    2E13 = (1 - eta)/2 g_xz(0, -1) + (1 + eta)/2 g_xz(0, 1)                              (5)

Eqs. (3)-(5) are the ANS: the thickness strain sampled at the nodes, the transverse shears
at the edge midpoints, all on the mid-surface (paper Eqs. (16)-(19)).  Each strain is a
quadratic form of e: eps_k = 1/2 sum_ab H^k_ab (e_a.e_b - e0_a.e0_b) with constant
symmetric H^k (8, 8) per integration point (:func:`point_forms`), so that

    B_k = d eps_k / de = (H^k (x) I_3) e,   d2 eps_k / de2 = H^k (x) I_3                 (6)

EAS (paper Eqs. (20)-(24)): five modes eps_EAS = G alpha_E, G (6, 5) with xi on E11,
eta on E22, xi and eta on 2E12 and zeta on E33.  Stress (Kelvin-Voigt, Chrono's
structural damping alpha s):

    sigma = D (eps + G alpha_E + alpha B e')                                            (7)
    Q = int B^T sigma dV,   0 = int G^T sigma dV  (alpha_E condensed per element)          (8)

so alpha_E = -K_aa^-1 int G^T D (eps + alpha B e') dV, K_aa = int G^T D G dV.  Exact
Jacobians (C = B at e + alpha e', P = int B^T D G dV, P_c = int C^T D G dV):

    K = dQ/de  = int [sum_k sigma_k H^k (x) I_3 + B^T D C] dV - P K_aa^-1 P_c^T            (9)
    R = dQ/de' = alpha (int B^T D B dV - P K_aa^-1 P^T)                                  (10)

Q is dU/de of the condensed energy U = int 1/2 (eps + G alpha_E)^T D (...) dV at e' = 0.
Integration: 2 x 2 x 2 Gauss points (Chrono's), dV = (a/2)(b/2)(h/2) dxi deta dzeta.

``ans="chrono"`` reproduces Chrono's interpolation of Eq. (3), which weights the samples at
nodes C and D with N_D and N_C (its knots run A, B, D, C against the shape functions'
A, B, C, D); ``ans="paper"`` (the default) is Eq. (3) as written, and the element as it was
when Chrono's stored plate history was made (2015).  They differ only for a non-uniform
thickness strain.
"""
from __future__ import annotations

import sys

import numpy as np
from numba import njit

from ancf.elements._ancf3423_generated import scalar_mass, shapes
from ancf.elements.material import isotropic_3d

NNODE, NSHAPE, NDOF = 4, 8, 24
NODE_XI = np.array([-1.0, 1.0, 1.0, -1.0])   # xi_i of nodes A, B, C, D
NODE_ETA = np.array([-1.0, -1.0, 1.0, 1.0])  # eta_i
#: ANS thickness-strain orders (module docstring): the shape function weighting node i's sample
ANS = {"chrono": (0, 1, 3, 2), "paper": (0, 1, 2, 3)}
GAUSS = 1.0 / np.sqrt(3.0)


def _shapes_at(xi, eta, zeta, a, b, h) -> np.ndarray:
    """(4, 8): s, ds/dx, ds/dy, ds/dz at one point (the generated evaluator)."""
    out = np.zeros((4, NSHAPE))
    shapes(float(xi), float(eta), float(zeta), float(a), float(b), float(h), out)
    return out


def _sym(u, v) -> np.ndarray:
    """u v^T + v u^T (8, 8): the form of the dot product r_u . r_v (shear, Eq. (6))."""
    return np.outer(u, v) + np.outer(v, u)


def point_forms(a: float, b: float, h: float, ans: str = "paper") -> tuple:
    """(H (8, 6, 8, 8), G (8, 6, 5), w (8,)) at the 2 x 2 x 2 Gauss points: the strain
    forms H^k of Eqs. (2)-(6), the EAS modes and the weights times dV (m^3); sides in m."""
    if ans not in ANS:
        raise ValueError(f"ans must be one of {tuple(ANS)} (got {ans!r})")
    nodes = [_shapes_at(x, y, 0.0, a, b, h) for x, y in zip(NODE_XI, NODE_ETA)]
    yz = [_shapes_at(x, 0.0, 0.0, a, b, h) for x in (-1.0, 1.0)]
    xz = [_shapes_at(0.0, y, 0.0, a, b, h) for y in (-1.0, 1.0)]
    H, G, w = [], [], []
    for zeta in (-GAUSS, GAUSS):
        for eta in (-GAUSS, GAUSS):
            for xi in (-GAUSS, GAUSS):
                s = _shapes_at(xi, eta, zeta, a, b, h)
                Hq = np.zeros((6, NSHAPE, NSHAPE))
                Hq[0], Hq[1], Hq[5] = np.outer(s[1], s[1]), np.outer(s[2], s[2]), _sym(s[1], s[2])
                for i, j in enumerate(ANS[ans]):
                    Hq[2] += s[0, 2 * j] * np.outer(nodes[i][3], nodes[i][3])
                for p, sp in zip(((1 - xi) / 2, (1 + xi) / 2), yz):
                    Hq[3] += p * _sym(sp[2], sp[3])
                for p, sp in zip(((1 - eta) / 2, (1 + eta) / 2), xz):
                    Hq[4] += p * _sym(sp[1], sp[3])
                Gq = np.zeros((6, 5))
                Gq[0, 0], Gq[1, 1], Gq[5, 2], Gq[5, 3], Gq[2, 4] = xi, eta, xi, eta, zeta
                H.append(Hq)
                G.append(Gq)
                w.append(a * b * h / 8)
    return np.array(H), np.array(G), np.array(w)


def eas_stiffness(G, w, D) -> np.ndarray:
    """K_aa = int G^T D G dV (5, 5), Pa m^3 (Eq. (8))."""
    return np.einsum("q,qki,kl,qlj->ij", w, G, D, G)


def reference_coordinates(a: float, b: float) -> np.ndarray:
    """e0 (24,): the flat plate on [0, a] x [0, b] at z = 0, d = (0, 0, 1) at every node."""
    corners = [(0, 0), (a, 0), (a, b), (0, b)]
    return np.concatenate([[x, y, 0.0, 0.0, 0.0, 1.0] for x, y in corners]).astype(float)


def mass_matrix(a: float, b: float, h: float, rho: float) -> np.ndarray:
    """The consistent mass M = rho int S^T S dV (24, 24), kg (kg m, kg m^2 on d), exact."""
    return np.kron(rho * scalar_mass(a, b, h), np.eye(3))


def gravity(a: float, b: float, h: float, rho: float, g) -> np.ndarray:
    """F_g = rho int S^T g dV (24,), N (N m on d), for g (3,) in m/s^2: M times g on every
    node's r, as sum_i N_i = 1 makes S times that vector g at every point."""
    return mass_matrix(a, b, h, rho) @ np.tile(np.r_[np.asarray(g, dtype=float), 0, 0, 0], NNODE)


def _bilinear(xi, eta):
    """(N, dN/dxi, dN/deta) (..., 4) of nodes A, B, C, D at xi, eta in [-1, 1]."""
    xi, eta = (np.asarray(v, dtype=float)[..., None] for v in (xi, eta))
    u, v = 1 + NODE_XI * xi, 1 + NODE_ETA * eta
    return u * v / 4, NODE_XI * v / 4, NODE_ETA * u / 4


def scalar_shape(xi, eta, z) -> np.ndarray:
    """The 8 scalar shape functions of Eq. (1) at xi, eta in [-1, 1] and z = h zeta/2 (m)
    from the mid-surface, (..., 8) ordered 2 node + (r, d): N_i (-) and z N_i (m)."""
    N, _, _ = _bilinear(xi, eta)
    z = np.asarray(z, dtype=float)[..., None]
    return np.stack(np.broadcast_arrays(N, z * N), -1).reshape(N.shape[:-1] + (NSHAPE,))


def natural_gradient(xi, eta, z) -> np.ndarray:
    """ds_a/d(xi, eta, z) (..., 8, 3) (the derivatives of :func:`scalar_shape`, z in m)."""
    N, Nx, Ny = _bilinear(xi, eta)
    z = np.asarray(z, dtype=float)[..., None]
    zero = np.zeros_like(N)
    r = np.stack(np.broadcast_arrays(Nx, Ny, zero), -1)
    d = np.stack(np.broadcast_arrays(z * Nx, z * Ny, N + zero), -1)
    return np.stack([r, d], -2).reshape(r.shape[:-2] + (NSHAPE, 3))


@njit(cache=True)
def element(E, V, E0, H, G, w, D, Kinv, alpha, want_J, Q, K, R):
    """One element: Q (24,) N (Eq. (8)), and if want_J K (24, 24) N/m, R (24, 24) N s/m
    (Eqs. (9), (10)), all overwritten; returns the energy U (J) at the EAS parameters of
    the call (the condensed strain energy when e' = 0).  E, V, E0 (8, 3): coordinates,
    their rates and the reference, per scalar shape function; H, G, w of
    :func:`point_forms`; D (6, 6) Pa; Kinv = K_aa^-1; alpha (s) the damping.  Loops
    written out: the small products as matrix calls cost three times as much."""
    nq = w.size
    dG, VE = _gram(E, V, E0)
    eps, B, C = _strains(E, V, H, dG, VE, alpha)
    f = _eas_load(eps, G, w, D)
    alpha_e = np.empty(5)
    for m in range(5):
        alpha_e[m] = -_dot(Kinv[m], f)
    Q[:] = 0.0
    U = 0.0
    tot, sig = np.zeros(6), np.zeros((nq, 6))
    for q in range(nq):
        for k in range(6):
            tot[k] = eps[q, k] + _dot(G[q, k], alpha_e)
        for k in range(6):
            sig[q, k] = _dot(D[k], tot)
            U += 0.5 * w[q] * tot[k] * sig[q, k]
            ws = w[q] * sig[q, k]
            for i in range(NDOF):
                Q[i] += ws * B[q, k, i]
    if want_J:
        _jacobians(B, C, sig, H, G, w, D, Kinv, alpha, K, R)
    return U


@njit(cache=True, inline="always")
def _dot(u, v) -> float:
    """u . v of two short vectors (a loop: BLAS costs more than the sum at this size)."""
    s = 0.0
    for i in range(u.size):
        s += u[i] * v[i]
    return s


@njit(cache=True)
def _gram(E, V, E0):
    """(e_a.e_b - e0_a.e0_b, e'_a.e_b) (8, 8) each: the strains' quadratic forms' data."""
    dG, VE = np.empty((NSHAPE, NSHAPE)), np.empty((NSHAPE, NSHAPE))
    for a_ in range(NSHAPE):
        for b_ in range(NSHAPE):
            s = t = 0.0
            for c in range(3):
                s += E[a_, c] * E[b_, c] - E0[a_, c] * E0[b_, c]
                t += V[a_, c] * E[b_, c]
            dG[a_, b_], VE[a_, b_] = s, t
    return dG, VE


@njit(cache=True)
def _strains(E, V, H, dG, VE, alpha):
    """(eps + alpha eps' (nq, 6) of Eq. (7), B, C (nq, 6, 24) of Eqs. (6), (9)) per point:
    eps_k = 1/2 H^k : dG, eps'_k = H^k : VE, B_k = H^k E, C_k = B_k + alpha H^k V."""
    nq = H.shape[0]
    eps, B, C = np.zeros((nq, 6)), np.zeros((nq, 6, NDOF)), np.zeros((nq, 6, NDOF))
    for q in range(nq):
        for k in range(6):
            s = t = 0.0
            for a_ in range(NSHAPE):
                for b_ in range(NSHAPE):
                    h = H[q, k, a_, b_]
                    s += h * dG[a_, b_]
                    t += h * VE[a_, b_]
                    for c in range(3):
                        B[q, k, 3 * a_ + c] += h * E[b_, c]
                        C[q, k, 3 * a_ + c] += h * V[b_, c]
            eps[q, k] = 0.5 * s + alpha * t
            for i in range(NDOF):
                C[q, k, i] = B[q, k, i] + alpha * C[q, k, i]
    return eps, B, C


@njit(cache=True)
def _eas_load(eps, G, w, D):
    """int G^T D eps dV (5,): the right side of the EAS equation."""
    f, De = np.zeros(5), np.zeros(6)
    for q in range(w.size):
        for k in range(6):
            De[k] = _dot(D[k], eps[q])
        for m in range(5):
            f[m] += w[q] * _dot(G[q, :, m], De)
    return f


@njit(cache=True)
def _jacobians(B, C, sig, H, G, w, D, Kinv, alpha, K, R):
    """K and R of Eqs. (9), (10) into K, R (overwritten)."""
    P, Pc = np.zeros((NDOF, 5)), np.zeros((NDOF, 5))
    Kg = np.zeros((NSHAPE, NSHAPE))
    K[:, :] = 0.0
    R[:, :] = 0.0
    DG, DB, DC = np.empty((6, 5)), np.empty((6, NDOF)), np.empty((6, NDOF))
    for q in range(w.size):
        _weighted_laws(B[q], C[q], G[q], D, w[q], DG, DB, DC)
        for i in range(NDOF):
            for k in range(6):
                b, c = B[q, k, i], C[q, k, i]
                for m in range(5):
                    P[i, m] += b * DG[k, m]
                    Pc[i, m] += c * DG[k, m]
                for j in range(NDOF):
                    K[i, j] += b * DC[k, j]
                    R[i, j] += b * DB[k, j]
        for k in range(6):
            ws = w[q] * sig[q, k]
            for a_ in range(NSHAPE):
                for b_ in range(NSHAPE):
                    Kg[a_, b_] += ws * H[q, k, a_, b_]
    for a_ in range(NSHAPE):
        for b_ in range(NSHAPE):
            for c in range(3):
                K[3 * a_ + c, 3 * b_ + c] += Kg[a_, b_]
    PK = np.empty((NDOF, 5))
    for i in range(NDOF):
        for n in range(5):
            PK[i, n] = _dot(P[i], Kinv[:, n])
    for i in range(NDOF):
        for j in range(NDOF):
            s = t = 0.0
            for n in range(5):
                s += PK[i, n] * Pc[j, n]
                t += PK[i, n] * P[j, n]
            K[i, j] -= s
            R[i, j] = alpha * (R[i, j] - t)


@njit(cache=True)
def _weighted_laws(Bq, Cq, Gq, D, wq, DG, DB, DC):
    """w D G (6, 5), w D B, w D C (6, 24) at one point into DG, DB, DC."""
    for k in range(6):
        for m in range(5):
            DG[k, m] = wq * _dot(D[k], Gq[:, m])
        for i in range(NDOF):
            s = t = 0.0
            for l_ in range(6):
                s += D[k, l_] * Bq[l_, i]
                t += D[k, l_] * Cq[l_, i]
            DB[k, i], DC[k, i] = wq * s, wq * t


@njit(cache=True)
def batch(Es, Vs, E0s, H, G, w, D, Kinv, alpha, want_J, Q, K, R, U):
    """:func:`element` over elements of one size: Es, Vs, E0s (nel, 8, 3); Q (nel, 24),
    K, R (nel, 24, 24) (untouched without want_J), U (nel,)."""
    for i in range(Es.shape[0]):
        U[i] = element(Es[i], Vs[i], E0s[i], H, G, w, D, Kinv, alpha, want_J, Q[i], K[i], R[i])


def internal_force(e, edot, a, b, h, E, nu, alpha=0.0, *, ans="paper") -> np.ndarray:
    """Q(e, e') (24,), N (N m on d), Eq. (8) of one element on its own reference
    (:func:`reference_coordinates`): e (24,) in m, edot (24,) in m/s, sides a, b and
    thickness h in m, E in Pa, nu, alpha in s; the interface of the other Chrono modules
    (``ancf element``).  Chrono's ``ComputeInternalForces`` stores -Q."""
    el = Shell3423(a, b, h, E, nu, ans=ans, alpha=alpha)
    return el.evaluate(np.reshape(e, (1, NDOF)), np.reshape(edot, (1, NDOF)))[0][0]


def internal_force_jacobians(e, edot, a, b, h, E, nu, alpha=0.0, *, ans="paper"):
    """(K, R) = (dQ/de in N/m, dQ/de' in N s/m), each (24, 24), Eqs. (9), (10), of
    :func:`internal_force` (same arguments)."""
    el = Shell3423(a, b, h, E, nu, ans=ans, alpha=alpha)
    _, K, R, _ = el.evaluate(np.reshape(e, (1, NDOF)), np.reshape(edot, (1, NDOF)), want_J=True)
    return K[0], R[0]


class Shell3423:
    """``nel`` ANCF 3423 elements of sides a, b (nel,) m and thickness h (m), one
    isotropic layer (E Pa, nu; or the law ``D`` (6, 6) in Pa, Voigt order of Eq. (2), in
    their place), density rho (kg/m^3), reference e0 (nel, 24) (default each element's
    own, :func:`reference_coordinates`), the ANS order ``ans`` (module docstring) and the
    damping alpha (s).  The element contract
    (:mod:`ancf.elements.contract`): energy, gradient (exact tangent), mass."""

    module = sys.modules[__name__]
    strain = sys.modules[__name__]  # the strain model (the registry's ``strain``)
    family = "ancf3423"
    slots = ("r", "r_z")
    schemes: dict = {}
    dim = 3
    node_points = ((NODE_XI + 1) / 2, (NODE_ETA + 1) / 2)

    @staticmethod
    def points_per_element() -> int:
        """The 2 x 2 x 2 Gauss points of :func:`point_forms` (the cost model's count)."""
        return 8

    def __init__(self, lengths, widths, h, E, nu, rho=0.0, e0=None, ans="paper", alpha=0.0,
                 D=None):
        a = np.atleast_1d(np.asarray(lengths, dtype=float))
        b = np.broadcast_to(np.asarray(widths, dtype=float), a.shape)
        if not np.all(a == a[0]) or not np.all(b == b[0]):
            raise ValueError("lengths, widths: elements of one size only (got several)")
        self.nel, self.nshape, self.ndof = a.size, NSHAPE, NDOF
        self.lengths, self.widths, self.h, self.rho = a, b, float(h), float(rho)
        self.D = isotropic_3d(E, nu) if D is None else np.array(D, dtype=float)
        self.H, self.G, self.w = point_forms(a[0], b[0], self.h, ans)
        self.Kinv = np.linalg.inv(eas_stiffness(self.G, self.w, self.D))
        self.alpha = float(alpha)
        ref = np.tile(reference_coordinates(a[0], b[0]), (self.nel, 1))
        self.e0 = ref if e0 is None else np.asarray(e0, dtype=float).reshape(self.nel, NDOF)

    def _shaped(self, e):
        return np.ascontiguousarray(np.asarray(e, dtype=float).reshape(self.nel, NSHAPE, 3))

    def evaluate(self, e, edot=None, want_J: bool = False):
        """(Q (nel, 24) N, K, R (nel, 24, 24) N/m, N s/m or None, U (nel,) J) at e, e'."""
        E = self._shaped(e)
        V = np.zeros(E.shape) if edot is None else self._shaped(edot)
        Q, U = np.zeros((self.nel, NDOF)), np.zeros(self.nel)
        K = np.zeros((self.nel, NDOF, NDOF)) if want_J else np.zeros((self.nel, 0, 0))
        R = np.zeros(K.shape)
        batch(E, V, self._shaped(self.e0), self.H, self.G, self.w, self.D, self.Kinv,
              self.alpha, want_J, Q, K, R, U)
        return Q, (K if want_J else None), (R if want_J else None), U

    def energy(self, e) -> np.ndarray:
        """The condensed strain energy of each element (nel,), J."""
        return self.evaluate(e)[3]

    def gradient(self, e, tangent: bool = False):
        """dU/de = Q (nel, 24), N, and K (nel, 24, 24), N/m, or None (e' = 0)."""
        Q, K, _, _ = self.evaluate(e, want_J=tangent)
        return Q, K

    def mass(self) -> np.ndarray:
        """Consistent mass matrices (nel, 24, 24), kg."""
        return np.array([mass_matrix(a, b, self.h, self.rho) for a, b in zip(self.lengths, self.widths)])

    @classmethod
    def own_shapes(cls) -> dict:
        """S and d/dX, d/dY, d/dZ (..., 8) at physical points (X, Y, Z) m from corner A of
        elements of sides (a, b) (the registry's ``field``; Z from the mid-surface)."""
        def table(X, Y, Z, a, b):
            X, Y, Z, a, b = np.broadcast_arrays(*(np.asarray(v, dtype=float) for v in (X, Y, Z, a, b)))
            out = np.zeros(X.shape + (4, NSHAPE))
            for idx in np.ndindex(X.shape):
                shapes(2 * X[idx] / a[idx] - 1, 2 * Y[idx] / b[idx] - 1, 2 * Z[idx], a[idx],
                       b[idx], 1.0, out[idx])
            return out

        return {**{key: (lambda X, Y, Z, a, b, i=i: table(X, Y, Z, a, b)[..., i, :])
                   for i, key in enumerate(("S", "x", "y", "z"))}, "n": NSHAPE}

