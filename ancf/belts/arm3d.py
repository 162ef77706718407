"""A tensioner in the 3D plate belt drive: the idler on an arm turning about the z axis
through its pivot, in the x-y plane (the arm of :mod:`ancf.belts.arm2d`: its row of
``arms``, :func:`~ancf.belts.arm2d.arm_geometry`, its spring, preload and damping, and its
rows in the march, :func:`ancf.belts.forces._combine_arms`), with the plate belt's contact
(:mod:`ancf.belts.contact3d`), compiled (numba).

Arm a at rotation psi (rad) places its pulley at o = P + l, l = L (cos b, sin b, 0),
b = beta0 + psi, with u = do/dpsi = e_z x l and odot = u psi'.  The belt's generalised
force on psi is the moment about the pivot of its force on the pulley,

    A = u . F_p = (l x F_p)_z,   F_p = -sum_q w_q f_q           N m   (contact3d's f)

and the contact law at a point sees a = r - o and rdot - odot, so by the centre it has
the derivatives by r and rdot negated: df/do = -df/dr, df/dodot = -df/drdot, with
dodot/dpsi = e_z x u psi' = -l psi' and du/dpsi = -l (the same for the moment tau of
the friction about the pulley's axis).  :func:`arm_terms3d` adds A and, if ``want_J``,
dA/de, dA/dedot (the arm's row by the belt), dA/domega_p, dA/d(psi, psi'), the belt's
contact forces' dQ/d(psi, psi') (the arm's column) and dT_p/d(psi, psi'), into the
outputs of :func:`ancf.belts.forces._arm_arrays` (36 coordinates per element).

:class:`Drive3DArms` is :class:`ancf.belts.forces.Drive3D` with tensioner arms, none
included (every plate belt): its :func:`ancf.belts.forces.drive_forces` places each arm's
pulley on its arm (its pivot carried by the pulley's prescribed centre motion) before the
contact acts; without arms that is the centres moved by their laws, the flanges and the
cylinders' contact, the crowned rims' or a friction state's
(:func:`ancf.belts.contact3d_state.contact_forces3d_crown`, ``contact_forces3d_state``),
chosen at run time: one record type, so one compilation of the march, for all of them.
"""
from __future__ import annotations

import numpy as np
from numba import njit

from ancf.belts import friction
from ancf.belts.arm2d import COORD, arm_geometry
from ancf.belts.contact3d import (_control_points, _may_touch, _mid_surface, _point_jacobian,
                                  _point_law, _sides, _unit_axis, contact_forces3d)
from ancf.belts.contact3d_state import contact_forces3d_crown, contact_forces3d_state
from ancf.belts.flange3d import add_flanges
from ancf.belts.forces import Drive3D, _carry, drive_forces, moved_centres
from ancf.common.dispatch import implements
from ancf.common.leaf import leaf
from ancf.elements import plate36


class Drive3DArms(Drive3D):
    """The compiled data of a 3D belt drive on cylinders with na >= 0 tensioner arms
    (fields as :class:`ancf.belts.forces.Drive3D`; ``arms`` (na, ARM_COLUMNS) of
    :mod:`ancf.belts.arm2d`, their angles coordinates past the free pulleys')."""

    __slots__ = ()


@leaf
def _centre_columns3d(D, u0, u1, psid, cols):
    """cols (4, 2): the derivatives of (f_0, f_1, f_2, tau) by psi and by psi' through the
    centre (D (4, 7) by r, rdot, omega: :func:`ancf.belts.contact3d._point_jacobian`)."""
    w0, w1 = -u1 * psid, u0 * psid  # dodot/dpsi = -l psi' = e_z x u psi'
    for d in range(4):
        cols[d, 0] = -(D[d, 0] * u0 + D[d, 1] * u1 + D[d, 3] * w0 + D[d, 4] * w1)
        cols[d, 1] = -(D[d, 3] * u0 + D[d, 4] * u1)


@leaf
def _add_point3d(S0, e, q, a, ww, f0, f1, u0, u1, D, cols, out):
    """Add contact point q's Jacobian terms (weight ww, m^2; module docstring) to ``out``."""
    _, dAq, dAv, dAw, dAp, Qp, Tp = out
    for k in range(S0.shape[2]):
        sk = ww * S0[e, q, k]
        for d in range(3):
            i = 3 * k + d
            dAq[a, e, i] -= sk * (u0 * D[0, d] + u1 * D[1, d])
            dAv[a, e, i] -= sk * (u0 * D[0, 3 + d] + u1 * D[1, 3 + d])
            Qp[a, 0, e, i] += sk * cols[d, 0]
            Qp[a, 1, e, i] += sk * cols[d, 1]
    dAw[a] -= ww * (u0 * D[0, 6] + u1 * D[1, 6])
    # du/dpsi = -l = e_z x u: A = -w u . f, so dA/dpsi = -w (e_z x u . f + u . df/dpsi)
    dAp[a, 0] -= ww * (-u1 * f0 + u0 * f1 + u0 * cols[0, 0] + u1 * cols[1, 0])
    dAp[a, 1] -= ww * (u0 * cols[0, 1] + u1 * cols[1, 1])
    Tp[a, 0] += ww * cols[3, 0]
    Tp[a, 1] += ww * cols[3, 1]


@njit(cache=True)
def arm_terms3d(E, V, S0, w, o, odot, axes, radii, omegas, prm, a, p, u, psid, want_J, out):
    """Add arm a's terms (pulley p, u (na, 2) m from
    :func:`ancf.belts.arm2d.arm_geometry`, psid its rate, rad/s) to out = (A (na,) N m,
    dA/de and dA/dedot (na, nel, 36), dA/domega_p (na,), dA/d(psi, psi') (na, 2),
    dQ/d(psi, psi') (na, 2, nel, 36), dT_p/d(psi, psi') (na, 2)).  E, V, S0, w, o (np, 3),
    odot, axes, radii, omegas, prm as :func:`ancf.belts.contact3d.contact_forces3d`."""
    nel, nq = w.shape
    D, G, gF, cols = np.zeros((4, 7)), np.zeros((3, 7)), np.zeros(7), np.zeros((4, 2))
    P, X = np.zeros((16, 3)), np.zeros((16, 3))
    r, v, av, vr = np.zeros(3), np.zeros(3), np.zeros(3), np.zeros(3)
    n, t, vs, ft, pax = np.zeros(3), np.zeros(3), np.zeros(3), np.zeros(3), np.zeros(3)
    _unit_axis(axes, p, pax)
    R, om, u0, u1 = radii[p], omegas[p], u[a, 0], u[a, 1]
    for e in range(nel):
        sa, sb = _sides(S0, w, e)
        _control_points(E, e, sa, sb, P)
        if not _may_touch(P, o[p], pax, R, X):
            continue
        for q in range(nq):
            _mid_surface(E, V, S0, e, q, r, v)
            for c in range(3):
                av[c], vr[c] = r[c] - o[p, c], v[c] - odot[p, c]
            rho, _, Fn, vsn, branch = _point_law(av, vr, pax, R, om, prm, n, t, vs, ft)
            if Fn <= 0.0:
                continue
            f0, f1 = Fn * n[0] + ft[0], Fn * n[1] + ft[1]
            out[0][a] -= w[e, q] * (u0 * f0 + u1 * f1)
            if want_J:
                _point_jacobian(vr, pax, R, om, rho, Fn, vsn, branch, n, t, vs, ft, prm, gF,
                                G, D)
                _centre_columns3d(D, u0, u1, psid, cols)
                _add_point3d(S0, e, q, a, w[e, q], f0, f1, u0, u1, D, cols, out)


@implements(drive_forces, Drive3DArms)
def _forces3d_arms(drive, x, v, E, V, laws, omegas, want_J, g, K, c, arm):
    """The centres moved by their laws (:func:`ancf.belts.forces.moved_centres`), each
    tensioner's pulley on its arm at the arm's angle (its pivot moved alike), the arms'
    terms (:func:`arm_terms3d`), then the contact of every pulley."""
    plate36.gradient_tangent(E, drive.element, want_J, g, K)
    arms, n = drive.arms, x.size - drive.inertia.size
    o, odot = moved_centres(drive, laws)
    u = np.zeros((arms.shape[0], 2))
    for a in range(arms.shape[0]):
        j = n + int(arms[a, COORD])
        p = arm_geometry(arms, a, x[j], v[j], o, odot, u)
        _carry(drive, laws, p, o, odot)
        arm_terms3d(E, V, drive.S0, drive.w, o, odot, drive.axes, drive.radii, omegas,
                    drive.prm, a, p, u, v[j], want_J, arm)
    add_flanges(E, V, drive.flanges, o, odot, drive.axes, drive.radii, want_J, c)
    if friction.has_state(drive.prm):  # its state z (no arms, no crowns then: drive3d)
        return contact_forces3d_state(E, V, drive.S0, drive.w, o, drive.axes, drive.radii,
                                      omegas, odot, drive.prm, drive.z, drive.h[0], want_J, *c)
    if drive.flanges.crowns.shape[0]:  # crowned rims (no arms then: tracking3d.crowns_of)
        return contact_forces3d_crown(E, V, drive.S0, drive.w, o, drive.axes, drive.radii,
                                      omegas, odot, drive.prm, drive.flanges.crowns, want_J, *c)
    return contact_forces3d(E, V, drive.S0, drive.w, o, drive.axes, drive.radii, omegas, odot,
                            drive.prm, want_J, *c)
