"""Distributed penalty contact between a planar ANCF belt and circular pulleys
(thesis section 3.2, Eqs 3.20-3.27), compiled (numba).

At every Gauss point of the centreline (y = 0) of a ``cubic2d`` element, with
r = S0 e (m) and rdot = S0 edot (m/s; less the centre's velocity where the centre moves:
a tensioner's, :mod:`ancf.belts.arm2d`), and for a pulley of centre o (m), radius R (m)
and angular velocity omega (rad/s, counter-clockwise positive).  A pulley on the belt's
back (side -1) is met the same way: the belt lies outside its disc either way.

    d    = R - |r - o|                   penetration, m                     (3.21)
    n    = (r - o) / |r - o|             outward normal of the pulley       (3.22)
    ddot = -n . rdot                     penetration rate, m/s
    F_n  = max(k_p d + c_p ddot, 0)      if d >= 0, else 0; N/m            (3.20)
    t    = I~ n,  I~ = [[0, -1], [1, 0]] tangent, counter-clockwise         (3.24)
    v_t  = t . (rdot - omega R t)        sliding velocity, m/s              (3.25)
    phi  = -sign(v_t) min(nu_s |v_t|, mu F_n)   friction along t, N/m       (3.23)
    f    = F_n n + phi t                 force per unit length on the belt, N/m

The clamp F_n >= 0 is ours: Eq 3.20 gives k_p d + c_p ddot for every d >= 0, which
is negative when the belt leaves the pulley faster than k_p d / c_p; the damper
would then pull the belt onto the pulley.  The thesis excludes adhesion ("only the
kinetic friction is applied ... excluding the existence of adhesion"), and Eq 3.23
scales friction with ||f_n||, which a pulling normal force would feed, so the
normal force is clamped at zero (no tension across the contact).

Friction law (our reading of Eq 3.23 and the tri-linear creep-rate law of Fig 3.3):
the friction force per unit length grows linearly with the sliding velocity with
slope nu_s (kg/(m s) = N s/m^2), through zero, and saturates at the Coulomb value
mu |f_n| for |v_t| > mu F_n / nu_s; the three lines are -mu F_n, -nu_s v_t and
+mu F_n.  The law (the tri-linear one, or another) is :mod:`ancf.belts.friction`'s, on
v = [v_t]; this module supplies the geometry and the chain rule.  The surface speed of
the pulley is omega R, as written in Eq 3.25 (R, not |r - o|).  A law with a state (the
bristle law) steps its deflection z at every Gauss point on every pulley over the
march's step h: the kernel reads z[0] (the last converged step's) and writes the trial
z[1] (0 out of contact), which the march accepts on convergence
(:mod:`ancf.belts.system`); a drive without a state passes an empty z (:data:`NO_STATE`):
one compiled kernel runs every law, chosen at run time by the contact record.

Generalised force (Eq 3.27) and pulley moment (Eq 3.26 integrand; the normal force
passes through the centre and has no moment), Gauss quadrature over each element:

    Q_e += sum_g w_g S0_g^T f_g                   N (per coordinate)
    T_p += sum_g w_g ((r - o) x (-phi t))_z = -sum_g w_g phi |r - o|    N m

Element coordinates are ordered ``k * 2 + d`` (shape function k of ``cubic2d_S``,
component d), 12 per element; E, V are (nel, 6, 2).  A point exactly at a pulley
centre has no normal; the penalty regime (d << R) never reaches it.
"""
from __future__ import annotations

import numpy as np
from numba import njit

from ancf.belts import friction
from ancf.belts.contact_common import BOUND_MARGIN, add_pulley_rows, positive_lengths
from ancf.elements.basis import cubic2d_S
from ancf.core.quadrature import gauss01

#: Gauss rules along the element the contact is integrated with (the force is not
#: smooth, so more points than the stiffness needs; Eq 3.27 discussion); 3 and 4 for
#: fine meshes, as THREAD's 4 contact segments per element and Exudyn's 2.
SUPPORTED_POINTS = (3, 4, 5, 7, 11)


def contact_points(lengths, gauss_points):
    """Shape functions and weights at the contact Gauss points.

    ``lengths`` (nel,) reference element lengths, m; ``gauss_points`` one of
    :data:`SUPPORTED_POINTS`.  Returns ``S0`` (nel, ng, 6) ``cubic2d`` shape functions
    on the centreline y = 0, ``w`` (nel, ng) Gauss weights times the element length (m)
    and ``xi`` (ng,) the points in [0, 1].
    """
    if gauss_points not in SUPPORTED_POINTS:
        raise ValueError(f"gauss_points must be one of {SUPPORTED_POINTS} (got {gauss_points!r})")
    l = positive_lengths("lengths", lengths)
    xi, wg = gauss01(int(gauss_points))
    L = l[:, None]
    S0 = np.ascontiguousarray(cubic2d_S(xi[None, :] * L, 0.0, L))
    return S0, wg[None, :] * L, xi


@njit(cache=True)
def _may_touch(E, e, l, o0, o1, R):
    """False only if the element's centreline provably stays outside the pulley disc:
    the cubic Hermite centreline lies in the convex hull of its Bezier control points
    r^I, r^I + l r_x^I / 3, r^J - l r_x^J / 3, r^J (cubic2d: S2 = l (xi - 2 xi^2 + xi^3),
    so r_x is per metre), hence in any disc enclosing them.  Distances by sqrt, not hypot
    (a third of its cost; within an ulp or two, far inside BOUND_MARGIN: the test stays
    conservative, a touching element is never left out)."""
    p0x, p0y = E[e, 0, 0], E[e, 0, 1]
    p3x, p3y = E[e, 3, 0], E[e, 3, 1]
    p1x, p1y = p0x + l * E[e, 1, 0] / 3.0, p0y + l * E[e, 1, 1] / 3.0
    p2x, p2y = p3x - l * E[e, 4, 0] / 3.0, p3y - l * E[e, 4, 1] / 3.0
    cx, cy = 0.25 * (p0x + p1x + p2x + p3x), 0.25 * (p0y + p1y + p2y + p3y)
    rb = max(_norm(p0x - cx, p0y - cy), _norm(p1x - cx, p1y - cy),
             _norm(p2x - cx, p2y - cy), _norm(p3x - cx, p3y - cy))
    dist = _norm(cx - o0, cy - o1)
    return dist - rb <= R + BOUND_MARGIN * (dist + rb + R)


@njit(cache=True)
def _norm(x, y):
    """|(x, y)| (m) by sqrt: a bound's distance (no overflow at the lengths of a drive)."""
    return np.sqrt(x * x + y * y)


#: the friction state of a drive whose law has none: an empty array of z's type, so that
#: one compiled march serves every law (the law chosen at run time)
NO_STATE = np.zeros((2, 0, 0, 0))


@njit(cache=True)
def _state_at(z, e, g, p, z1):
    """The friction state z0 (m) at point g of element e on pulley p (0 without one:
    :data:`NO_STATE`); its trial reset."""
    if z.size == 0:
        return 0.0
    z1[0] = 0.0
    return z[0, e, g, p]


@njit(cache=True)
def _keep_trial(z, e, g, p, z1):
    if z.size != 0:
        z[1, e, g, p] = z1[0]


@njit(cache=True)
def _clear_trials(z, e, p):
    if z.size != 0:
        z[1, e, :, p] = 0.0


@njit(cache=True)
def _point_law(a0, a1, v0, v1, R, om, prm, f, z0, h, z1):
    """Contact law at one point, r - o = a (m), rdot = v0, v1 (m/s), the friction law's
    state z0 (m) at the last converged step and the step h (s).  Returns |r - o|, d,
    F_n, v_t and the friction law's branch (0 out of contact or clamped); fills
    f = [phi] (1,) and, for a law with a state in contact, z1 = [its trial state] (1,)
    (a stateless law leaves z1: :func:`ancf.belts.friction.state_force` runs every law)."""
    kp, cp = prm.k_p, prm.c_p
    rho = np.hypot(a0, a1)
    n0, n1 = a0 / rho, a1 / rho
    d = R - rho
    vt = -n1 * v0 + n0 * v1 - om * R
    f[0] = 0.0
    Fn = kp * d - cp * (n0 * v0 + n1 * v1) if d >= 0.0 else 0.0
    if Fn <= 0.0:
        return rho, d, 0.0, vt, 0
    return rho, d, Fn, vt, friction.state_force((vt,), abs(vt), Fn, prm, f, (z0,), h, z1)


@njit(cache=True)
def _point_jacobian(a0, a1, v0, v1, R, rho, Fn, vt, branch, phi, prm, G, Dphi, D, z0, h):
    """D (3, 5): derivatives of (f_0, f_1, tau = -phi |r - o|) with respect to
    (r_0, r_1, rdot_0, rdot_1, omega) on the active branch (F_n > 0; the friction state
    z0 and the step h fixed); G (1, 5) the derivatives of v_t,
    Dphi (1, 5) those of phi (scratch)."""
    kp, cp = prm.k_p, prm.c_p
    n0, n1 = a0 / rho, a1 / rho
    t0, t1 = -n1, n0
    vn, vtt = n0 * v0 + n1 * v1, t0 * v0 + t1 * v1
    gF = (-kp * n0 - cp * vtt / rho * t0, -kp * n1 - cp * vtt / rho * t1, -cp * n0, -cp * n1, 0.0)
    G[0, 0], G[0, 1], G[0, 2], G[0, 3], G[0, 4] = -vn / rho * t0, -vn / rho * t1, t0, t1, -R
    friction.state_chain(branch, (vt,), abs(vt), Fn, prm, G, gF, Dphi, (z0,), h)
    n, t = (n0, n1), (t0, t1)
    for c in range(5):
        gphi = Dphi[0, c]
        for d in range(2):
            D[d, c] = n[d] * gF[c] + t[d] * gphi
        D[2, c] = -rho * gphi
        if c < 2:  # n and t turn with r: dn/dr = t t^T / rho, dt/dr = -n t^T / rho
            for d in range(2):
                D[d, c] += (Fn * t[d] - phi * n[d]) * t[c] / rho
            D[2, c] -= phi * n[c]


@njit(cache=True)
def _centreline(E, V, S0, e, g):
    r0 = r1 = v0 = v1 = 0.0
    for k in range(S0.shape[2]):
        s = S0[e, g, k]
        r0 += s * E[e, k, 0]
        r1 += s * E[e, k, 1]
        v0 += s * V[e, k, 0]
        v1 += s * V[e, k, 1]
    return r0, r1, v0, v1


@njit(cache=True)
def _add_jacobians(S0, e, g, p, ww, D, Kq, Cv, Qw, dTq, dTv, dTw):
    ns = S0.shape[2]
    for k in range(ns):
        sk = ww * S0[e, g, k]
        add_pulley_rows(e, p, k, sk, D, 2, Qw, dTq, dTv)
        for d in range(2):
            for m in range(ns):
                skm = sk * S0[e, g, m]
                for c in range(2):
                    Kq[e, 2 * k + d, 2 * m + c] += skm * D[d, c]
                    Cv[e, 2 * k + d, 2 * m + c] += skm * D[d, 2 + c]
    dTw[p] += ww * D[2, 4]


@njit(cache=True)
def contact_forces(E, V, S0, w, centres, radii, omegas, prm, want_J,
                   Q, Kq, Cv, Qw, T, dTq, dTv, dTw):
    """:func:`contact_forces_moving` with the pulley centres at rest and a friction law's
    state zero (over a step of 0 s)."""
    z = np.zeros((2, w.shape[0], w.shape[1], radii.shape[0]))
    return contact_forces_moving(E, V, S0, w, centres, np.zeros_like(centres), radii, omegas,
                                 prm, z, 0.0, want_J, Q, Kq, Cv, Qw, T, dTq, dTv, dTw)


@njit(cache=True)
def contact_forces_moving(E, V, S0, w, centres, odot, radii, omegas, prm, z, h, want_J,
                          Q, Kq, Cv, Qw, T, dTq, dTv, dTw):
    """Add the contact forces of every element on every pulley.

    E, V (nel, 6, 2) element coordinates (m, slopes -) and velocities; S0, w from
    :func:`contact_points` (the element length is sum_g w); centres (np, 2) m and their
    velocities odot (np, 2) m/s (rdot - odot enters the law: the point's velocity
    relative to the centre), radii (np,) m, omegas (np,) rad/s; prm the contact
    record (k_p N/m^2, c_p N s/m^2, the friction law's code and parameters by name:
    :func:`ancf.belts.friction.contact_record`); z (2, nel, ng, np) the friction law's
    state at every contact point (m): z[0] at the last converged step, z[1] filled with
    the trial state of the step of h (s) (0 out of contact); :data:`NO_STATE` for a
    stateless law.
    Adds Q (nel, 12) N and T (np,) N m and, if ``want_J``, their exact derivatives on the
    active branch: Kq, Cv (nel, 12, 12) dQ/de, dQ/dedot; Qw (nel, np, 12) dQ/domega_p;
    dTq, dTv (np, nel, 12) dT_p/de, dT_p/dedot; dTw (np,) dT_p/domega_p.  Returns the
    number of (element, pulley) pairs whose Gauss points were evaluated.
    """
    nel, ng = w.shape
    D, Dphi, G = np.zeros((3, 5)), np.zeros((1, 5)), np.zeros((1, 5))
    f, z1 = np.zeros(1), np.zeros(1)
    pairs = 0
    for e in range(nel):
        l = 0.0
        for g in range(ng):
            l += w[e, g]
        for p in range(radii.shape[0]):
            o0, o1, R = centres[p, 0], centres[p, 1], radii[p]
            if not _may_touch(E, e, l, o0, o1, R):
                _clear_trials(z, e, p)
                continue
            pairs += 1
            for g in range(ng):
                r0, r1, v0, v1 = _centreline(E, V, S0, e, g)
                a0, a1 = r0 - o0, r1 - o1
                v0, v1 = v0 - odot[p, 0], v1 - odot[p, 1]
                z0 = _state_at(z, e, g, p, z1)
                rho, _, Fn, vt, branch = _point_law(a0, a1, v0, v1, R, omegas[p], prm, f, z0,
                                                    h, z1)
                _keep_trial(z, e, g, p, z1)
                if Fn <= 0.0:
                    continue
                ww, phi = w[e, g], f[0]
                f0 = (Fn * a0 - phi * a1) / rho
                f1 = (Fn * a1 + phi * a0) / rho
                for k in range(S0.shape[2]):
                    Q[e, 2 * k] += ww * S0[e, g, k] * f0
                    Q[e, 2 * k + 1] += ww * S0[e, g, k] * f1
                T[p] -= ww * phi * rho
                if want_J:
                    _point_jacobian(a0, a1, v0, v1, R, rho, Fn, vt, branch, phi, prm, G, Dphi,
                                    D, z0, h)
                    _add_jacobians(S0, e, g, p, ww, D, Kq, Cv, Qw, dTq, dTv, dTw)
    return pairs


@njit(cache=True)
def contact_state(E, V, S0, centres, radii, omegas, prm):
    """:func:`contact_state_moving` with the pulley centres at rest."""
    return contact_state_moving(E, V, S0, centres, np.zeros_like(centres), radii, omegas, prm)


@njit(cache=True)
def contact_state_moving(E, V, S0, centres, odot, radii, omegas, prm):
    """:func:`contact_state_stepped` with a friction law's state 0 over a step of 0 s (its
    damper alone: a stateless law's whole force, not a law with a state's)."""
    z = np.zeros((S0.shape[0], S0.shape[1], radii.shape[0]))
    return contact_state_stepped(E, V, S0, centres, odot, radii, omegas, prm, z, 0.0)


@njit(cache=True)
def contact_state_stepped(E, V, S0, centres, odot, radii, omegas, prm, z, h):
    """Contact quantities at every point of S0 for post-processing (no bounding test),
    the pulley centres moving at odot (np, 2) m/s (rdot - odot enters the law, as in the
    march), a friction law with a state stepped from z (nel, ng, np) m over h (s) as the
    march steps it (:func:`contact_forces_moving`; a stateless law ignores z and h).

    Returns ``r`` (nel, ng, 2) centreline positions, m, and, each (nel, ng, np):
    penetration ``d`` (m, negative out of contact), normal force ``F_n`` (N/m),
    friction ``phi`` along t (N/m, signed) and sliding velocity ``v_t`` (m/s).
    """
    nel, ng = S0.shape[0], S0.shape[1]
    npul = radii.shape[0]
    r = np.zeros((nel, ng, 2))
    d, Fn = np.zeros((nel, ng, npul)), np.zeros((nel, ng, npul))
    phi, vt = np.zeros((nel, ng, npul)), np.zeros((nel, ng, npul))
    f, z1 = np.zeros(1), np.zeros(1)
    for e in range(nel):
        for g in range(ng):
            r0, r1, v0, v1 = _centreline(E, V, S0, e, g)
            r[e, g, 0], r[e, g, 1] = r0, r1
            for p in range(npul):
                _, dd, F, vtp, _ = _point_law(r0 - centres[p, 0], r1 - centres[p, 1],
                                              v0 - odot[p, 0], v1 - odot[p, 1], radii[p],
                                              omegas[p], prm, f, z[e, g, p], h, z1)
                d[e, g, p], Fn[e, g, p], phi[e, g, p], vt[e, g, p] = dd, F, f[0], vtp
    return r, d, Fn, phi, vt
