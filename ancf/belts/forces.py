"""Compiled force evaluation of the belt drives: elastic and contact forces of the belt
and the moments on the free pulleys, with the force part of the bordered iteration
matrix of the march (:mod:`ancf.belts.system`).

A drive reaches compiled code as named data, one record type per drive:
:class:`Drive2D` (``kernel()`` of :class:`ancf.belts.drive2d.BeltDrive`: Dufva
elements, :mod:`ancf.belts.contact2d`) and the records of :class:`Drive3D`'s fields (of
:class:`ancf.belts.drive3d.Belt3DDrive`: plate36 elements; the cylinders' contact of
:mod:`ancf.belts.contact3d` with any number of tensioner arms, none included, crowned rims
or a friction state (:mod:`ancf.belts.contact3d_state`), one record type,
:class:`ancf.belts.arm3d.Drive3DArms`).  Each record type compiles the march once more
(about a minute cold), so every plate belt is a Drive3DArms.
:func:`evaluate` is written once; its element and contact kernels are chosen at
compile time by the record's type (:func:`drive_forces`).

:func:`evaluate` returns the residual forces ``fz`` at the system state (x, v): belt
``dU/dz + Q_d - Q_c - F_g`` (band numbering of the drive's pattern; Q_d the 2D belt's
strain-rate damping, F_g its weight)
and, for free pulley j (pulley p with ``free[p] = j``; k of them, coordinates n + j
their angles theta_j), ``fz[n + j] = -T_c,p + T_a,p + c_j theta_j'`` (Eq. 3.26 with
the load torque T_a and the rotational damping c_j), and, if ``want_J``, the force
part of the iteration matrix: band ``mat`` = bp (K + dQ_d/dz - dQ_c/dz) + gp (dQ_d/dz'
- dQ_c/dz') (without M), border columns ``col[j]`` = -gp dQ_c/dtheta_j' and rows
``row[j]`` = -bp dT_c,p/dz - gp dT_c,p/dz', and the corner's force part ``corner``
(k, k), diagonal: gp (c_j - dT_c,p/dtheta_j').  A tensioner's arm (2D,
:mod:`ancf.belts.arm2d`) is one more coordinate psi past the free pulleys'
(:func:`_combine_arms`): its pulley's centre moves with psi, so the arm gets a row, a
column and corner entries with its pulley's coordinate.  It returns the number of element-pulley pairs the contact kernel evaluated.  bp, gp = 1, 0 or 0, 1 give df/dx and df/dv alone.

``laws`` are the pulley laws at the evaluation time, one row per pulley: a pulley
turned by its law (``free[p] = -1``) its angular velocity (rad/s), a free one its load
torque T_a (N m); then, for the i-th pulley of ``moving`` (its centre moved by a prescribed
law, :class:`ancf.belts.pulleys.CentreMotion`), the displacement u (m) and its rate (m/s)
along its unit direction ``shift[i]`` (the thesis driver's, Eq. 4.46), rows np + 2 i and
np + 2 i + 1 (:func:`moved_centres`; a tensioner's pivot is carried so).
"""
from __future__ import annotations

from typing import NamedTuple

import numpy as np
from numba import njit

from ancf.belts.arm2d import COORD, PULLEY, PRELOAD, STIFFNESS, arm_geometry, arm_terms
from ancf.belts.contact2d import contact_forces_moving
from ancf.belts.flange3d import NO_FLANGES, Flanges, add_flanges
from ancf.common.dispatch import as_struct, implements
from ancf.core.pattern import scatter
from ancf.elements import dufva2d, plate36

#: the belt damping's part of the iteration matrix (a 2D drive's ``damping_jacobian``):
#: exact (dQ_d/dz and dQ_d/dz'), or rate (dQ_d/dz' only; dQ_d/dz, proportional to the strain
#: rates, left out: the residual, and so the converged steps, are the same)
DAMPING_JACOBIANS = ("exact", "rate")


class Drive2D(NamedTuple):
    """The compiled data of a 2D belt drive (SI units)."""

    vidx: np.ndarray     # (nel, 12) element coordinates -> system positions
    midx: np.ndarray     # (nel, 12, 12) element matrix entries -> band storage
    element: tuple       # the Dufva elements' kernel data (DufvaBelt2D.kernel_data)
    strain_damping: np.ndarray  # (2,) the belt's dEA N s, dEI N m^2 s (dufva2d.damping_forces)
    S0: np.ndarray       # contact points' shape functions
    w: np.ndarray        # their weights (nel, ng), m
    centres: np.ndarray  # pulley centres (2, 2), m
    radii: np.ndarray    # pulley radii (2,), m
    prm: np.record       # k_p, c_p, friction law code, its parameters (contact_record)
    free: np.ndarray     # (np,) int: the pulley's coordinate j past the belt's, -1: its law
    inertia: np.ndarray  # (k,) the free pulleys' moments of inertia, kg m^2
    damping: np.ndarray  # (k,) their rotational damping, N m s
    weight: np.ndarray   # (n,) the belt's weight as generalised forces F_g, N
    arms: np.ndarray     # (na, ARM_COLUMNS) tensioner arms (ancf.belts.arm2d), psi coordinates j
    z: np.ndarray        # (2, nel, ng, np) friction state per contact point, m: [0] at the
    #                      last converged step, [1] the trial (a law with a state; else empty)
    h: np.ndarray        # (1,) the step the trial state is of, s (the march's)
    last: np.ndarray     # (2, np) work: the pulley speeds (rad/s) and the belt's moments on
    #                      them T_c,p (N m) at the last evaluation
    moving: np.ndarray   # (m,) int: the pulleys whose centres move by a prescribed law
    shift: np.ndarray    # (m, 2) their unit directions (module docstring)
    damping_jacobian: int = 0  # the damping's part of the iteration matrix: an index of
    #                      DAMPING_JACOBIANS (0 exact; 1 rate: dQ_d/dz' only)


class Drive3D(NamedTuple):
    """The fields of a 3D belt drive's compiled data (SI units; as :class:`Drive2D`); its
    records are its subclasses' (module docstring), each with its :func:`drive_forces`."""

    vidx: np.ndarray     # (nel, 36)
    midx: np.ndarray     # (nel, 36, 36)
    element: tuple       # the plate36 elements' kernel data (Plate36.kernel_data)
    S0: np.ndarray
    w: np.ndarray        # (nel, ng), m^2
    centres: np.ndarray  # (np, 3), m
    radii: np.ndarray
    prm: np.record
    free: np.ndarray
    inertia: np.ndarray
    damping: np.ndarray
    weight: np.ndarray   # (n,)
    arms: np.ndarray     # (0, ARM_COLUMNS): the arms are arm3d.Drive3DArms's
    z: np.ndarray        # (2, nel, nq, np, 2) m: a friction law's state (drive3d.NO_STATE: none)
    h: np.ndarray        # (1,)
    last: np.ndarray     # (2, np)
    axes: np.ndarray     # pulley axes (np, 3)
    moving: np.ndarray   # (m,) int: the pulleys whose centres move (the thesis's driver)
    shift: np.ndarray    # (m, 3) their unit directions (Eq. 4.46: the driver's -e_x)
    flanges: Flanges = NO_FLANGES  # flanged pulleys' walls (ancf.belts.flange3d)


def drive_forces(drive, x, v, E, V, laws, omegas, want_J, g, K, c, arm):
    """Add the elastic forces (g, and K if want_J), the contact outputs c of the elements
    with coordinates E and velocities V and the arm outputs ``arm`` (:func:`_arm_arrays`)
    at the system state x, v; returns the pairs evaluated."""
    raise NotImplementedError("resolved at compile time by the type of drive")


@njit(cache=True)
def moved_centres(drive, laws):
    """The pulley centres (np, dim) m and their velocities (np, dim) m/s at the pulley
    laws ``laws``: each pulley of ``drive.moving`` moved by its law along its direction."""
    o, odot = drive.centres.copy(), np.zeros_like(drive.centres)
    npul = drive.radii.shape[0]
    for i in range(drive.moving.size):
        p = drive.moving[i]
        o[p] += laws[npul + 2 * i] * drive.shift[i]
        odot[p] = laws[npul + 2 * i + 1] * drive.shift[i]
    return o, odot


@njit(cache=True)
def _carry(drive, laws, p, o, odot):
    """Add pulley p's prescribed motion to o[p], odot[p] (a tensioner's pulley placed on its
    arm: the pivot moves so)."""
    npul = drive.radii.shape[0]
    for i in range(drive.moving.size):
        if drive.moving[i] == p:
            o[p] += laws[npul + 2 * i] * drive.shift[i]
            odot[p] += laws[npul + 2 * i + 1] * drive.shift[i]


@njit(cache=True)
def _belt_damping(E, V, drive, want_J, g, K, Cv):
    """The belt's strain-rate damping forces Q_d (:func:`ancf.elements.dufva2d.damping_forces`)
    into g and dQ_d/dz into K, like the elastic forces (not with ``damping_jacobian`` rate:
    :func:`ancf.elements.dufva2d.damping_forces_rate`); dQ_d/dz' is subtracted from Cv,
    which holds dQ_c/dz' of the contact forces on the belt's other side.  Both through
    :func:`ancf.elements.dufva2d.damping_parts` with runtime flags: one compilation."""
    C = np.zeros_like(Cv)
    want_K = want_J and drive.damping_jacobian != 1
    dufva2d.damping_parts(E, V, drive.element, drive.strain_damping, want_K, want_J, g, K, C)
    Cv -= C


@implements(drive_forces, Drive2D)
def _forces2d(drive, x, v, E, V, laws, omegas, want_J, g, K, c, arm):
    """The centres moved by their laws (:func:`moved_centres`), the tensioners' pulleys at
    their arms' angles (:mod:`ancf.belts.arm2d`, their pivots moved alike); the belt's
    strain-rate damping only if it has any, an axial one alone in the elastic
    forces' pass (:func:`ancf.elements.dufva2d.gradient_tangent_damped`)."""
    d = drive.strain_damping
    if d[0] != 0.0 and d[1] == 0.0:
        Cv = c[2]
        C = np.zeros_like(Cv)  # an axial damping alone: with the elastic pass
        want_Kd = want_J and drive.damping_jacobian != 1
        dufva2d.gradient_tangent_damped(E, V, drive.element, d[0], want_J, want_Kd, want_J,
                                        g, K, C)
        Cv -= C
    else:
        dufva2d.gradient_tangent(E, drive.element, want_J, g, K)
        if d[0] != 0.0 or d[1] != 0.0:
            _belt_damping(E, V, drive, want_J, g, K, c[2])
    arms, n = drive.arms, x.size - drive.inertia.size
    o, odot = moved_centres(drive, laws)
    u = np.zeros((arms.shape[0], 2))
    for a in range(arms.shape[0]):
        j = n + int(arms[a, COORD])
        p = arm_geometry(arms, a, x[j], v[j], o, odot, u)
        _carry(drive, laws, p, o, odot)
        arm_terms(E, V, drive.S0, drive.w, o, odot, drive.radii, omegas, drive.prm, drive.z,
                  drive.h[0], a, p, u, v[j], want_J, arm)
    return contact_forces_moving(E, V, drive.S0, drive.w, o, odot, drive.radii, omegas,
                                 drive.prm, drive.z, drive.h[0], want_J, *c)


@njit(cache=True)
def gather(x, vidx, E, V, v):
    """Element coordinates E and velocities V (nel, nshape, dim) from system vectors x, v."""
    nel, nd = vidx.shape
    dim = E.shape[2]
    for e in range(nel):
        for a in range(nd):
            E[e, a // dim, a % dim] = x[vidx[e, a]]
            V[e, a // dim, a % dim] = v[vidx[e, a]]


@njit(cache=True)
def _arrays(nel, nd, npul, want_J):
    """Zeroed contact outputs: Q, Kq, Cv, Qw, T, dTq, dTv, dTw."""
    nj = nel if want_J else 0
    return (np.zeros((nel, nd)), np.zeros((nj, nd, nd)), np.zeros((nj, nd, nd)),
            np.zeros((nj, npul, nd)), np.zeros(npul), np.zeros((npul, nj, nd)),
            np.zeros((npul, nj, nd)), np.zeros(npul))


@njit(cache=True)
def _arm_arrays(nel, nd, na, want_J):
    """Zeroed arm outputs (:func:`ancf.belts.arm2d.arm_terms`): A, dAq, dAv, dAw, dAp,
    Qp, Tp."""
    nj = nel if want_J else 0
    return (np.zeros(na), np.zeros((na, nj, nd)), np.zeros((na, nj, nd)), np.zeros(na),
            np.zeros((na, 2)), np.zeros((na, 2, nj, nd)), np.zeros((na, 2)))


@njit(cache=True)
def _combine_arms(drive, x, v, arm, bp, gp, want_J, fz, col, row, corner):
    """The arms' rows and columns: arm a (coordinate ja, its pulley's j) obeys
    I_a psi'' = A + preload - k psi - c_a psi' + c_j (theta_j' - psi'), the pulley's
    bearing damping c_j acting on its turn relative to the arm (its row gets -c_j psi')."""
    A, dAq, dAv, dAw, dAp, Qp, Tp = arm
    arms, vidx = drive.arms, drive.vidx
    n = fz.size - drive.inertia.size
    for a in range(arms.shape[0]):
        ja, j = int(arms[a, COORD]), drive.free[int(arms[a, PULLEY])]
        cj, ca, k = drive.damping[j], drive.damping[ja], arms[a, STIFFNESS]
        psi, psid, th = x[n + ja], v[n + ja], v[n + j]
        fz[n + j] -= cj * psid
        fz[n + ja] = -A[a] - arms[a, PRELOAD] + k * psi + ca * psid - cj * (th - psid)
        if not want_J:
            continue
        for e in range(vidx.shape[0]):
            for b in range(vidx.shape[1]):
                i = vidx[e, b]
                col[ja, i] -= bp * Qp[a, 0, e, b] + gp * Qp[a, 1, e, b]
                row[ja, i] -= bp * dAq[a, e, b] + gp * dAv[a, e, b]
        corner[j, ja] -= bp * Tp[a, 0] + gp * (Tp[a, 1] + cj)
        corner[ja, ja] = bp * (k - dAp[a, 0]) + gp * (ca + cj - dAp[a, 1])
        corner[ja, j] = -gp * (dAw[a] + cj)


@njit(cache=True)
def _combine(g, K, c, drive, bp, gp, want_J, laws, omegas, fz, mat, col, row, corner):
    """Elastic gradient g, K and contact outputs c into fz, mat, col, row and the corner."""
    Q, Kq, Cv, Qw, T, dTq, dTv, dTw = c
    vidx, free = drive.vidx, drive.free
    nel, nd = g.shape
    n = fz.size - drive.inertia.size
    fz[:] = 0.0
    g -= Q
    if want_J:
        mat[:, :] = 0.0
        col[:, :] = 0.0
        row[:, :] = 0.0
        corner[:, :] = 0.0
        for e in range(nel):
            for a in range(nd):
                i = vidx[e, a]
                for p in range(free.size):
                    j = free[p]
                    if j >= 0:
                        col[j, i] -= gp * Qw[e, p, a]
                        row[j, i] -= bp * dTq[p, e, a] + gp * dTv[p, e, a]
                for b in range(nd):
                    K[e, a, b] = bp * (K[e, a, b] - Kq[e, a, b]) - gp * Cv[e, a, b]
    scatter(g, K, vidx, drive.midx, fz, mat, want_J)
    for i in range(n):
        fz[i] -= drive.weight[i]
    for p in range(free.size):
        j = free[p]
        if j >= 0:
            fz[n + j] = -T[p] + laws[p] + drive.damping[j] * omegas[p]
            if want_J:
                corner[j, j] = -gp * dTw[p] + gp * drive.damping[j]


@njit(cache=True)
def pulley_speeds(v, laws, free, k):
    """Angular velocities (np,) rad/s: a free pulley's from v (its coordinate n + j), the
    others' from their laws."""
    n = v.size - k
    omegas = np.empty(free.size)
    for p in range(free.size):
        omegas[p] = laws[p] if free[p] < 0 else v[n + free[p]]
    return omegas


@njit(cache=True)
def evaluate(x, v, laws, drive, want_J, bp, gp, fz, mat, col, row, corner):
    """The residual forces and the force part of the iteration matrix (module docstring);
    the pulley speeds and moments into ``drive.last``; returns the pairs the contact
    kernel evaluated."""
    nel, nd = drive.vidx.shape
    dim = drive.centres.shape[1]
    E, V = np.empty((nel, nd // dim, dim)), np.empty((nel, nd // dim, dim))
    gather(x, drive.vidx, E, V, v)
    g = np.zeros((nel, nd))
    K = np.zeros((nel, nd, nd)) if want_J else np.zeros((0, 0, 0))
    c = _arrays(nel, nd, drive.radii.size, want_J)
    arm = _arm_arrays(nel, nd, drive.arms.shape[0], want_J)
    omegas = pulley_speeds(v, laws, drive.free, drive.inertia.size)
    pairs = drive_forces(drive, x, v, E, V, laws, omegas, want_J, g, K, c, arm)
    drive.last[0] = omegas
    drive.last[1] = c[4]
    _combine(g, K, c, drive, bp, gp, want_J, laws, omegas, fz, mat, col, row, corner)
    _combine_arms(drive, x, v, arm, bp, gp, want_J, fz, col, row, corner)
    return pairs


@njit(cache=True)
def evaluate_record(x, v, laws, drive, want_J, bp, gp, fz, mat, col, row, corner):
    """:func:`evaluate` from Python (:mod:`ancf.belts.bdf`) with the drive's record and its
    laws (np,) at one time, called with the march's types (the drive as its struct, the
    laws a column of a table): evaluate and the drive's kernels are not compiled again
    for another signature (about 15 CPU-s cold per drive type)."""
    tab = np.empty((laws.size, 1))
    tab[:, 0] = laws
    return evaluate(x, v, tab[:, 0], as_struct(drive), want_J, bp, gp, fz, mat, col, row,
                    corner)
