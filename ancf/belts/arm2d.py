"""A tensioner in the 2D belt drive: an idler whose centre moves on an arm turning about a
pivot, the arm's rotation psi (rad, counter-clockwise from the given centre) one more
coordinate of the march (:mod:`ancf.belts.forces`), compiled (numba).

Arm a (a row of ``arms``: pulley p, its coordinate j, pivot P (m), length L (m), nominal
angle beta0 (rad, of c - P from x), spring stiffness k (N m/rad), preload (N m,
counter-clockwise)):

    l = L (cos b, sin b),  b = beta0 + psi      the arm, m
    o = P + l,  u = do/dpsi = I~ l,  odot = u psi'          (I~ = [[0, -1], [1, 0]])

The belt's generalised force on psi is the work of its force on the pulley along u,
A = u . F_p = (l x F_p)_z with F_p = -sum_g w_g f_g (:mod:`ancf.belts.contact2d`'s f, the
force per unit length on the belt), the moment about the pivot; the friction's moment T_p
turns the pulley (its own coordinate, the absolute angle).  The contact point law sees
r - o and rdot - odot, so by the centre it has the derivatives of r and rdot negated:
df/do = -df/dr, df/dodot = -df/drdot, with dodot/dpsi = I~ u psi' = -l psi' and
du/dpsi = -l.  :func:`arm_terms` adds A and, if ``want_J``, its derivatives by the belt's
coordinates and velocities, by the pulley's spin and by psi, psi', and the derivatives of
the belt's contact forces Q and of T_p by psi, psi'.
"""
from __future__ import annotations

import numpy as np
from numba import njit

from ancf.belts.contact2d import (_centreline, _may_touch, _point_jacobian, _point_law,
                                  _state_at)
from ancf.common.leaf import leaf

#: columns of an arm row (:func:`arm_row`), and their number
PULLEY, COORD, PIVOT_X, PIVOT_Y, LENGTH, BETA0, STIFFNESS, PRELOAD = range(8)
ARM_COLUMNS = PRELOAD + 1


def arm_row(*, pulley: int, coord: int, pivot, length: float, beta0: float,
            stiffness: float, preload: float) -> np.ndarray:
    """One arm as a row of ``arms`` (ARM_COLUMNS,): its pulley's index, its coordinate j
    past the free pulleys', pivot (2,) m, length m, nominal angle beta0 rad, spring
    stiffness N m/rad and preload N m (module docstring)."""
    row = np.zeros(ARM_COLUMNS)
    row[PULLEY], row[COORD], row[PIVOT_X], row[PIVOT_Y] = pulley, coord, pivot[0], pivot[1]
    row[LENGTH], row[BETA0], row[STIFFNESS], row[PRELOAD] = length, beta0, stiffness, preload
    return row


@leaf
def arm_geometry(arms, a, psi, psid, o, odot, u):
    """Arm a at rotation psi (rad), rate psid (rad/s): its pulley's centre o[p] (m) and
    velocity odot[p] (m/s), u[a] = do/dpsi (m); returns the pulley's index p."""
    p = int(arms[a, PULLEY])
    b = arms[a, BETA0] + psi
    l0, l1 = arms[a, LENGTH] * np.cos(b), arms[a, LENGTH] * np.sin(b)
    o[p, 0], o[p, 1] = arms[a, PIVOT_X] + l0, arms[a, PIVOT_Y] + l1
    u[a, 0], u[a, 1] = -l1, l0
    odot[p, 0], odot[p, 1] = -l1 * psid, l0 * psid
    return p


@leaf
def _centre_columns(D, u0, u1, psid, cols):
    """cols (3, 2): the derivatives of (f_0, f_1, tau) by psi and by psi' through the centre
    (D by r - o and rdot - odot, :func:`ancf.belts.contact2d._point_jacobian`)."""
    w0, w1 = -u1 * psid, u0 * psid  # dodot/dpsi = -l psi' = I~ u psi'
    for d in range(3):
        cols[d, 0] = -(D[d, 0] * u0 + D[d, 1] * u1 + D[d, 2] * w0 + D[d, 3] * w1)
        cols[d, 1] = -(D[d, 2] * u0 + D[d, 3] * u1)


@leaf
def _add_point(S0, e, g, a, ww, f0, f1, u0, u1, D, cols, out):
    """Add one contact point's Jacobian terms (module docstring) to ``out``."""
    _, dAq, dAv, dAw, dAp, Qp, Tp = out
    for k in range(S0.shape[2]):
        sk = ww * S0[e, g, k]
        for d in range(2):
            dAq[a, e, 2 * k + d] -= sk * (u0 * D[0, d] + u1 * D[1, d])
            dAv[a, e, 2 * k + d] -= sk * (u0 * D[0, 2 + d] + u1 * D[1, 2 + d])
            for c in range(2):
                Qp[a, c, e, 2 * k + d] += sk * cols[d, c]
    dAw[a] -= ww * (u0 * D[0, 4] + u1 * D[1, 4])
    # du/dpsi = -l = I~ u: A = -w u . f, so dA/dpsi = -w (I~ u . f + u . df/dpsi)
    dAp[a, 0] -= ww * (-u1 * f0 + u0 * f1 + u0 * cols[0, 0] + u1 * cols[1, 0])
    dAp[a, 1] -= ww * (u0 * cols[0, 1] + u1 * cols[1, 1])
    Tp[a, 0] += ww * cols[2, 0]
    Tp[a, 1] += ww * cols[2, 1]


@njit(cache=True)
def arm_terms(E, V, S0, w, o, odot, radii, omegas, prm, z, h, a, p, u, psid, want_J, out):
    """Add arm a's terms (pulley p, u (na, 2) from :func:`arm_geometry`, psid its rate,
    rad/s) to out = (A (na,) N m, dA/de and dA/dedot (na, nel, 12), dA/domega_p (na,),
    dA/d(psi, psi') (na, 2), dQ/d(psi, psi') (na, 2, nel, 12), dT_p/d(psi, psi') (na, 2)).
    E, V, S0, w, o, odot, radii, omegas, prm, z (read: z[0]; or NO_STATE), h as
    :func:`ancf.belts.contact2d.contact_forces_moving`."""
    nel, ng = w.shape
    D, Dphi, G, cols = np.zeros((3, 5)), np.zeros((1, 5)), np.zeros((1, 5)), np.zeros((3, 2))
    f, z1 = np.zeros(1), np.zeros(1)
    u0, u1, R = u[a, 0], u[a, 1], radii[p]
    for e in range(nel):
        if not _may_touch(E, e, np.sum(w[e]), o[p, 0], o[p, 1], R):
            continue
        for g in range(ng):
            r0, r1, v0, v1 = _centreline(E, V, S0, e, g)
            a0, a1, v0, v1 = r0 - o[p, 0], r1 - o[p, 1], v0 - odot[p, 0], v1 - odot[p, 1]
            z0 = _state_at(z, e, g, p, z1)
            rho, _, Fn, vt, branch = _point_law(a0, a1, v0, v1, R, omegas[p], prm, f, z0, h, z1)
            if Fn <= 0.0:
                continue
            phi = f[0]
            f0, f1 = (Fn * a0 - phi * a1) / rho, (Fn * a1 + phi * a0) / rho
            out[0][a] -= w[e, g] * (u0 * f0 + u1 * f1)
            if want_J:
                _point_jacobian(a0, a1, v0, v1, R, rho, Fn, vt, branch, phi, prm, G, Dphi, D,
                                z0, h)
                _centre_columns(D, u0, u1, psid, cols)
                _add_point(S0, e, g, a, w[e, g], f0, f1, u0, u1, D, cols, out)
