"""The axially moving (Lagrange-Eulerian, ALE) description of the 2D Dufva belt
(Pechstein & Gerstmayr, Multibody Syst Dyn 30 (2013) 343-358), compiled where it loops.

The mesh stays on the path and the belt's material flows through it at the transport
speed ``vb`` (reference length per second, m/s): the material at mesh coordinate x has
the position r(x, t) of the element field, its velocity is Dr/Dt = r_t + vb r_x and its
acceleration r_tt + 2 vb r_xt + vb_t r_x + vb^2 r_xx.  In a steady running state r_t = 0,
so the material velocity is vb r_x: every kernel of the Lagrangian drive (strain-rate
damping, contact and friction, tensioner arms) sees it as the element velocities

    V_e = vb P_e E_e                                                      (1)

where the transport map P_e (:func:`transport_map`) takes an element's coordinates to
those of the field r_x: Hermite data of the quadratic centreline r_x (nodal r_x and
r_xx) and the constant (r_y^J - r_y^I) / l of the section's linear r_y, so S P E equals
S_x E at every point of the element, exactly.  The inertia of the steady flow is the
kinetic energy T = 1/2 int rho |vb r_x|^2 dV differentiated by the coordinates,

    F_s = -vb^2 M_x E,   M_x = int rho S_x^T S_x dV = P^T M P             (2)

(the consistent mass M of the element: S P = S_x), the centrifugal softening of the
axial force by rho A vb^2.  :func:`ale_terms` evaluates the Lagrangian drive's elastic,
damping, contact and arm kernels (:func:`ancf.belts.forces.drive_forces`) at the
velocities (1).
"""
from __future__ import annotations

import numpy as np
from numba import njit

from ancf.belts.forces import _arm_arrays, _arrays, drive_forces, gather, pulley_speeds


def transport_map(lengths) -> np.ndarray:
    """P (nel, 12, 12) of Eq. (1), element coordinates ordered ``k * 2 + d`` (slot k of
    r^I, r_x^I, r_y^I, r^J, r_x^J, r_y^J; component d); ``lengths`` (nel,) m.  The ends'
    r_xx of the cubic Hermite centreline: r_xx(0) = 6 (r^J - r^I) / l^2 - (4 r_x^I +
    2 r_x^J) / l, r_xx(l) = -6 (r^J - r^I) / l^2 + (2 r_x^I + 4 r_x^J) / l."""
    l = np.asarray(lengths, dtype=float)
    P6 = np.zeros((l.size, 6, 6))
    P6[:, 0, 1] = P6[:, 3, 4] = 1.0                       # r-slots take r_x
    P6[:, 1, 0], P6[:, 1, 3] = -6 / l**2, 6 / l**2        # r_x^I slot takes r_xx(0)
    P6[:, 1, 1], P6[:, 1, 4] = -4 / l, -2 / l
    P6[:, 4, 0], P6[:, 4, 3] = 6 / l**2, -6 / l**2        # r_x^J slot takes r_xx(l)
    P6[:, 4, 1], P6[:, 4, 4] = 2 / l, 4 / l
    P6[:, 2, 2] = P6[:, 5, 2] = -1 / l                    # r_y slots take the constant r_y'
    P6[:, 2, 5] = P6[:, 5, 5] = 1 / l
    return np.ascontiguousarray(np.einsum("eab,cd->eacbd", P6, np.eye(2)).reshape(-1, 12, 12))


def spin_matrix(mass, P) -> np.ndarray:
    """M_x = P^T M P (nel, 12, 12) of Eq. (2), kg/m... per element: ``mass`` the elements'
    consistent mass matrices (nel, 12, 12) kg, P from :func:`transport_map`."""
    return np.ascontiguousarray(np.einsum("eba,ebc,ecd->ead", P, mass, P))


@njit(cache=True)
def ale_terms(drive, x, w, vb, P, laws, want_J):
    """The Lagrangian drive's kernels at the steady ALE state: belt and arm coordinates in
    the system vector x, the free pulleys' angular velocities in w (w[n + j], rad/s; the
    rest 0), transport speed vb (m/s), the material velocities (1); ``laws`` the pulley
    laws (:mod:`ancf.belts.forces`).  A transient state (:mod:`ancf.belts.ale_march2d`)
    gives the mesh's rates q' in w's belt entries (m/s; the steady solve's are 0) and its
    arms' rates psi' in theirs: the material velocities are then V_e = q'_e + vb P_e E_e.  Returns E (nel, 6, 2), the element velocities V,
    the elastic and damping gradient g (nel, 12) and its dE Jacobian K, the contact
    outputs c = (Q, Kq, Cv, Qw, T, dTq, dTv, dTw) (Cv: d(Q_c - Q_d)/dV) and the arm
    outputs (:func:`ancf.belts.arm2d.arm_terms`)."""
    nel, nd = drive.vidx.shape
    E, V = np.empty((nel, 6, 2)), np.empty((nel, 6, 2))
    gather(x, drive.vidx, E, V, w)
    for e in range(nel):
        for a in range(nd):
            s = 0.0
            for b in range(nd):
                s += P[e, a, b] * E[e, b // 2, b % 2]
            V[e, a // 2, a % 2] += vb * s
    g = np.zeros((nel, nd))
    K = np.zeros((nel, nd, nd)) if want_J else np.zeros((0, 0, 0))
    c = _arrays(nel, nd, drive.radii.size, want_J)
    arm = _arm_arrays(nel, nd, drive.arms.shape[0], want_J)
    omegas = pulley_speeds(w, laws, drive.free, drive.inertia.size)
    drive_forces(drive, x, w, E, V, laws, omegas, want_J, g, K, c, arm)
    return E, V, g, K, c, arm
