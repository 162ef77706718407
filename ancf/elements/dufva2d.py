"""Dufva's shear-deformable planar belt element (12 DOF; thesis 3.1, Eqs 3.1-3.19).

Nodal coordinates per node: ``r``, ``r_x``, ``r_y`` (family ``cubic2d``, Eq. 3.11),
element coordinates ordered ``k * 2 + d`` (shape function k, component d) as in
:mod:`ancf.elements.green2d`.  Kinematics (Eqs 3.1-3.12): the centre line
``r_c = S e`` at y = 0 with ``a = r_c,x`` and ``c = r_c,xx``; ``t = a/|a|`` (3.4),
``n = Ĩ t`` (3.5-3.6); the section vector ``r_s = (I + Ĩ sin γ) Ĩ t = n - sin γ t``
(3.10); ``sin γ`` linear between its nodal values (3.12).  Ref. [54] ties the nodal
shear angle to the nodal slopes; here it is read as the angle between the two
nodal slope vectors, ``(sin γ)^K = -(r_x^K . r_y^K)/(|r_x^K| |r_y^K|)``, so that
``r_s`` is parallel to ``r_y^K`` at the nodes to first order in γ.

Strain energy (J): Eq. 3.18 (axial part scaled by ``alpha1``, bending parts by
``alpha2``) + Eq. 3.19 (shear, scaled by ``alpha2``, G = E/(2(1 + nu)), factor
``ks``) + the transverse term of Eq. 2.18, ``E/2 int eps_yy^2 dV`` with
``eps_yy`` linear between ``eps_yy^K = 1/2 (r_y^K . r_y^K - 1)`` (thesis line
~792); the transverse term is NOT scaled by alpha.  Section integrals are exact
(``A = b h``, ``int y^2 dA = b h^3/12``, ``int y^4 dA = b h^5/80``; odd powers
vanish), the axis is integrated by ``nx`` Gauss points.

Axial strain law (``axial``): ``green`` (the thesis's, above: the axial energy density
``1/2 E A alpha1 eps_G^2`` with the Green strain ``eps_G = (|a|^2 - 1)/2``, the force
``N = E A alpha1 eps_G`` of Eq. 3.17) or ``engineering`` (Exudyn's ANCFCable2D:
``1/2 E A alpha1 (|a| - 1)^2``, the force ``N = E A alpha1 (|a| - 1)``, the real force
in the belt).  The engineering term is added to the generated density by the kernels
from the generated axial strain ``eps = |a| - 1`` (its gradient and Hessian, shared with
the damping): ``w_e = k6/2 eps^2``, ``dw_e = k6 eps deps``, ``d2w_e = k6 (deps deps^T +
eps d2eps)`` with ``k6 = E A alpha1`` and ``k0 = 0``; for ``green`` ``k6 = 0`` and the
term is skipped.

The reference is a straight, unstrained element of length l (thesis: "initially
the beam is coincident with the global coordinate system and not curved"): the
energy is zero iff |a| = 1, the centre line does not turn, sin γ = 0 and
|r_y^K| = 1, whatever ``e0`` is.  A mesh laid on a curve is therefore
pre-stressed in bending (as a belt wrapped on pulleys is).

The energy density per unit length and its derivatives in the point variables
(a, c, sin γ, d sin γ/dx, eps_yy) and those of the nodal shear sine are generated
by SymPy (``analytic/dufva_belt.py`` -> ``_dufva_generated.py``); the compiled
kernels :func:`energy` and :func:`gradient_tangent` chain them to the element
coordinates, giving the exact gradient and the exact tangent.

Strain-rate damping (:func:`damping_forces`; Exudyn's ANCFCable2D
``physicsAxialDamping`` / ``physicsBendingDamping``): the generalised forces

    Q_d = int (dEA eps' deps/de + dEI kappa' dkappa/de) dx

with the axial strain ``eps = |a| - 1`` and the bending strain ``kappa = (a x c)/|a|^2 +
s_x`` (SymPy: ``analytic/dufva_belt.py``), their rates ``eps' = deps/de e'`` and the
same Gauss points as the elastic forces; the exact Jacobians are dQ_d/de = int dEA
(deps/de (d2eps/de2 e')^T + eps' d2eps/de2) dx + (the same for kappa) and dQ_d/de' =
int (dEA deps/de deps/de^T + dEI dkappa/de dkappa/de^T) dx.  An axial damping alone (dEI =
0), with or without dQ_d/de, also comes with the elastic forces in one pass
(:func:`gradient_tangent_damped`).
"""
from __future__ import annotations

import math

import numpy as np
from numba import njit

from ancf.elements import _dufva_generated as gen
from ancf.elements import _generated as shape_gen
from ancf.elements.compiled_element import BeltElement, check

_NODE = 6  # coordinates per node: r, r_x, r_y
_SHAPES = 6  # shape functions per element (cubic2d), each with 2 coordinates
AXIAL_LAWS = ("green", "engineering")  # the axial strain laws (module docstring)


@njit(cache=True)
def _centre_line(E, BX, BXX, e, q):
    """a = r_c,x and c = r_c,xx at point q of element e."""
    a0 = a1 = c0 = c1 = 0.0
    for k in range(E.shape[1]):
        a0 += BX[e, q, k] * E[e, k, 0]
        a1 += BX[e, q, k] * E[e, k, 1]
        c0 += BXX[e, q, k] * E[e, k, 0]
        c1 += BXX[e, q, k] * E[e, k, 1]
    return a0, a1, c0, c1


@njit(cache=True)
def _transverse_strain(E, e, node):
    """eps_yy^K = 1/2 (r_y.r_y - 1) of node 0 (I) or 1 (J)."""
    k = 3 * node + 2
    return 0.5 * (E[e, k, 0] ** 2 + E[e, k, 1] ** 2 - 1.0)


@njit(cache=True)
def energy(E, data):
    """Strain energy per element (nel,), J.  E: (nel, 6, 2); data: ``kernel_data()``."""
    BX, BXX, xi, wq, lengths, k = data
    nel, nq = wq.shape
    out = np.zeros(nel)
    for e in range(nel):
        sI = gen.shear_sine(E[e, 1, 0], E[e, 1, 1], E[e, 2, 0], E[e, 2, 1])
        sJ = gen.shear_sine(E[e, 4, 0], E[e, 4, 1], E[e, 5, 0], E[e, 5, 1])
        yI, yJ = _transverse_strain(E, e, 0), _transverse_strain(E, e, 1)
        for q in range(nq):
            a0, a1, c0, c1 = _centre_line(E, BX, BXX, e, q)
            z = xi[q]
            s = (1.0 - z) * sI + z * sJ
            ey = (1.0 - z) * yI + z * yJ
            out[e] += wq[e, q] * gen.density(a0, a1, c0, c1, s, (sJ - sI) / lengths[e], ey, k)
            if k[6] != 0.0:
                out[e] += wq[e, q] * 0.5 * k[6] * (math.sqrt(a0 * a0 + a1 * a1) - 1.0) ** 2
    return out


@njit(cache=True)
def _add_engineering(k6, a0, a1, want_K, gw, H, ge, He):
    """Add the engineering axial density's gradient k6 eps deps to gw (7,) and, if
    want_K, its Hessian k6 (deps deps^T + eps d2eps) to H (7, 7); ge (2,), He (2, 2): work
    arrays (eps depends on the slopes a alone: its derivatives by a, the same sums as
    those of the seven point variables)."""
    if want_K:
        gen.axial_slope_hess(a0, a1, ge, He)
    else:
        gen.axial_slope_grad(a0, a1, ge)
    eps = math.sqrt(a0 * a0 + a1 * a1) - 1.0
    for i in range(2):
        gw[i] += k6 * eps * ge[i]
        if want_K:
            for j in range(2):
                H[i, j] += k6 * (ge[i] * ge[j] + eps * He[i, j])


@njit(cache=True)
def _point_jacobian(BX, BXX, e, q, z, inv_l, gI, gJ, E, Jv):
    """d(a0, a1, c0, c1, s, s_x, eps_yy)/de (7, 12) at point q (z = x/l)."""
    Jv[:] = 0.0
    for k in range(BX.shape[2]):
        Jv[0, 2 * k] = Jv[1, 2 * k + 1] = BX[e, q, k]
        Jv[2, 2 * k] = Jv[3, 2 * k + 1] = BXX[e, q, k]
    for i in range(4):
        Jv[4, 2 + i] = (1.0 - z) * gI[i]
        Jv[4, _NODE + 2 + i] = z * gJ[i]
        Jv[5, 2 + i] = -gI[i] * inv_l
        Jv[5, _NODE + 2 + i] = gJ[i] * inv_l
    for d in range(2):
        Jv[6, 4 + d] = (1.0 - z) * E[e, 2, d]
        Jv[6, _NODE + 4 + d] = z * E[e, 5, d]


@njit(cache=True)
def _add_nodal_curvature(Ke, bI, bJ, hI, hJ, yI, yJ):
    """Ke += the second derivatives of the nodal quantities: bK d2s^K + yK d2eps_yy^K."""
    for i in range(4):
        for j in range(4):
            Ke[2 + i, 2 + j] += bI * hI[i, j]
            Ke[_NODE + 2 + i, _NODE + 2 + j] += bJ * hJ[i, j]
    for d in range(2):
        Ke[4 + d, 4 + d] += yI
        Ke[_NODE + 4 + d, _NODE + 4 + d] += yJ


@njit(cache=True)
def _nodal_shear_sine(x, y, want_K, grad, hess):
    """(sin gamma)^K of a node with slopes x = r_x, y = r_y (2,), its gradient in (r_x, r_y)
    into grad (4,) and, if want_K, its Hessian into hess (4, 4).  The node's slopes, not
    its index: a constant index would compile it once per node."""
    if want_K:
        return gen.shear_sine_hess(x[0], x[1], y[0], y[1], grad, hess)
    return gen.shear_sine_grad(x[0], x[1], y[0], y[1], grad)


@njit(cache=True)
def gradient_tangent(E, data, want_K, g, K):
    """Add dU/de (nel, 12) to ``g`` (N or N m) and, if ``want_K``, d2U/de2 (nel, 12, 12)
    to ``K``.  E: (nel, 6, 2) C-contiguous; data: ``DufvaBelt2D.kernel_data()``."""
    _elastic(E, E, data, 0.0, want_K, False, False, g, K, K)


@njit(cache=True)
def gradient_tangent_damped(E, V, data, dEA, want_K, want_Kd, want_C, g, K, C):
    """:func:`gradient_tangent` and the axial strain-rate damping of dEA (N s; dEI = 0) of
    ``damping_parts(E, V, data, (dEA, 0), want_Kd, want_C, g, K, C)`` in one pass: each
    element's elastic terms, then its damping's (dQ_d/de into K if ``want_Kd``), with the
    slopes and their axial strain's derivatives formed once per point; both kernels' sums
    bit for bit (each g[e], K[e] gets its terms in the same order)."""
    _elastic(E, V, data, dEA, want_K, want_Kd, want_C, g, K, C)


@njit(cache=True)
def _elastic(E, V, data, dEA, want_K, want_Kd, want_C, g, K, C):
    """:func:`gradient_tangent_damped` (dEA = 0: :func:`gradient_tangent`; V, C unread)."""
    BX, BXX, xi, wq, lengths, k = data
    nel, nq = wq.shape
    nd = 2 * E.shape[1]
    gI, gJ, gw = np.empty(4), np.empty(4), np.empty(7)
    hI, hJ, H = np.empty((4, 4)), np.empty((4, 4)), np.empty((7, 7))
    Jv, HJ = np.empty((7, nd)), np.empty((7, nd))
    Ke = np.empty((nd, nd))
    ge, He = np.empty(2), np.empty((2, 2))
    ax, hx, G, Hs = np.empty((nq, 2)), np.empty((nq, 2, 2)), np.empty(nd), np.empty((nd, nd))
    W = np.empty((2, nd))
    for e in range(nel):
        sI = _nodal_shear_sine(E[e, 1], E[e, 2], want_K, gI, hI)
        sJ = _nodal_shear_sine(E[e, 4], E[e, 5], want_K, gJ, hJ)
        yI, yJ = _transverse_strain(E, e, 0), _transverse_strain(E, e, 1)
        inv_l = 1.0 / lengths[e]
        bI = bJ = wI = wJ = 0.0
        Ke[:] = 0.0
        for q in range(nq):
            a0, a1, c0, c1 = _centre_line(E, BX, BXX, e, q)
            z, ww = xi[q], wq[e, q]
            s, sx = (1.0 - z) * sI + z * sJ, (sJ - sI) * inv_l
            ey = (1.0 - z) * yI + z * yJ
            if want_K:
                gen.density_hess(a0, a1, c0, c1, s, sx, ey, k, gw, H)
            else:
                gen.density_grad(a0, a1, c0, c1, s, sx, ey, k, gw)
            if k[6] != 0.0:
                _add_engineering(k[6], a0, a1, want_K, gw, H, ge, He)
            elif dEA != 0.0:
                gen.axial_slope_grad(a0, a1, ge)
            ax[q, 0], ax[q, 1] = ge[0], ge[1]
            if want_Kd:
                gen.axial_slope_hess(a0, a1, ge, hx[q])
            _add_point_gradient(g, e, q, ww, z, inv_l, BX, BXX, gI, gJ, E, gw)
            if want_K:
                _point_jacobian(BX, BXX, e, q, z, inv_l, gI, gJ, E, Jv)
                _add_point_tangent(Ke, ww, Jv, H, HJ)
                bI += ww * ((1.0 - z) * gw[4] - inv_l * gw[5])
                bJ += ww * (z * gw[4] + inv_l * gw[5])
                wI += ww * (1.0 - z) * gw[6]
                wJ += ww * z * gw[6]
        if want_K:
            for a in range(nd):
                for b in range(a + 1, nd):
                    Ke[b, a] = Ke[a, b]
            _add_nodal_curvature(Ke, bI, bJ, hI, hJ, wI, wJ)
            for a in range(nd):
                for b in range(nd):
                    K[e, a, b] += Ke[a, b]
        if dEA != 0.0:
            _element_axial_damping(e, V, BX, wq, dEA, ax, want_C, g, C, G)
            if want_Kd:
                _element_axial_damping_tangent(e, V, BX, wq, dEA, ax, hx, K, G, Hs, W)


@njit(cache=True)
def _add_point_gradient(g, e, q, ww, z, inv_l, BX, BXX, gI, gJ, E, gw):
    """g[e] += ww Jv^T gw at point q (z = x/l) with the entries of Jv
    (:func:`_point_jacobian`) formed as there, over the rows that may be nonzero in each
    column 2 m + d (:func:`_add_point_tangent`): the dense sums bit for bit, without Jv."""
    for m in range(_SHAPES):
        node, slot = m // 3, m % 3
        for d in range(2):
            acc = 0.0 + BX[e, q, m] * gw[d]
            acc += BXX[e, q, m] * gw[2 + d]
            if slot != 0:
                i = 2 * (slot - 1) + d
                if node == 0:
                    acc += ((1.0 - z) * gI[i]) * gw[4]
                    acc += (-gI[i] * inv_l) * gw[5]
                    if slot == 2:
                        acc += ((1.0 - z) * E[e, 2, d]) * gw[6]
                else:
                    acc += (z * gJ[i]) * gw[4]
                    acc += (gJ[i] * inv_l) * gw[5]
                    if slot == 2:
                        acc += (z * E[e, 5, d]) * gw[6]
            g[e, 2 * m + d] += ww * acc


@njit(cache=True)
def _add_point_tangent(Ke, ww, Jv, H, HJ):
    """Ke += ww Jv^T H Jv (upper triangle): the sums of
    :func:`ancf.elements.compiled_element.add_point_tangent` bit for bit, over the rows of
    Jv (:func:`_point_jacobian`) that may be nonzero in column 2 m + d, in increasing order
    from 0.0: a (row d) and c (row 2 + d) of every shape function m, s and s_x (rows 4, 5)
    of the nodal slopes r_x, r_y (m % 3 = 1, 2), eps_yy (row 6) of r_y (the terms left
    out are products with an exact zero; half the products, loops of known length)."""
    for i in range(7):
        for m in range(_SHAPES):
            for d in range(2):
                b = 2 * m + d
                acc = 0.0 + H[i, d] * Jv[d, b]
                acc += H[i, 2 + d] * Jv[2 + d, b]
                if m % 3 != 0:
                    acc += H[i, 4] * Jv[4, b]
                    acc += H[i, 5] * Jv[5, b]
                    if m % 3 == 2:
                        acc += H[i, 6] * Jv[6, b]
                HJ[i, b] = ww * acc
    for m in range(_SHAPES):
        for d in range(2):
            a = 2 * m + d
            for b in range(a, 2 * _SHAPES):
                acc = 0.0 + Jv[d, a] * HJ[d, b]
                acc += Jv[2 + d, a] * HJ[2 + d, b]
                if m % 3 != 0:
                    acc += Jv[4, a] * HJ[4, b]
                    acc += Jv[5, a] * HJ[5, b]
                    if m % 3 == 2:
                        acc += Jv[6, a] * HJ[6, b]
                Ke[a, b] += acc


@njit(cache=True)
def _live_tangent(Hs, Jv, Hm, HJ, live):
    """Hs += Jv^T Hm Jv (upper triangle) as
    ``compiled_element.add_point_tangent(Hs, 1.0, Jv, Hm, HJ)``, over the point variables
    with a nonzero row of the symmetric Hm only (live: (7,) int work): the terms left out
    are products with an exact zero, so the sums are the same (the axial strain's Hessian
    has 2 live rows of 7: a seventh of the work)."""
    nv, nd = Jv.shape
    nl = 0
    for i in range(nv):
        for j in range(nv):
            if Hm[i, j] != 0.0:
                live[nl] = i
                nl += 1
                break
    for t in range(nl):
        i = live[t]
        for b in range(nd):
            acc = 0.0
            for u in range(nl):
                acc += Hm[i, live[u]] * Jv[live[u], b]
            HJ[i, b] = acc
    for a in range(nd):
        for b in range(a, nd):
            acc = 0.0
            for t in range(nl):
                acc += Jv[live[t], a] * HJ[live[t], b]
            Hs[a, b] += acc


@njit(cache=True)
def _measure_hessian(Jv, gm, Hm, hI, hJ, inv_l, z, Hs, HJ, live):
    """Hs = d2m/de2 (nd, nd) of a point measure m with point gradient gm and Hessian Hm:
    Jv^T Hm Jv and the nodal shear sines' Hessians hI, hJ times dm/d(s, s_x)."""
    Hs[:] = 0.0
    _live_tangent(Hs, Jv, Hm, HJ, live)
    for a in range(Hs.shape[0]):
        for b in range(a + 1, Hs.shape[0]):
            Hs[b, a] = Hs[a, b]
    bI = (1.0 - z) * gm[4] - inv_l * gm[5]
    bJ = z * gm[4] + inv_l * gm[5]
    if bI != 0.0 or bJ != 0.0:  # else it adds exact zeros
        _add_nodal_curvature(Hs, bI, bJ, hI, hJ, 0.0, 0.0)


@njit(cache=True)
def _add_damping(e, ww, d, Jv, gm, Hm, ve, want_K, want_C, g, K, C, hI, hJ, inv_l, z, Hs, HJ,
                 G, live):
    """A point's damping force ww d m' dm/de of the measure m (gradient gm, Hessian Hm
    in the point variables) into g[e] and its Jacobians into K[e] (if want_K) and C[e]
    (if want_C)."""
    nd = ve.size
    rate = 0.0
    for a in range(nd):
        acc = 0.0
        for i in range(7):
            acc += Jv[i, a] * gm[i]
        G[a] = acc
        rate += acc * ve[a]
    f = ww * d
    for a in range(nd):
        g[e, a] += f * rate * G[a]
    if want_C:
        for a in range(nd):
            for b in range(nd):
                C[e, a, b] += f * G[a] * G[b]
    if not want_K:
        return
    _measure_hessian(Jv, gm, Hm, hI, hJ, inv_l, z, Hs, HJ, live)
    u = np.dot(Hs, ve)
    for a in range(nd):
        for b in range(nd):
            K[e, a, b] += f * (G[a] * u[b] + rate * Hs[a, b])


@njit(cache=True)
def _point_measure(m, want_J, a0, a1, c0, c1, s, sx, gm, Hm):
    """Gradient gm (7,) and, if want_J, Hessian Hm (7, 7) in the point variables of the
    axial strain (m = 0) or the bending strain (m = 1)."""
    if m == 0 and want_J:
        gen.axial_strain_hess(a0, a1, c0, c1, s, sx, 0.0, gm, Hm)
    elif m == 0:
        gen.axial_strain_grad(a0, a1, c0, c1, s, sx, 0.0, gm)
    elif want_J:
        gen.bending_strain_hess(a0, a1, c0, c1, s, sx, 0.0, gm, Hm)
    else:
        gen.bending_strain_grad(a0, a1, c0, c1, s, sx, 0.0, gm)


@njit(cache=True)
def damping_parts(E, V, data, d, want_K, want_C, g, K, C):
    """:func:`damping_forces` with dQ_d/de (want_K) and dQ_d/de' (want_C) apart (runtime
    flags: called with literal ones, numba would compile it once per literal, so
    :func:`damping_forces_rate` passes ``bool(...)``); an axial damping alone (dEI = 0)
    by :func:`_axial_damping`."""
    if d[1] == 0.0:
        _axial_damping(E, V, data, d[0], want_K, want_C, g, K, C)
    else:
        measures_damping(E, V, data, d, want_K, want_C, g, K, C)


@njit(cache=True)
def measures_damping(E, V, data, d, want_K, want_C, g, K, C):
    """:func:`damping_parts` through each point's Jacobian of the point variables and the
    strain measures' derivatives in them (any dEA, dEI; :func:`_axial_damping` gives its
    sums for dEI = 0 in fewer operations)."""
    BX, BXX, xi, wq, lengths, k = data
    nel, nq = wq.shape
    nd = 2 * E.shape[1]
    gI, gJ, gm = np.empty(4), np.empty(4), np.empty(7)
    hI, hJ, Hm = np.zeros((4, 4)), np.zeros((4, 4)), np.zeros((7, 7))
    Jv, HJ, Hs, G = np.empty((7, nd)), np.empty((7, nd)), np.empty((nd, nd)), np.empty(nd)
    live = np.empty(7, dtype=np.int64)
    for e in range(nel):
        sI = _nodal_shear_sine(E[e, 1], E[e, 2], want_K, gI, hI)
        sJ = _nodal_shear_sine(E[e, 4], E[e, 5], want_K, gJ, hJ)
        ve = V[e].ravel().copy()
        inv_l = 1.0 / lengths[e]
        for q in range(nq):
            a0, a1, c0, c1 = _centre_line(E, BX, BXX, e, q)
            z, ww = xi[q], wq[e, q]
            s, sx = (1.0 - z) * sI + z * sJ, (sJ - sI) * inv_l
            _point_jacobian(BX, BXX, e, q, z, inv_l, gI, gJ, E, Jv)
            for m in range(2):
                if d[m] == 0.0:
                    continue
                _point_measure(m, want_K, a0, a1, c0, c1, s, sx, gm, Hm)
                _add_damping(e, ww, d[m], Jv, gm, Hm, ve, want_K, want_C, g, K, C, hI, hJ,
                             inv_l, z, Hs, HJ, G, live)


@njit(cache=True)
def _axial_damping(E, V, data, dEA, want_K, want_C, g, K, C):
    """:func:`damping_parts` of the axial strain alone (dEI = 0): its gradient deps/de = Jv^T
    deps/dv has a (Jv's rows 0, 1) alone, so dm/de[2 k + d] = BX_k deps/da_d, and its
    Hessian so (:func:`_slope_hessian`): the sums of :func:`_add_damping` bit for bit (they
    add exact zeros besides) without the point Jacobian and the nodal shear sines."""
    BX, BXX, xi, wq, lengths, k = data
    nel, nq = wq.shape
    nd = 2 * E.shape[1]
    ge, ax, hx = np.empty(2), np.empty((nq, 2)), np.empty((nq, 2, 2))
    G, Hs, W = np.empty(nd), np.empty((nd, nd)), np.empty((2, nd))
    for e in range(nel):
        for q in range(nq):
            a0, a1, c0, c1 = _centre_line(E, BX, BXX, e, q)
            if want_K:
                gen.axial_slope_hess(a0, a1, ge, hx[q])
            else:
                gen.axial_slope_grad(a0, a1, ge)
            ax[q, 0], ax[q, 1] = ge[0], ge[1]
        _element_axial_damping(e, V, BX, wq, dEA, ax, want_C, g, C, G)
        if want_K:
            _element_axial_damping_tangent(e, V, BX, wq, dEA, ax, hx, K, G, Hs, W)


@njit(cache=True)
def _element_axial_damping(e, V, BX, wq, dEA, ax, want_C, g, C, G):
    """Element e's axial damping forces into g[e] and, if want_C, dQ_d/de' into C[e], from
    the axial strain's gradient ax[q] (2,) by the slopes at its points (G: work)."""
    ns = V.shape[1]
    for q in range(wq.shape[1]):
        rate = 0.0
        for m in range(ns):
            for d in range(2):
                G[2 * m + d] = 0.0 + BX[e, q, m] * ax[q, d]
                rate += G[2 * m + d] * V[e, m, d]
        f = wq[e, q] * dEA
        for a in range(2 * ns):
            g[e, a] += f * rate * G[a]
        if want_C:
            for a in range(2 * ns):
                for b in range(2 * ns):
                    C[e, a, b] += f * G[a] * G[b]


@njit(cache=True)
def _element_axial_damping_tangent(e, V, BX, wq, dEA, ax, hx, K, G, Hs, W):
    """Element e's dQ_d/de of its axial damping into K[e], from the axial strain's gradient
    ax[q] (2,) and Hessian hx[q] (2, 2) by the slopes at its points (G, Hs, W (2, nd):
    work): per point f (G u^T + m' Hs) with G = dm/de, m' = G.e', Hs = d2m/de2
    (:func:`_slope_hessian`), u = Hs e', the sums of :func:`_add_damping` bit for bit."""
    ns = V.shape[1]
    ve, u = W[0], W[1]
    for a in range(2 * ns):
        ve[a] = V[e, a // 2, a % 2]
    for q in range(wq.shape[1]):
        rate = 0.0
        for a in range(2 * ns):
            G[a] = 0.0 + BX[e, q, a // 2] * ax[q, a % 2]
            rate += G[a] * ve[a]
        f = wq[e, q] * dEA
        _slope_hessian(BX, e, q, hx[q], Hs)
        np.dot(Hs, ve, u)
        for a in range(2 * ns):
            for b in range(2 * ns):
                K[e, a, b] += f * (G[a] * u[b] + rate * Hs[a, b])


@njit(cache=True)
def _slope_hessian(BX, e, q, h, Hs):
    """Hs = d2m/de2 (nd, nd) of a point measure m of the slopes alone with Hessian h (2, 2)
    by them: Hs[2 k + d, 2 m + f] = BX_k (h_df BX_m), the upper triangle's products of
    :func:`_measure_hessian` (its other terms are exact zeros) mirrored as there."""
    ns = BX.shape[2]
    for k in range(ns):
        for d in range(2):
            a = 2 * k + d
            for b in range(a, 2 * ns):
                Hs[a, b] = BX[e, q, k] * (h[d, b % 2] * BX[e, q, b // 2])
    for a in range(2 * ns):
        for b in range(a + 1, 2 * ns):
            Hs[b, a] = Hs[a, b]


@njit(cache=True)
def damping_forces(E, V, data, d, want_J, g, K, C):
    """Add the strain-rate damping forces Q_d (nel, 12) to ``g`` (N or N m) and, if
    ``want_J``, dQ_d/de to ``K`` and dQ_d/de' to ``C`` (nel, 12, 12) (module docstring).
    E, V: (nel, 6, 2) coordinates and velocities; d = (dEA N s, dEI N m^2 s)."""
    damping_parts(E, V, data, d, want_J, want_J, g, K, C)


@njit(cache=True)
def damping_forces_rate(E, V, data, d, g, C):
    """:func:`damping_forces` with dQ_d/de' (into ``C``) but not dQ_d/de: an iteration
    matrix's approximation (dQ_d/de is proportional to the strain rates: int dEA (deps/de
    (d2eps/de2 e')^T + eps' d2eps/de2) dx) that costs a fraction of the exact one."""
    damping_parts(E, V, data, d, bool(False), bool(True), g, np.zeros((0, 0, 0)), C)


class DufvaBelt2D(BeltElement):
    """Planar belt elements (arguments: :class:`BeltElement`; e0 (nel, 12); ``axial`` the
    axial strain law, one of :data:`AXIAL_LAWS`, module docstring)."""

    family = "cubic2d"
    slots = ("r", "r_x", "r_y")
    dim = 2
    shape_xx = staticmethod(shape_gen.cubic2d_xx)
    kernel_energy = staticmethod(energy)
    kernel_gradient_tangent = staticmethod(gradient_tangent)

    def __init__(self, lengths, e0, section, E, nu, rho=0.0, alpha1=1.0, alpha2=1.0,
                 ks=5.0 / 6.0, nx=5, axial="green"):
        check("axial", axial, lambda v: v in AXIAL_LAWS, f"one of {', '.join(AXIAL_LAWS)}")
        self.axial = axial
        super().__init__(lengths, e0, section, E, nu, rho, alpha1, alpha2, ks, nx)

    def density_coefficients(self, section, E, G, alpha1, alpha2, ks) -> np.ndarray:
        """The density's coefficients (N, N m^2, N m^4, N, N m^2, N) and the engineering
        axial stiffness k6 (N): (k0, k6) = (E A alpha1/8, 0) (green) or (0, E A alpha1)."""
        A, I2, I4 = section.area, section.second_moment, section.b * section.h**5 / 80.0
        EA1 = E * alpha1 * A
        k0, k6 = (EA1 / 8, 0.0) if self.axial == "green" else (0.0, EA1)
        return np.array([k0, E * alpha2 * I2 / 2, E * alpha2 * I4 / 8,
                         ks * G * alpha2 * A / 2, ks * G * alpha2 * I2 / 2, E * A / 2, k6])

    def axial_strain(self, a) -> np.ndarray:
        """The law's axial strain of the slopes a (..., 2): (|a|^2 - 1)/2 or |a| - 1."""
        P = np.einsum("...d,...d->...", a, a)
        return 0.5 * (P - 1.0) if self.axial == "green" else np.sqrt(P) - 1.0
