"""Strain model: spatial Green-Lagrange strains, compiled (numba).

:class:`GreenSpatial` is :class:`ancf.elements.green2d.GreenPlanar` in three
dimensions: the same call conventions, with the gradients ``r_x``, ``r_y``, ``r_z``
and Voigt strains ``[eps_xx, eps_yy, eps_zz, 2 eps_yz, 2 eps_xz, 2 eps_xy]``.
Per point, with the directions a = x, y, z, the shape-function derivatives
``B_a`` and the displacement gradients ``u_a = sum_k B_ak (E_k - E0_k)``,

    eps_aa = r0_a.u_a + u_a.u_a/2,   2 eps_ab = r0_a.u_b + r0_b.u_a + u_a.u_b
    s = C eps                         (2nd Piola-Kirchhoff, Voigt; S its 3x3 tensor)
    dU/dE_kd   += w sum_a B_ak (sum_b S_ab r_b)_d
    d2U/dE dE  += w G^T C G + w (sum_ab S_ab B_a B_b^T) (x) I3

with ``G`` (6, 3n) the strain derivatives.  Element coordinates are ordered
``k * 3 + d``.  Shapes: E, E0 (nel, n, 3); BX, BY, BZ (nel, nq, n); dX0, dY0, dZ0
(nel, nq, 3); w (nel, nq) (m^3); C (nterm, 6, 6) (Pa); cidx (nq,).
"""
from __future__ import annotations

import numpy as np
from numba import njit

#: the direction pair (a, b) of each Voigt component
_VA = np.array([0, 1, 2, 1, 0, 0])
_VB = np.array([0, 1, 2, 2, 2, 1])


@njit(cache=True)
def _point(E, E0, BX, BY, BZ, dX0, dY0, dZ0, r, e, q, B, F, eps):
    """Fill B (3, n) with the shape-function derivatives at point q of element e, F (3, 3)
    with the gradients r_a (row a) and eps (6,) with the Voigt strains of state row r
    (r = e but for stacked states, :func:`energy`)."""
    n = B.shape[1]
    for k in range(n):
        B[0, k], B[1, k], B[2, k] = BX[e, q, k], BY[e, q, k], BZ[e, q, k]
    for d in range(3):
        F[0, d], F[1, d], F[2, d] = dX0[e, q, d], dY0[e, q, d], dZ0[e, q, d]
    U = np.zeros((3, 3))
    for k in range(n):
        for d in range(3):
            u = E[r, k, d] - E0[e, k, d]
            for a in range(3):
                U[a, d] += B[a, k] * u
    for v in range(6):
        a, b = _VA[v], _VB[v]
        val = 0.0
        for d in range(3):
            val += F[a, d] * U[b, d] + F[b, d] * U[a, d] + U[a, d] * U[b, d]
        eps[v] = 0.5 * val if a == b else val
    for a in range(3):
        for d in range(3):
            F[a, d] += U[a, d]


@njit(cache=True)
def _stress(c, eps, s):
    for i in range(6):
        s[i] = 0.0
        for j in range(6):
            s[i] += c[i, j] * eps[j]


@njit(cache=True)
def energy(E, E0, BX, BY, BZ, dX0, dY0, dZ0, w, C, cidx):
    """Strain energy per row of ``E`` (rows,), J.  ``E`` may stack several states of the
    nel elements (rows = k nel, row r is element r mod nel), each as by itself."""
    nel, nq, n = BX.shape
    out = np.zeros(E.shape[0])
    B, F, eps, s = np.empty((3, n)), np.empty((3, 3)), np.empty(6), np.empty(6)
    for r in range(E.shape[0]):
        e = r % nel
        for q in range(nq):
            _point(E, E0, BX, BY, BZ, dX0, dY0, dZ0, r, e, q, B, F, eps)
            _stress(C[cidx[q]], eps, s)
            out[r] += 0.5 * w[e, q] * np.dot(s, eps)
    return out


@njit(cache=True)
def _strain_derivatives(B, F, G):
    """G[v, 3k + d] = d eps_v / dE_kd at the point."""
    n = B.shape[1]
    for v in range(6):
        a, b = _VA[v], _VB[v]
        for k in range(n):
            for d in range(3):
                if a == b:
                    G[v, 3 * k + d] = B[a, k] * F[a, d]
                else:
                    G[v, 3 * k + d] = B[a, k] * F[b, d] + B[b, k] * F[a, d]


@njit(cache=True)
def gradient_tangent(E, E0, BX, BY, BZ, dX0, dY0, dZ0, w, C, cidx, want_K, g, K):
    """Add dU/de (nel, 3n) to ``g`` and, if ``want_K``, d2U/de2 (nel, 3n, 3n) to ``K``."""
    nel, nq, n = BX.shape
    nd = 3 * n
    B, F, eps, s = np.empty((3, n)), np.empty((3, 3)), np.empty(6), np.empty(6)
    S, P = np.empty((3, 3)), np.empty((3, 3))
    G, CG = np.empty((6, nd)), np.empty((6, nd))
    for e in range(nel):
        for q in range(nq):
            _point(E, E0, BX, BY, BZ, dX0, dY0, dZ0, e, e, q, B, F, eps)
            c = C[cidx[q]]
            _stress(c, eps, s)
            ww = w[e, q]
            for v in range(6):
                S[_VA[v], _VB[v]] = S[_VB[v], _VA[v]] = s[v]
            P[:, :] = S @ F
            for k in range(n):
                for d in range(3):
                    g[e, 3 * k + d] += ww * (B[0, k] * P[0, d] + B[1, k] * P[1, d] + B[2, k] * P[2, d])
            if not want_K:
                continue
            _strain_derivatives(B, F, G)
            CG[:, :] = (ww * c) @ G
            for a in range(nd):
                for b in range(a, nd):
                    v = 0.0
                    for i in range(6):
                        v += G[i, a] * CG[i, b]
                    K[e, a, b] += v
            SB = S @ B
            for k in range(n):
                for m in range(k, n):
                    v = ww * (B[0, k] * SB[0, m] + B[1, k] * SB[1, m] + B[2, k] * SB[2, m])
                    for d in range(3):
                        K[e, 3 * k + d, 3 * m + d] += v
    if want_K:
        for e in range(nel):
            for a in range(nd):
                for b in range(a + 1, nd):
                    K[e, b, a] = K[e, a, b]


class GreenSpatial:
    """Spatial Green-Lagrange strains in the element's local frame, Voigt
    ``[eps_xx, eps_yy, eps_zz, 2 eps_yz, 2 eps_xz, 2 eps_xy]``, from the gradients
    ``r_x``, ``r_y``, ``r_z`` (dim 3)."""

    dim = 3
    voigt = 6
    energy = staticmethod(energy)
    gradient_tangent = staticmethod(gradient_tangent)
