"""Strain model: planar Green-Lagrange strains, compiled (numba).

:class:`GreenPlanar` declares the model; its kernels give the strain energy, its
gradient and its exact tangent from the strains, their first derivatives ``G``
and the geometric term.  One call evaluates every element at every quadrature
point of every energy term:
the points of all terms are concatenated, each carrying the index of its
material matrix in ``C`` (nterm, 3, 3).  Per point, with the displacement
gradients ``u_x = sum_k BX_k (E_k - E0_k)`` (no cancellation at small strain),

    eps = [r0_x.u_x + u_x.u_x/2,  r0_y.u_y + u_y.u_y/2,  r0_x.u_y + r0_y.u_x + u_x.u_y]
    s = C eps                                   (2nd Piola-Kirchhoff, Voigt)
    dU/dE_kd   += w (BX_k (s0 r_x + s2 r_y)_d + BY_k (s1 r_y + s2 r_x)_d)
    d2U/dE dE  += w G^T C G + w (s0 BX BX^T + s1 BY BY^T + s2 (BX BY^T + BY BX^T)) (x) I2

with ``G`` (3, 2n) the strain derivatives.  Element coordinates are ordered
``k * 2 + d`` (shape function k, component d).  Shapes: E, E0 (nel, n, 2);
BX, BY (nel, nq, n); dX0, dY0 (nel, nq, 2); w (nel, nq); cidx (nq,).

A single group of these elements on band storage is also a compiled group
(:class:`GreenBand`, :meth:`ancf.core.pattern.ReducedPattern.compiled`): its reduced
gradient and tangent are one call (:func:`assemble_band`), from the static Newton
solver and the generalised-alpha march alike.
"""
from __future__ import annotations

from typing import NamedTuple

import numpy as np
from numba import njit

from ancf.common.dispatch import implements
from ancf.common.leaf import leaf
from ancf.core.pattern import assemble_group, scatter


@leaf
def _point_strain(E, E0, BX, BY, dX0, dY0, r, e, q, n):
    """Green strains (exx, eyy, gxy) and the current gradients at point q of state row r
    of element e (r = e but for stacked states, :func:`energy`)."""
    ux0 = ux1 = uy0 = uy1 = 0.0
    for k in range(n):
        u0 = E[r, k, 0] - E0[e, k, 0]
        u1 = E[r, k, 1] - E0[e, k, 1]
        ux0 += BX[e, q, k] * u0
        ux1 += BX[e, q, k] * u1
        uy0 += BY[e, q, k] * u0
        uy1 += BY[e, q, k] * u1
    a0, a1, b0, b1 = dX0[e, q, 0], dX0[e, q, 1], dY0[e, q, 0], dY0[e, q, 1]
    exx = a0 * ux0 + a1 * ux1 + 0.5 * (ux0 * ux0 + ux1 * ux1)
    eyy = b0 * uy0 + b1 * uy1 + 0.5 * (uy0 * uy0 + uy1 * uy1)
    gxy = a0 * uy0 + a1 * uy1 + b0 * ux0 + b1 * ux1 + ux0 * uy0 + ux1 * uy1
    return exx, eyy, gxy, a0 + ux0, a1 + ux1, b0 + uy0, b1 + uy1


@njit(cache=True)
def energy(E, E0, BX, BY, dX0, dY0, w, C, cidx):
    """Strain energy per row of ``E`` (rows,), J.  ``E`` may stack several states of the
    nel elements (rows = k nel, row r is element r mod nel), each as by itself."""
    nel, nq, n = BX.shape
    out = np.zeros(E.shape[0])
    for r in range(E.shape[0]):
        e = r % nel
        for q in range(nq):
            ex, ey, gm, _, _, _, _ = _point_strain(E, E0, BX, BY, dX0, dY0, r, e, q, n)
            c = C[cidx[q]]
            s0 = c[0, 0] * ex + c[0, 1] * ey + c[0, 2] * gm
            s1 = c[1, 0] * ex + c[1, 1] * ey + c[1, 2] * gm
            s2 = c[2, 0] * ex + c[2, 1] * ey + c[2, 2] * gm
            out[r] += 0.5 * w[e, q] * (s0 * ex + s1 * ey + s2 * gm)
    return out


@njit(cache=True)
def gradient_tangent(E, E0, BX, BY, dX0, dY0, w, C, cidx, want_K, g, K):
    """Add dU/de (nel, 2n) to ``g`` and, if ``want_K``, d2U/de2 (nel, 2n, 2n) to ``K``."""
    nel, nq, n = BX.shape
    nd = 2 * n
    G = np.empty((3, nd))
    CG = np.empty((3, nd))
    for e in range(nel):
        for q in range(nq):
            ex, ey, gm, dx0, dx1, dy0, dy1 = _point_strain(E, E0, BX, BY, dX0, dY0, e, e, q, n)
            c = C[cidx[q]]
            ww = w[e, q]
            s0 = c[0, 0] * ex + c[0, 1] * ey + c[0, 2] * gm
            s1 = c[1, 0] * ex + c[1, 1] * ey + c[1, 2] * gm
            s2 = c[2, 0] * ex + c[2, 1] * ey + c[2, 2] * gm
            px0, px1 = s0 * dx0 + s2 * dy0, s0 * dx1 + s2 * dy1
            py0, py1 = s1 * dy0 + s2 * dx0, s1 * dy1 + s2 * dx1
            for k in range(n):
                bx, by = BX[e, q, k], BY[e, q, k]
                g[e, 2 * k] += ww * (bx * px0 + by * py0)
                g[e, 2 * k + 1] += ww * (bx * px1 + by * py1)
            if not want_K:
                continue
            for k in range(n):
                bx, by = BX[e, q, k], BY[e, q, k]
                G[0, 2 * k], G[0, 2 * k + 1] = bx * dx0, bx * dx1
                G[1, 2 * k], G[1, 2 * k + 1] = by * dy0, by * dy1
                G[2, 2 * k], G[2, 2 * k + 1] = bx * dy0 + by * dx0, bx * dy1 + by * dx1
            for i in range(3):
                for a in range(nd):
                    CG[i, a] = ww * (c[i, 0] * G[0, a] + c[i, 1] * G[1, a] + c[i, 2] * G[2, a])
            for a in range(nd):
                for b in range(a, nd):
                    v = G[0, a] * CG[0, b] + G[1, a] * CG[1, b] + G[2, a] * CG[2, b]
                    K[e, a, b] += v
            for k in range(n):
                bxk, byk = BX[e, q, k], BY[e, q, k]
                for m in range(k, n):
                    bxm, bym = BX[e, q, m], BY[e, q, m]
                    v = ww * (s0 * bxk * bxm + s1 * byk * bym + s2 * (bxk * bym + byk * bxm))
                    K[e, 2 * k, 2 * m] += v
                    K[e, 2 * k + 1, 2 * m + 1] += v
    if want_K:
        for e in range(nel):
            for a in range(nd):
                for b in range(a + 1, nd):
                    K[e, b, a] = K[e, a, b]


class GreenBand(NamedTuple):
    """One planar Green-strain element group in the numbering of a band
    :class:`~ancf.core.pattern.ReducedPattern` (q = T z + g)."""

    qsel: np.ndarray    # global coordinates that are independent ...
    zsel: np.ndarray    # ... and their positions in z
    dofmap: np.ndarray  # (nel, 2n) element DOF maps
    E0: np.ndarray      # the arrays of gradient_tangent (module docstring)
    BX: np.ndarray
    BY: np.ndarray
    dX0: np.ndarray
    dY0: np.ndarray
    w: np.ndarray
    C: np.ndarray
    cidx: np.ndarray
    vidx: np.ndarray    # scatter targets of the pattern (ancf.core.pattern.scatter)
    midx: np.ndarray


def band_group(pattern, group) -> GreenBand:
    """The :class:`GreenBand` of an assembly's element group on ``pattern``."""
    el, pts = group.element, group.element.points
    vidx, midx = pattern.groups[0]
    return GreenBand(qsel=pattern.qsel, zsel=pattern.zsel,
                     dofmap=np.ascontiguousarray(group.dofmap), E0=pts.E0, BX=pts.BX, BY=pts.BY,
                     dX0=pts.dX0, dY0=pts.dY0, w=pts.w, C=el.C, cidx=pts.cidx, vidx=vidx,
                     midx=midx)


@implements(assemble_group, GreenBand)
def assemble_band(group, z, gq, want_K, grad, K):
    """grad = T^T dU/dq at q = T z + gq (N) and, if want_K, K = T^T (d2U/dq2) T (N/m,
    band storage)."""
    qsel, zsel, dofmap = group.qsel, group.zsel, group.dofmap  # a tuple or its struct
    q = gq.copy()
    for i in range(qsel.size):
        q[qsel[i]] += z[zsel[i]]
    nel, nd = dofmap.shape
    E = np.empty((nel, nd // 2, 2))
    for e in range(nel):
        for a in range(nd):
            E[e, a // 2, a % 2] = q[dofmap[e, a]]
    ge = np.zeros((nel, nd))
    Ke = np.zeros((nel, nd, nd)) if want_K else np.zeros((0, 0, 0))
    gradient_tangent(E, group.E0, group.BX, group.BY, group.dX0, group.dY0, group.w, group.C,
                     group.cidx, want_K, ge, Ke)
    grad[:] = 0.0
    if want_K:
        K[:, :] = 0.0
    scatter(ge, Ke, group.vidx, group.midx, grad, K, want_K)


class GreenPlanar:
    """Planar Green-Lagrange strains in the element's local frame, Voigt
    ``[eps_xx, eps_yy, 2 eps_xy]``, from the gradients ``r_x``, ``r_y`` (dim 2)."""

    dim = 2
    voigt = 3
    energy = staticmethod(energy)
    gradient_tangent = staticmethod(gradient_tangent)
    band_group = staticmethod(band_group)
