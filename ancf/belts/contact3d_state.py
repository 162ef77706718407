"""The plate belt's contact (:mod:`ancf.belts.contact3d`) with a friction law that carries a
state per contact point (the bristle law, :mod:`ancf.belts.friction.bristle`), compiled
(numba).

The law acts in the rim's tangent plane on the sliding velocity's components along the
circumferential tangent t = p x n and the axis p (v_s has no part along n),

    v    = (t . v_s, p . v_s) = (t . (rdot - odot) - omega R,  p . (rdot - odot))   m/s
    f_t  = phi_0 t + phi_1 p,   (phi, z1) = law(v, z0, h, F_n)                    N/m^2

with the bristle deflection z (m, two components along t and p) of every contact point
(element e, point q) on every pulley: z[0] at the last converged step, the trial z[1]
stepped over the march's step h (s), stick |k_t z0 + (k_t h + d_t) v| <= mu F_n, else
slip at mu F_n against it (:func:`ancf.belts.friction.bristle.bristle_force`).  A point out
of contact (d < 0 or F_n clamped to 0) has the trial state 0, as in 2D
(:mod:`ancf.belts.contact2d`); the march accepts z[1] on convergence
(:func:`ancf.belts.system.accept_state`).

Derivatives (z0 and h fixed within a step): dv_0 = -(n . vr) t^T / |N| dr + t^T drdot
- R domega (dt/dr = -n t^T / |N|), dv_1 = p^T drdot; the law's d phi by v and F_n
(:func:`ancf.belts.friction.state_chain`); d f_t = t d phi_0 + p d phi_1
- phi_0 n t^T / |N| dr.  The normal force's part and the moment row are contact3d's.

The drive's record (:class:`ancf.belts.arm3d.Drive3DArms`) carries the state z
(2, nel, nq, np, 2) m; its :func:`ancf.belts.forces.drive_forces` takes
:func:`contact_forces3d_state` for a law with a state (chosen at run time).

Crowned rims (:func:`contact_forces3d_crown`; issue 36 item 4).  A
pulley's rim is the surface of revolution of radius R(s) about its axis, s the point's
axial coordinate from the mid-face point f = (o_x, o_y, z_m) (as :mod:`ancf.belts.flange3d`:
s = (r - o) . p - (z_m - o_z) p_z), W the face width (``face_width_m``; 0: 1.1 b):

    R(s) = R + c (1 - (2 s / W)^2),  R' = -8 c s / W^2,  R'' = -8 c / W^2           (C1)
    n, t, |N| as contact3d;  g = sqrt(1 + R'^2),  nu = (n - R' p) / g
    d    = (R(s) - |N|) / g                        penetration along the normal nu, m  (C2)
    F_n  = max(k_p d - c_p nu . vr, 0);  w = vr - omega R(s) t;  v_s = w - (w . nu) nu
    f    = F_n nu + f_t(v_s)                       friction in the tangent plane        (C3)

nu is the outward unit normal of the surface of revolution (the gradient of R(s) - |N| is
R' p - n); d is the radial gap R(s) - |N| projected on it, the distance to the surface to
first order in d.  For |s| > W / 2 the parabola is continued (R(s) < R there): the law stays
smooth (C-infinity), so the Newton Jacobian stays exact everywhere, and a belt edge
hanging over the end of the face loses its support gradually, as off a real face's edge;
a clamp R(s) = R beyond W / 2 would put a kink in R' at the face's ends.  The normal has
no moment about the axis (t . nu = 0), so the moment is -|N| t . f_t as contact3d's.
Derivatives (C4): dnu/dr = (t t^T / |N| - R'' p p^T) / g - nu (R' R'' / g^2) p^T,
dd/dr = (R' p - n)^T / g - d (R' R'' / g^2) p^T, dF_n = k_p dd - c_p (vr^T dnu/dr) dr
- c_p nu^T drdot, dw/dr = -omega (R' t p^T - R(s) n t^T / |N|), dv_s/dr = (I - nu nu^T)
dw/dr - (nu (w^T dnu/dr) + (w . nu) dnu/dr), dv_s/drdot = I - nu nu^T, dv_s/domega =
-R(s) t; the moment row as contact3d's (p x f).  tests/belts/test_belt3d_crown.py checks
them by central differences.  With c = 0 on every pulley the drive has no crown rows and
takes contact3d's kernel (bit for bit the drive without the key); a crowned drive (the
friction laws without a state, no tensioner arms) takes this kernel, chosen at run time by
the forces of :class:`ancf.belts.arm3d.Drive3DArms` (one compilation of the march for both).
"""
from __future__ import annotations

import numpy as np
from numba import njit

from ancf.belts import friction
from ancf.belts.contact3d import (BATCH, _add_normal, _add_point, _batch_point,
                                  _control_points, _end_pair, _may_touch, _mid_surface,
                                  _mid_velocity, _normal_rates, _penetrates, _point_geometry,
                                  _positions, _sides, _swap_forces, _unit_axis)
from ancf.common.leaf import leaf


@leaf
def _state_law(a, vr, p, R, om, prm, n, t, vs, ft, z0, h, z1, phi):
    """Contact law at one point with the friction state z0 (2-tuple, m) over the step h (s):
    fills n, t, v_s, f_t (3,), phi (2,) (f_t along t and p, N/m^2) and the trial state
    z1 (2,) (0 out of contact); returns |N|, F_n, the branch (0 out, 1 clamped, else the
    law's) and v (2-tuple, m/s: along t and p)."""
    rho, _, Fn, _, where = _point_geometry(a, vr, p, R, om, prm, n, t, vs)
    ft[:] = 0.0
    z1[:] = 0.0
    v = (t[0] * vs[0] + t[1] * vs[1] + t[2] * vs[2], p[0] * vs[0] + p[1] * vs[1] + p[2] * vs[2])
    if where >= 0:
        return rho, Fn, where, v
    s = np.sqrt(v[0] * v[0] + v[1] * v[1])
    branch = friction.state_force(v, s, Fn, prm, phi, z0, h, z1)
    for c in range(3):
        ft[c] = phi[0] * t[c] + phi[1] * p[c]
    return rho, Fn, branch, v


@leaf
def _state_jacobian(vr, p, R, rho, Fn, branch, n, t, ft, phi, prm, z0, h, v, gF, G, Dz, D):
    """D (4, 7): derivatives of (f_0, f_1, f_2, tau) by (r, rdot, omega) at a point in
    contact (module docstring); gF (7,), G (2, 7) = dv/d(r, rdot, omega), Dz (2, 7) scratch."""
    _normal_rates(vr, rho, n, t, prm, gF)
    nv = n[0] * vr[0] + n[1] * vr[1] + n[2] * vr[2]
    for c in range(3):
        G[0, c] = -nv * t[c] / rho
        G[0, 3 + c] = t[c]
        G[1, c] = 0.0
        G[1, 3 + c] = p[c]
    G[0, 6], G[1, 6] = -R, 0.0
    gFt = (gF[0], gF[1], gF[2], gF[3], gF[4], gF[5], gF[6])
    s = np.sqrt(v[0] * v[0] + v[1] * v[1])
    friction.state_chain(branch, v, s, Fn, prm, G, gFt, Dz, z0, h)
    for i in range(3):
        for c in range(7):
            D[i, c] = t[i] * Dz[0, c] + p[i] * Dz[1, c]
        for c in range(3):
            D[i, c] -= phi[0] * n[i] * t[c] / rho
    _add_normal(p, rho, Fn, n, t, ft, gF, D)


@njit(cache=True)
def contact_forces3d_state(E, V, S0, w, centres, axes, radii, omegas, centre_velocities, prm,
                           z, h, want_J, Q, Kq, Cv, Qw, T, dTq, dTv, dTw):
    """:func:`ancf.belts.contact3d.contact_forces3d` with the friction state z
    (2, nel, nq, np, 2) m of a law with a state: z[0] read, the trial z[1] written, over
    the step h (s).  Arguments and outputs otherwise as there; returns the pairs
    evaluated."""
    nel, nq = w.shape
    D, G, Dz, P, X = (np.zeros((4, 7)), np.zeros((2, 7)), np.zeros((2, 7)), np.zeros((16, 3)),
                      np.zeros((16, 3)))
    v, a, vr, gF, rq = np.zeros(3), np.zeros(3), np.zeros(3), np.zeros(7), np.zeros((nq, 3))
    n, t, vs, ft, pax = np.zeros(3), np.zeros(3), np.zeros(3), np.zeros(3), np.zeros(3)
    phi, z1 = np.zeros(2), np.zeros(2)
    ns = S0.shape[2]
    PB, DB = np.zeros((BATCH, ns * (ns + 1) // 2)), np.zeros((BATCH, 18))
    A = np.zeros((18, ns * (ns + 1) // 2))
    sk, Qt = np.zeros(ns), np.zeros((3, ns))
    pairs = 0
    z[1, :, :, :, :] = 0.0
    for e in range(nel):
        sa, sb = _sides(S0, w, e)
        _control_points(E, e, sa, sb, P)
        placed = False
        for p in range(radii.shape[0]):
            _unit_axis(axes, p, pax)
            R, om = radii[p], omegas[p]
            if not _may_touch(P, centres[p], pax, R, X):
                continue
            pairs += 1
            if not placed:
                _positions(E, S0, e, rq)
                placed = True
            nb = 0
            touched = False
            _swap_forces(Q, e, Qt, False)
            for q in range(nq):
                if not _penetrates(rq, q, centres, p, pax, R):
                    continue
                _mid_velocity(V, S0, e, q, v)
                for c in range(3):
                    a[c] = rq[q, c] - centres[p, c]
                    vr[c] = v[c] - centre_velocities[p, c]
                z0 = (z[0, e, q, p, 0], z[0, e, q, p, 1])
                rho, Fn, branch, v2 = _state_law(a, vr, pax, R, om, prm, n, t, vs, ft, z0, h,
                                                 z1, phi)
                z[1, e, q, p, 0], z[1, e, q, p, 1] = z1[0], z1[1]
                if Fn <= 0.0:
                    continue
                ww = w[e, q]
                T[p] += _add_point(S0, e, q, ww, Fn, n, ft, rho, t, sk, Qt)
                if want_J:
                    _state_jacobian(vr, pax, R, rho, Fn, branch, n, t, ft, phi, prm, z0, h, v2,
                                    gF, G, Dz, D)
                    nb = _batch_point(S0, e, q, ww, D, Qw[e, p], dTq[p, e], dTv[p, e], dTw, p,
                                      PB, DB, nb, A)
                    touched = True
            _end_pair(Q, e, Qt, touched, PB, DB, nb, A, Kq, Cv)
    return pairs


@njit(cache=True)
def contact_state3d_stepped(E, V, S, centres, axes, radii, omegas, centre_velocities, prm,
                            z0, h):
    """:func:`ancf.belts.contact3d.contact_state3d` (post-processing at the points of S,
    (nel, nq, 36)) with the friction state z0 (nel, nq, np, 2) m at those points stepped
    over h (s): r, d, F_n, f_t, v_s, branch as there."""
    nel, nq, npul = S.shape[0], S.shape[1], radii.shape[0]
    rr = np.zeros((nel, nq, 3))
    d, Fn = np.zeros((nel, nq, npul)), np.zeros((nel, nq, npul))
    fts, vss = np.zeros((nel, nq, npul, 3)), np.zeros((nel, nq, npul, 3))
    br = np.zeros((nel, nq, npul), dtype=np.int64)
    r, v, a, vr = np.zeros(3), np.zeros(3), np.zeros(3), np.zeros(3)
    n, t, vs, ft, pax = np.zeros(3), np.zeros(3), np.zeros(3), np.zeros(3), np.zeros(3)
    phi, z1 = np.zeros(2), np.zeros(2)
    for e in range(nel):
        for q in range(nq):
            _mid_surface(E, V, S, e, q, r, v)
            rr[e, q] = r
            for p in range(npul):
                _unit_axis(axes, p, pax)
                for c in range(3):
                    a[c] = r[c] - centres[p, c]
                    vr[c] = v[c] - centre_velocities[p, c]
                _, dd, _, _, _ = _point_geometry(a, vr, pax, radii[p], omegas[p], prm, n, t,
                                                 vs)
                _, F, b, _ = _state_law(a, vr, pax, radii[p], omegas[p], prm, n, t, vs, ft,
                                        (z0[e, q, p, 0], z0[e, q, p, 1]), h, z1, phi)
                d[e, q, p], Fn[e, q, p], br[e, q, p] = dd, F, b
                fts[e, q, p] = ft
                vss[e, q, p] = vs
    return rr, d, Fn, fts, vss, br


@leaf
def _crown_geometry(a, vr, p, R, om, prm, cr, o_z, n, t, nu, vs):
    """The crowned rim's geometry and normal force at one point (a = r - o, m; vr m/s;
    crown row cr = (c, z_m, W / 2), centre height o_z, m): fills n, t, nu, v_s (3,) and
    returns |N|, d, F_n, |v_s|, the branch (0 out, 1 clamped, -1 in contact), R(s) (m),
    R' and g = sqrt(1 + R'^2) (:func:`contact_forces3d_crown`, Eqs C1-C3)."""
    kp, cp = prm.k_p, prm.c_p
    c, half = cr[0], cr[2]
    ap = a[0] * p[0] + a[1] * p[1] + a[2] * p[2]
    s = ap - (cr[1] - o_z) * p[2]
    Rs = R + c * (1.0 - (s / half) ** 2)
    R1 = -2.0 * c * s / (half * half)
    for i in range(3):
        n[i] = a[i] - ap * p[i]
    rho = np.sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2])
    for i in range(3):
        n[i] /= rho
    t[0], t[1] = p[1] * n[2] - p[2] * n[1], p[2] * n[0] - p[0] * n[2]
    t[2] = p[0] * n[1] - p[1] * n[0]
    g = np.sqrt(1.0 + R1 * R1)
    for i in range(3):
        nu[i] = (n[i] - R1 * p[i]) / g
    d = (Rs - rho) / g
    wn = nu[0] * vr[0] + nu[1] * vr[1] + nu[2] * vr[2]  # w = vr - omega R(s) t, t . nu = 0
    for i in range(3):
        vs[i] = vr[i] - om * Rs * t[i] - wn * nu[i]
    vsn = np.sqrt(vs[0] * vs[0] + vs[1] * vs[1] + vs[2] * vs[2])
    if d < 0.0:
        return rho, d, 0.0, vsn, 0, Rs, R1, g
    Fn = kp * d - cp * wn
    if Fn <= 0.0:
        return rho, d, 0.0, vsn, 1, Rs, R1, g
    return rho, d, Fn, vsn, -1, Rs, R1, g


@leaf
def _crown_law(a, vr, p, R, om, prm, cr, o_z, n, t, nu, vs, ft):
    """:func:`_crown_geometry` and the friction f_t (3,) in the crowned rim's tangent plane;
    returns |N|, d, F_n, |v_s|, the branch (the friction law's in contact), R(s), R', g."""
    rho, d, Fn, vsn, where, Rs, R1, g = _crown_geometry(a, vr, p, R, om, prm, cr, o_z, n, t,
                                                        nu, vs)
    ft[:] = 0.0
    if where >= 0:
        return rho, d, Fn, vsn, where, Rs, R1, g
    b = friction.force((vs[0], vs[1], vs[2]), vsn, Fn, prm, ft)
    return rho, d, Fn, vsn, b, Rs, R1, g


@leaf
def _crown_jacobian(vr, p, om, cr, rho, d, Fn, vsn, branch, Rs, R1, g, n, t, nu, vs, ft, prm,
                    Dn, gF, G, D):
    """D (4, 7): derivatives of (f_0, f_1, f_2, tau) by (r, rdot, omega) on the crowned rim
    (Eq. C4); Dn (3, 3) d nu / dr, gF (7,), G (3, 7) scratch."""
    kp, cp = prm.k_p, prm.c_p
    R2 = -2.0 * cr[0] / (cr[2] * cr[2])
    q = R1 * R2 / (g * g)
    for i in range(3):
        for c in range(3):
            Dn[i, c] = (t[i] * t[c] / rho - R2 * p[i] * p[c]) / g - nu[i] * q * p[c]
    w0, w1, w2 = vr[0] - om * Rs * t[0], vr[1] - om * Rs * t[1], vr[2] - om * Rs * t[2]
    wn = nu[0] * w0 + nu[1] * w1 + nu[2] * w2
    for c in range(3):
        vDn = vr[0] * Dn[0, c] + vr[1] * Dn[1, c] + vr[2] * Dn[2, c]
        gF[c] = kp * ((R1 * p[c] - n[c]) / g - d * q * p[c]) - cp * vDn
        gF[3 + c] = -cp * nu[c]
    gF[6] = 0.0
    for c in range(3):  # d w / dr = -omega (R' t p^T - R(s) n t^T / |N|), column c in G
        for i in range(3):
            G[i, c] = -om * (R1 * t[i] * p[c] - Rs * n[i] * t[c] / rho)
        dwn = (nu[0] * G[0, c] + nu[1] * G[1, c] + nu[2] * G[2, c]
               + w0 * Dn[0, c] + w1 * Dn[1, c] + w2 * Dn[2, c])
        for i in range(3):
            G[i, c] += -nu[i] * dwn - wn * Dn[i, c]
            G[i, 3 + c] = (1.0 if i == c else 0.0) - nu[i] * nu[c]
    for i in range(3):
        G[i, 6] = -Rs * t[i]
    gFt = (gF[0], gF[1], gF[2], gF[3], gF[4], gF[5], gF[6])
    friction.chain(branch, (vs[0], vs[1], vs[2]), vsn, Fn, prm, G, gFt, D)
    for i in range(3):
        for c in range(7):
            D[i, c] += nu[i] * gF[c]
        for c in range(3):
            D[i, c] += Fn * Dn[i, c]
    f0, f1, f2 = Fn * nu[0] + ft[0], Fn * nu[1] + ft[1], Fn * nu[2] + ft[2]
    for c in range(7):
        D[3, c] = -rho * (t[0] * D[0, c] + t[1] * D[1, c] + t[2] * D[2, c])
    D[3, 0] += p[1] * f2 - p[2] * f1
    D[3, 1] += p[2] * f0 - p[0] * f2
    D[3, 2] += p[0] * f1 - p[1] * f0


@njit(cache=True)
def contact_forces3d_crown(E, V, S0, w, centres, axes, radii, omegas, centre_velocities, prm,
                           crowns, want_J, Q, Kq, Cv, Qw, T, dTq, dTv, dTw):
    """:func:`ancf.belts.contact3d.contact_forces3d` on crowned rims (module docstring,
    Eqs C1-C4): ``crowns`` (np, 3) per pulley c (m), z_m (m), W / 2 (m); arguments and
    outputs otherwise as there; returns the pairs evaluated.  The culling takes the
    largest radius R + c."""
    nel, nq = w.shape
    D, G, P, X = np.zeros((4, 7)), np.zeros((3, 7)), np.zeros((16, 3)), np.zeros((16, 3))
    v, a, vr, gF, rq = np.zeros(3), np.zeros(3), np.zeros(3), np.zeros(7), np.zeros((nq, 3))
    n, t, vs, ft, pax = np.zeros(3), np.zeros(3), np.zeros(3), np.zeros(3), np.zeros(3)
    nu, Dn = np.zeros(3), np.zeros((3, 3))
    ns = S0.shape[2]
    PB, DB = np.zeros((BATCH, ns * (ns + 1) // 2)), np.zeros((BATCH, 18))
    A = np.zeros((18, ns * (ns + 1) // 2))
    sk, Qt = np.zeros(ns), np.zeros((3, ns))
    pairs = 0
    for e in range(nel):
        sa, sb = _sides(S0, w, e)
        _control_points(E, e, sa, sb, P)
        _positions(E, S0, e, rq)
        for p in range(radii.shape[0]):
            _unit_axis(axes, p, pax)
            R, om, cr = radii[p], omegas[p], crowns[p]
            if not _may_touch(P, centres[p], pax, R + cr[0], X):
                continue
            pairs += 1
            nb = 0
            touched = False
            _swap_forces(Q, e, Qt, False)
            for q in range(nq):
                if not _penetrates(rq, q, centres, p, pax, R + cr[0]):
                    continue
                _mid_velocity(V, S0, e, q, v)
                for c in range(3):
                    a[c] = rq[q, c] - centres[p, c]
                    vr[c] = v[c] - centre_velocities[p, c]
                rho, d, Fn, vsn, branch, Rs, R1, g = _crown_law(
                    a, vr, pax, R, om, prm, cr, centres[p, 2], n, t, nu, vs, ft)
                if Fn <= 0.0:
                    continue
                ww = w[e, q]
                T[p] += _add_point(S0, e, q, ww, Fn, nu, ft, rho, t, sk, Qt)
                if want_J:
                    _crown_jacobian(vr, pax, om, cr, rho, d, Fn, vsn, branch, Rs, R1, g, n, t,
                                    nu, vs, ft, prm, Dn, gF, G, D)
                    nb = _batch_point(S0, e, q, ww, D, Qw[e, p], dTq[p, e], dTv[p, e], dTw, p,
                                      PB, DB, nb, A)
                    touched = True
            _end_pair(Q, e, Qt, touched, PB, DB, nb, A, Kq, Cv)
    return pairs


@njit(cache=True)
def contact_state3d_crown(E, V, S0, centres, axes, radii, omegas, centre_velocities, prm,
                          crowns):
    """:func:`ancf.belts.contact3d.contact_state3d` on crowned rims: r, d, F_n, f_t, v_s,
    branch as there (d the crowned rim's penetration, Eq. C2) and the normals nu
    (nel, nq, np, 3)."""
    nel, nq, npul = S0.shape[0], S0.shape[1], radii.shape[0]
    rr = np.zeros((nel, nq, 3))
    d, Fn = np.zeros((nel, nq, npul)), np.zeros((nel, nq, npul))
    fts, vss = np.zeros((nel, nq, npul, 3)), np.zeros((nel, nq, npul, 3))
    br = np.zeros((nel, nq, npul), dtype=np.int64)
    nus = np.zeros((nel, nq, npul, 3))
    r, v, a, vr = np.zeros(3), np.zeros(3), np.zeros(3), np.zeros(3)
    n, t, vs, ft, pax, nu = (np.zeros(3), np.zeros(3), np.zeros(3), np.zeros(3), np.zeros(3),
                             np.zeros(3))
    for e in range(nel):
        for q in range(nq):
            _mid_surface(E, V, S0, e, q, r, v)
            rr[e, q] = r
            for p in range(npul):
                _unit_axis(axes, p, pax)
                for c in range(3):
                    a[c] = r[c] - centres[p, c]
                    vr[c] = v[c] - centre_velocities[p, c]
                _, dd, F, _, b, _, _, _ = _crown_law(a, vr, pax, radii[p], omegas[p], prm,
                                                     crowns[p], centres[p, 2], n, t, nu, vs, ft)
                d[e, q, p], Fn[e, q, p], br[e, q, p] = dd, F, b
                fts[e, q, p] = ft
                vss[e, q, p] = vs
                nus[e, q, p] = nu
    return rr, d, Fn, fts, vss, br, nus
