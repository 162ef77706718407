"""Distributed penalty contact between thin ANCF plates and cylindrical pulleys
(thesis 4.5, Eqs 4.43-4.45), compiled (numba); the 3D counterpart of
:mod:`ancf.belts.contact2d` (Eqs 3.20-3.27).

The contact acts on the mid surface of the ``plate36`` element (the thin plate has
no thickness coordinate, as the planar belt's contact acts on its centre line).  At
every point of an n x n Gauss rule, with r = S0 e (m), rdot = S0 edot (m/s), and
for a pulley of centre o (m), unit axis p, radius R (m), angular velocity omega
(rad/s, right-handed about p) and centre velocity odot (m/s):

    r_n  = r - o,  N = r_n - (r_n . p) p       radial vector                     (4.44)
    d    = R - |N|                              penetration, m                    (4.43)
    n    = N / |N|,  t = p x n                  outward normal, circumferential
    ddot = -n . (rdot - odot)                   penetration rate, m/s
    F_n  = max(k_p d + c_p ddot, 0)  if d >= 0, else 0;  N/m^2
    u    = odot + omega R t                     pulley surface velocity, m/s
    v_s  = w - (w . n) n,  w = rdot - u          sliding velocity in the tangent
                                                plane (circumferential and axial)
    f_t  = -nu_s v_s                  if nu_s |v_s| <= mu F_n     friction, N/m^2
         = -mu F_n v_s / |v_s|        otherwise
    f    = F_n n + f_t                          force per unit area on the plate, N/m^2

The clamp F_n >= 0 and the tri-linear creep-rate law are those of :mod:`ancf.belts.contact2d`
(there: why the clamp), the friction now a vector in the tangent plane (the law is
:mod:`ancf.belts.friction`'s, on v = v_s; this module supplies the geometry); the linear
branch is smooth through v_s = 0, and the saturated branch has |v_s| > 0.  The
surface speed is omega R (R, not |N|), as in Eq 3.25.

Generalised force (Eq 4.45) and pulley moment about its axis (the normal force
passes through the axis and has no moment: (r - o) x n . p = 0), Gauss quadrature
over each element's reference rectangle:

    Q_e += sum_q w_q S0_q^T f_q                                  N (per coordinate)
    T_p += sum_q w_q ((r - o) x (-f_q)) . p = -sum_q w_q |N| t . f_t    N m

Element coordinates are ordered ``k * 3 + d`` (shape function k of ``plate36_S``,
component d), 36 per element; E, V are (nel, 12, 3).  Forces are per unit area of
the reference rectangle (the weights w).  A point exactly on a pulley axis has no
normal; the penalty regime (d << R) never reaches it.  With a plane motion about an
axis along z, the law per unit width is the planar one of :mod:`ancf.belts.contact2d` with
k_p, c_p, nu_s divided by the width (tests/belts/test_contact3d.py).
"""
from __future__ import annotations

from math import comb

import numpy as np
from numba import njit

from ancf.belts import friction
from ancf.common.leaf import leaf
from ancf.belts.contact_common import BOUND_MARGIN, positive_lengths
from ancf.elements.basis import plate36_S
from ancf.core.quadrature import gauss01

#: n x n Gauss rules over each element's mid surface (the thesis uses 81 points).
SUPPORTED_RULES = (25, 49, 81)


def _bernstein_controls():
    """C (16, 12): the plate36 field of the unit square is cubic in x and in y
    separately, so it is the tensor Bernstein patch sum_ij B_i(x) B_j(y) P_ij with
    P_ij = sum_k C[4 i + j, k] e_k (interpolation at a 4 x 4 grid, exact but for
    round-off).  For an a x b element the r_x columns scale with a, the r_y ones with b."""
    g = np.linspace(0.0, 1.0, 4)
    X, Y = (v.ravel() for v in np.meshgrid(g, g, indexing="ij"))

    def bern(i, t):
        return comb(3, i) * t**i * (1.0 - t) ** (3 - i)

    M = np.stack([bern(i, X) * bern(j, Y) for i in range(4) for j in range(4)], axis=1)
    return np.ascontiguousarray(np.linalg.solve(M, plate36_S(X, Y, 1.0, 1.0)))


def _unit_moments():
    """int S_1 and int S_2 (the r_x and r_y functions of node A) over the unit square;
    over an a x b element they are a^2 b m_x and a b^2 m_y (the kernel's side lengths)."""
    t, w = gauss01(4)
    X, Y = (v.ravel() for v in np.meshgrid(t, t, indexing="ij"))
    W = np.outer(w, w).ravel()
    S = plate36_S(X, Y, 1.0, 1.0)
    return np.array([W @ S[:, 1], W @ S[:, 2]])


_CONTROLS = _bernstein_controls()
_MOMENTS = _unit_moments()


def contact_points3d(lengths, widths, rule):
    """Shape functions and weights at the contact points of each element.

    ``lengths``, ``widths`` (nel,) reference element sides along x and y, m; ``rule``
    one of :data:`SUPPORTED_RULES` (n x n Gauss points).  Returns ``S0`` (nel, nq, 12)
    ``plate36`` shape functions on the mid surface, point q = n i + j at
    (x_i a, y_j b), and ``w`` (nel, nq) Gauss weights times the element area, m^2.
    """
    if rule not in SUPPORTED_RULES or isinstance(rule, bool):
        raise ValueError(f"contact_points3d: rule must be one of {SUPPORTED_RULES} "
                         f"(n x n Gauss points; got {rule!r})")
    a, b = (positive_lengths(name, v, "contact_points3d: ")
            for name, v in (("lengths", lengths), ("widths", widths)))
    if a.shape != b.shape:
        raise ValueError(f"contact_points3d: lengths and widths differ in shape "
                         f"({a.shape} != {b.shape})")
    n = int(round(np.sqrt(rule)))
    t, wg = gauss01(n)
    X, Y = (v.ravel() for v in np.meshgrid(t, t, indexing="ij"))
    W = np.outer(wg, wg).ravel()
    A, B = a[:, None], b[:, None]
    S0 = np.ascontiguousarray(plate36_S(X[None, :] * A, Y[None, :] * B, A, B))
    return S0, W[None, :] * A * B


@leaf
def _sides(S0, w, e):
    """Element sides a, b (m) from its rule: sum w = a b, sum w S_1 = a^2 b m_x,
    sum w S_2 = a b^2 m_y (exact for every supported rule)."""
    area = sx = sy = 0.0
    for q in range(w.shape[1]):
        area += w[e, q]
        sx += w[e, q] * S0[e, q, 1]
        sy += w[e, q] * S0[e, q, 2]
    return sx / (_MOMENTS[0] * area), sy / (_MOMENTS[1] * area)


@leaf
def _control_points(E, e, a, b, P):
    """P (16, 3): the Bernstein control points of element e (sides a, b, m); the mid
    surface lies in their convex hull (see ``_bernstein_controls``)."""
    P[:] = 0.0
    for i in range(16):
        for k in range(12):
            s = k % 3
            ck = _CONTROLS[i, k] * (a if s == 1 else (b if s == 2 else 1.0))
            if ck != 0.0:
                for c in range(3):
                    P[i, c] += ck * E[e, k, c]


@leaf
def _may_touch(P, o, p, R, X):
    """False only if the element's mid surface provably stays outside the pulley's
    cylinder |N| < R.  N = (I - p p^T)(r - o) is affine in r, so it maps the convex
    hull of the control points P onto the hull of their images X_i = N(P_i) in the
    plane normal to the axis, which lies in the disc of centre c (their mean) and
    radius r_b = max |X_i - c|; hence |N| >= |c| - r_b on the whole surface."""
    c0 = c1 = c2 = big = 0.0
    for i in range(16):
        xp = (P[i, 0] - o[0]) * p[0] + (P[i, 1] - o[1]) * p[1] + (P[i, 2] - o[2]) * p[2]
        big = max(big, abs(P[i, 0]) + abs(P[i, 1]) + abs(P[i, 2]) + abs(xp))
        for c in range(3):
            X[i, c] = P[i, c] - o[c] - xp * p[c]
        c0 += X[i, 0] / 16.0
        c1 += X[i, 1] / 16.0
        c2 += X[i, 2] / 16.0
    rb = 0.0
    for i in range(16):
        rb = max(rb, np.sqrt((X[i, 0] - c0) ** 2 + (X[i, 1] - c1) ** 2 + (X[i, 2] - c2) ** 2))
    dist = np.sqrt(c0 * c0 + c1 * c1 + c2 * c2)
    scale = dist + rb + R + big + abs(o[0]) + abs(o[1]) + abs(o[2])
    return dist - rb <= R + BOUND_MARGIN * scale


@leaf
def _unit_axis(axes, p, out):
    s = np.sqrt(axes[p, 0] ** 2 + axes[p, 1] ** 2 + axes[p, 2] ** 2)
    for c in range(3):
        out[c] = axes[p, c] / s


@leaf
def _point_geometry(a, vr, p, R, om, prm, n, t, vs):
    """The geometry and normal force at one point, a = r - o (m), vr = rdot - odot (m/s),
    unit axis p: fills n, t, v_s (3,) and returns |N|, d, F_n, |v_s| and 0 out (d < 0),
    1 clamped (F_n = 0), -1 in contact (F_n > 0).  Computed in registers, stored once."""
    kp, cp = prm.k_p, prm.c_p
    ap = a[0] * p[0] + a[1] * p[1] + a[2] * p[2]
    n0, n1, n2 = a[0] - ap * p[0], a[1] - ap * p[1], a[2] - ap * p[2]
    rho = 0.0
    rho += n0 * n0
    rho += n1 * n1
    rho += n2 * n2
    rho = np.sqrt(rho)
    n0, n1, n2 = n0 / rho, n1 / rho, n2 / rho
    t0, t1, t2 = p[1] * n2 - p[2] * n1, p[2] * n0 - p[0] * n2, p[0] * n1 - p[1] * n0
    d = R - rho
    wn = n0 * vr[0] + n1 * vr[1] + n2 * vr[2]  # w = vr - omega R t and t . n = 0
    vs0 = vr[0] - om * R * t0 - wn * n0
    vs1 = vr[1] - om * R * t1 - wn * n1
    vs2 = vr[2] - om * R * t2 - wn * n2
    vsn = 0.0
    vsn += vs0 * vs0
    vsn += vs1 * vs1
    vsn += vs2 * vs2
    vsn = np.sqrt(vsn)
    n[0], n[1], n[2], t[0], t[1], t[2] = n0, n1, n2, t0, t1, t2
    vs[0], vs[1], vs[2] = vs0, vs1, vs2
    if d < 0.0:
        return rho, d, 0.0, vsn, 0
    Fn = kp * d - cp * wn
    if Fn <= 0.0:
        return rho, d, 0.0, vsn, 1
    return rho, d, Fn, vsn, -1


@leaf
def _point_law(a, vr, p, R, om, prm, n, t, vs, ft):
    """Contact law at one point (:func:`_point_geometry`): fills n, t, v_s, f_t (3,) and
    returns |N|, d, F_n, |v_s| and the branch: 0 out (d < 0), 1 clamped (F_n = 0), else
    the friction law's (creep-rate: 2 linear, 3 saturated)."""
    rho, d, Fn, vsn, where = _point_geometry(a, vr, p, R, om, prm, n, t, vs)
    ft[:] = 0.0
    if where >= 0:
        return rho, d, Fn, vsn, where
    return rho, d, Fn, vsn, friction.force((vs[0], vs[1], vs[2]), vsn, Fn, prm, ft)


@leaf
def _normal_rates(vr, rho, n, t, prm, gF):
    """gF (7,): dF_n / d(r, rdot, omega) = (-(k_p n + c_p (t . vr) t / |N|), -c_p n, 0)."""
    kp, cp = prm.k_p, prm.c_p
    tv = t[0] * vr[0] + t[1] * vr[1] + t[2] * vr[2]
    for c in range(3):
        gF[c] = -kp * n[c] - cp * tv * t[c] / rho
        gF[3 + c] = -cp * n[c]
    gF[6] = 0.0


@leaf
def _add_normal(p, rho, Fn, n, t, ft, gF, D):
    """Complete D (4, 7) whose rows 0-2 hold d f_t: add d(F_n n) to them and fill row 3,
    d tau with tau = -f . (p x (r - o)), p x (r - o) = |N| t."""
    for i in range(3):
        for c in range(7):
            D[i, c] += n[i] * gF[c]
        for c in range(3):
            D[i, c] += Fn * t[i] * t[c] / rho
    px0 = p[1] * (Fn * n[2] + ft[2]) - p[2] * (Fn * n[1] + ft[1])
    px1 = p[2] * (Fn * n[0] + ft[0]) - p[0] * (Fn * n[2] + ft[2])
    px2 = p[0] * (Fn * n[1] + ft[1]) - p[1] * (Fn * n[0] + ft[0])
    for c in range(7):
        D[3, c] = -rho * (t[0] * D[0, c] + t[1] * D[1, c] + t[2] * D[2, c])
    D[3, 0] += px0
    D[3, 1] += px1
    D[3, 2] += px2


@leaf
def _point_jacobian(vr, p, R, om, rho, Fn, vsn, branch, n, t, vs, ft, prm, gF, G, D):
    """D (4, 7): derivatives of (f_0, f_1, f_2, tau = -|N| t . f_t) with respect to
    (r, rdot, omega) on the active branch (F_n > 0); gF (7,), G (3, 7) scratch.

    dn/dr = t t^T / |N|, dt/dr = -n t^T / |N|, d|N|/dr = n^T;
    dF_n = -(k_p n + c_p (t . vr) t / |N|) . dr - c_p n . drdot;
    dv_s = -((n . w) t + (t . w) n) t^T / |N| dr + (I - n n^T) drdot - R t domega."""
    _normal_rates(vr, rho, n, t, prm, gF)
    tv = t[0] * vr[0] + t[1] * vr[1] + t[2] * vr[2]
    nw = n[0] * vr[0] + n[1] * vr[1] + n[2] * vr[2]
    tw = tv - om * R
    # G = dv_s / d(r, rdot, omega)
    for i in range(3):
        for c in range(3):
            G[i, c] = -(nw * t[i] + tw * n[i]) * t[c] / rho
            G[i, 3 + c] = (1.0 if i == c else 0.0) - n[i] * n[c]
        G[i, 6] = -R * t[i]
    gFt = (gF[0], gF[1], gF[2], gF[3], gF[4], gF[5], gF[6])
    friction.chain(branch, (vs[0], vs[1], vs[2]), vsn, Fn, prm, G, gFt, D)  # D[:3] = d f_t
    _add_normal(p, rho, Fn, n, t, ft, gF, D)


@njit(cache=True)
def _mid_surface(E, V, S0, e, q, r, v):
    r[:] = 0.0
    v[:] = 0.0
    for k in range(S0.shape[2]):
        s = S0[e, q, k]
        for c in range(3):
            r[c] += s * E[e, k, c]
            v[c] += s * V[e, k, c]


@leaf
def _mid_velocity(V, S0, e, q, v):
    """The velocity part of :func:`_mid_surface` (its arithmetic, summed in registers)."""
    v0 = v1 = v2 = 0.0
    for k in range(S0.shape[2]):
        s = S0[e, q, k]
        v0 += s * V[e, k, 0]
        v1 += s * V[e, k, 1]
        v2 += s * V[e, k, 2]
    v[0], v[1], v[2] = v0, v1, v2


@leaf
def _positions(E, S0, e, rq):
    """rq (nq, 3): the mid-surface positions (m) of element e's contact points, with the
    arithmetic of :func:`_mid_surface`."""
    for q in range(S0.shape[1]):
        r0 = r1 = r2 = 0.0
        for k in range(S0.shape[2]):
            s = S0[e, q, k]
            r0 += s * E[e, k, 0]
            r1 += s * E[e, k, 1]
            r2 += s * E[e, k, 2]
        rq[q, 0], rq[q, 1], rq[q, 2] = r0, r1, r2


@leaf
def _penetrates(rq, q, centres, j, p, R):
    """False if point q (position rq[q], :func:`_positions`) is outside pulley j's cylinder
    (d = R - |N| < 0; unit axis p), with the arithmetic of :func:`_point_law`, so the
    contact kernel skips such a point (it has no force)."""
    a0, a1, a2 = rq[q, 0] - centres[j, 0], rq[q, 1] - centres[j, 1], rq[q, 2] - centres[j, 2]
    ap = a0 * p[0] + a1 * p[1] + a2 * p[2]
    n0, n1, n2 = a0 - ap * p[0], a1 - ap * p[1], a2 - ap * p[2]
    rho = 0.0
    rho += n0 * n0
    rho += n1 * n1
    rho += n2 * n2
    return not R - np.sqrt(rho) < 0.0


#: contact points whose Jacobian terms are buffered before they are added to a pair's A
BATCH = 4


@leaf
def _add_jacobians(S0, e, q, ww, D, Qwe, dTqe, dTve, PB, DB, b):
    """Add point q's terms (weight ww, derivatives D) to the pair's omega and moment
    derivatives Qwe = Qw[e, p], dTqe = dTq[p, e], dTve = dTv[p, e], and put its
    shape-function products (for k <= m, pair index km, w S_k S_m) in PB[b] and its
    force derivatives in DB[b]: dF_d/dr_c at 3 d + c, dF_d/drdot_c at 9 + 3 d + c
    (:func:`_add_batch` adds them to the pair's buffer A)."""
    w0, w1, w2 = D[0, 6], D[1, 6], D[2, 6]
    r0, r1, r2, v0, v1, v2 = D[3, 0], D[3, 1], D[3, 2], D[3, 3], D[3, 4], D[3, 5]
    ns = S0.shape[2]
    km = 0
    for k in range(ns):
        sk = ww * S0[e, q, k]
        Qwe[3 * k] += sk * w0
        Qwe[3 * k + 1] += sk * w1
        Qwe[3 * k + 2] += sk * w2
        dTqe[3 * k] += sk * r0
        dTqe[3 * k + 1] += sk * r1
        dTqe[3 * k + 2] += sk * r2
        dTve[3 * k] += sk * v0
        dTve[3 * k + 1] += sk * v1
        dTve[3 * k + 2] += sk * v2
        for m in range(k, ns):
            PB[b, km] = sk * S0[e, q, m]
            km += 1
    for d in range(3):
        for c in range(3):
            DB[b, 3 * d + c] = D[d, c]
            DB[b, 9 + 3 * d + c] = D[d, 3 + c]


@leaf
def _add_batch(PB, DB, nb, A):
    """A[j] += PB[b] DB[b, j] for the nb buffered points b in order (one pass over A
    for a full batch): A (18, 78) is the pair's sum over its points of the 3 x 3 blocks
    (k, m) of dQ/de and dQ/dedot, (k, m) and (m, k) being equal (:func:`_flush`)."""
    nk = PB.shape[1]
    if nb == BATCH:
        for j in range(A.shape[0]):
            d0, d1, d2, d3 = DB[0, j], DB[1, j], DB[2, j], DB[3, j]
            for i in range(nk):
                A[j, i] = (((A[j, i] + PB[0, i] * d0) + PB[1, i] * d1) + PB[2, i] * d2) \
                    + PB[3, i] * d3
        return
    for b in range(nb):
        for j in range(A.shape[0]):
            dj = DB[b, j]
            for i in range(nk):
                A[j, i] += PB[b, i] * dj


@leaf
def _flush(A, e, ns, Kq, Cv):
    """Add a pair's buffer A (see :func:`_add_jacobians`) to Kq[e], Cv[e] and zero it."""
    km = 0
    for k in range(ns):
        for m in range(k, ns):
            for d in range(3):
                for c in range(3):
                    kq, cv = A[3 * d + c, km], A[9 + 3 * d + c, km]
                    Kq[e, 3 * k + d, 3 * m + c] += kq
                    Cv[e, 3 * k + d, 3 * m + c] += cv
                    if m != k:
                        Kq[e, 3 * m + d, 3 * k + c] += kq
                        Cv[e, 3 * m + d, 3 * k + c] += cv
            km += 1
    A[:, :] = 0.0


@leaf
def _swap_forces(Q, e, Qt, back):
    """Qt[d, k] = Q[e, 3 k + d] (the element's forces by component), or back."""
    for k in range(Qt.shape[1]):
        for d in range(3):
            if back:
                Q[e, 3 * k + d] = Qt[d, k]
            else:
                Qt[d, k] = Q[e, 3 * k + d]


@leaf
def _add_force(S0, e, q, ww, Fn, n, ft, sk, Qt):
    """Qt += w S_q^T f of point q (weight ww, m^2; sk scratch), Qt by component
    (:func:`_swap_forces`): f = F_n n + f_t, N/m^2."""
    f0, f1, f2 = Fn * n[0] + ft[0], Fn * n[1] + ft[1], Fn * n[2] + ft[2]
    for k in range(sk.size):
        sk[k] = ww * S0[e, q, k]
    for k in range(sk.size):
        Qt[0, k] += sk[k] * f0
    for k in range(sk.size):
        Qt[1, k] += sk[k] * f1
    for k in range(sk.size):
        Qt[2, k] += sk[k] * f2


@leaf
def _add_point(S0, e, q, ww, Fn, nrm, ft, rho, t, sk, Qt):
    """Add point q's force w S_q^T (F_n nrm + f_t) to the element's Qt (:func:`_add_force`)
    and return its moment about the pulley axis, -w |N| t . f_t, N m (module docstring)."""
    _add_force(S0, e, q, ww, Fn, nrm, ft, sk, Qt)
    return -(ww * rho * (t[0] * ft[0] + t[1] * ft[1] + t[2] * ft[2]))


@leaf
def _batch_point(S0, e, q, ww, D, Qwe, dTqe, dTve, dTw, p, PB, DB, nb, A):
    """Point q's derivatives D (4, 7) into the pair's batch (:func:`_add_jacobians`) and
    dTw[p]; a full batch goes into A (:func:`_add_batch`).  Returns the points then in
    the batch."""
    _add_jacobians(S0, e, q, ww, D, Qwe, dTqe, dTve, PB, DB, nb)
    dTw[p] += ww * D[3, 6]
    nb += 1
    if nb == BATCH:
        _add_batch(PB, DB, nb, A)
        nb = 0
    return nb


@leaf
def _end_pair(Q, e, Qt, touched, PB, DB, nb, A, Kq, Cv):
    """A pair's end: its forces back into Q[e] (:func:`_swap_forces`) and, if a point added
    derivatives, the batch's last points and the buffer A into Kq[e], Cv[e]."""
    _swap_forces(Q, e, Qt, True)
    if touched:
        _add_batch(PB, DB, nb, A)
        _flush(A, e, Qt.shape[1], Kq, Cv)


@njit(cache=True)
def contact_forces3d(E, V, S0, w, centres, axes, radii, omegas, centre_velocities, prm,
                     want_J, Q, Kq, Cv, Qw, T, dTq, dTv, dTw, cull=True):
    """Add the contact forces of every plate element on every pulley.

    E, V (nel, 12, 3) element coordinates (m, slopes -) and velocities; S0, w from
    :func:`contact_points3d`; centres (np, 3) m, axes (np, 3) (normalised here),
    radii (np,) m, omegas (np,) rad/s about the axes, centre_velocities (np, 3) m/s;
    prm the contact record (k_p N/m^3, c_p N s/m^3, the friction law's code and
    parameters by name: :func:`ancf.belts.friction.contact_record`).  Adds Q (nel, 36) N and
    T (np,) N m and, if ``want_J``, their exact derivatives on the active branch:
    Kq, Cv (nel, 36, 36) dQ/de, dQ/dedot; Qw (nel, np, 36) dQ/domega_p; dTq, dTv
    (np, nel, 36) dT_p/de, dT_p/dedot; dTw (np,) dT_p/domega_p.  Returns the number
    of (element, pulley) pairs whose points were evaluated.  ``cull``: skip the pairs
    whose bounds keep them apart (``_may_touch``) and the points outside the cylinder
    (``_penetrates``), neither of which has a force; False evaluates every point of
    every pair (the reference the culling is tested against).
    """
    nel, nq = w.shape
    D, G, P, X = np.zeros((4, 7)), np.zeros((3, 7)), np.zeros((16, 3)), np.zeros((16, 3))
    v, a, vr, gF, rq = np.zeros(3), np.zeros(3), np.zeros(3), np.zeros(7), np.zeros((nq, 3))
    n, t, vs, ft, pax = np.zeros(3), np.zeros(3), np.zeros(3), np.zeros(3), np.zeros(3)
    ns = S0.shape[2]
    PB, DB = np.zeros((BATCH, ns * (ns + 1) // 2)), np.zeros((BATCH, 18))
    A = np.zeros((18, ns * (ns + 1) // 2))
    sk, Qt = np.zeros(ns), np.zeros((3, ns))
    pairs = 0
    for e in range(nel):
        sa, sb = _sides(S0, w, e)
        _control_points(E, e, sa, sb, P)
        placed = False  # rq holds element e's points
        for p in range(radii.shape[0]):
            _unit_axis(axes, p, pax)
            R, om = radii[p], omegas[p]
            if cull and not _may_touch(P, centres[p], pax, R, X):
                continue
            pairs += 1
            if not placed:
                _positions(E, S0, e, rq)
                placed = True
            nb = 0  # points in the batch
            touched = False
            _swap_forces(Q, e, Qt, False)
            for q in range(nq):
                if cull and not _penetrates(rq, q, centres, p, pax, R):
                    continue
                _mid_velocity(V, S0, e, q, v)
                for c in range(3):
                    a[c] = rq[q, c] - centres[p, c]
                    vr[c] = v[c] - centre_velocities[p, c]
                rho, _, Fn, vsn, branch = _point_law(a, vr, pax, R, om, prm, n, t, vs, ft)
                if Fn <= 0.0:
                    continue
                ww = w[e, q]
                T[p] += _add_point(S0, e, q, ww, Fn, n, ft, rho, t, sk, Qt)
                if want_J:
                    _point_jacobian(vr, pax, R, om, rho, Fn, vsn, branch, n, t, vs, ft,
                                    prm, gF, G, D)
                    nb = _batch_point(S0, e, q, ww, D, Qw[e, p], dTq[p, e], dTv[p, e], dTw, p,
                                      PB, DB, nb, A)
                    touched = True
            _end_pair(Q, e, Qt, touched, PB, DB, nb, A, Kq, Cv)
    return pairs


@njit(cache=True)
def contact_state3d(E, V, S0, centres, axes, radii, omegas, centre_velocities, prm):
    """Contact quantities at every point for post-processing (no bounding test).

    Returns ``r`` (nel, nq, 3) mid-surface positions, m; penetration ``d`` (m,
    negative out of contact) and normal force ``F_n`` (N/m^2), each (nel, nq, np);
    friction ``f_t`` (N/m^2) and sliding velocity ``v_s`` (m/s), each (nel, nq, np, 3);
    ``branch`` (nel, nq, np): 0 out, 1 clamped, 2 linear, 3 saturated.
    """
    nel, nq = S0.shape[0], S0.shape[1]
    npul = radii.shape[0]
    rr = np.zeros((nel, nq, 3))
    d, Fn = np.zeros((nel, nq, npul)), np.zeros((nel, nq, npul))
    fts, vss = np.zeros((nel, nq, npul, 3)), np.zeros((nel, nq, npul, 3))
    br = np.zeros((nel, nq, npul), dtype=np.int64)
    r, v, a, vr = np.zeros(3), np.zeros(3), np.zeros(3), np.zeros(3)
    n, t, vs, ft, pax = np.zeros(3), np.zeros(3), np.zeros(3), np.zeros(3), np.zeros(3)
    for e in range(nel):
        for q in range(nq):
            _mid_surface(E, V, S0, e, q, r, v)
            rr[e, q] = r
            for p in range(npul):
                _unit_axis(axes, p, pax)
                for c in range(3):
                    a[c] = r[c] - centres[p, c]
                    vr[c] = v[c] - centre_velocities[p, c]
                _, dd, F, _, b = _point_law(a, vr, pax, radii[p], omegas[p], prm, n, t, vs, ft)
                d[e, q, p], Fn[e, q, p], br[e, q, p] = dd, F, b
                fts[e, q, p] = ft
                vss[e, q, p] = vs
    return rr, d, Fn, fts, vss, br
