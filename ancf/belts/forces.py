"""Compiled force evaluation of the belt drives: elastic and contact forces of the belt
and the moments on the free pulleys, with the force part of the bordered iteration
matrix of the march (:mod:`ancf.belts.system`).

A drive reaches compiled code as named data, one record type per drive:
:class:`Drive2D` (``kernel()`` of :class:`ancf.belts.drive2d.BeltDrive`: Dufva
elements, :mod:`ancf.belts.contact2d`) and :class:`Drive3D` (of
:class:`ancf.belts.drive3d.Belt3DDrive`: plate36 elements, :mod:`ancf.belts.contact3d`).
:func:`evaluate` is written once; its element and contact kernels are chosen at
compile time by the record's type (:func:`drive_forces`).

:func:`evaluate` returns the residual forces ``fz`` at the system state (x, v): belt
``dU/dz - Q_c - F_g`` (band numbering of the drive's pattern; F_g the belt's weight)
and, for free pulley j (pulley p with ``free[p] = j``; k of them, coordinates n + j
their angles theta_j), ``fz[n + j] = -T_c,p + T_a,p + c_j theta_j'`` (Eq. 3.26 with
the load torque T_a and the rotational damping c_j), and, if ``want_J``, the force
part of the iteration matrix: band ``mat`` = bp (K - dQ_c/dz) - gp dQ_c/dz' (without
M), border columns ``col[j]`` = -gp dQ_c/dtheta_j' and rows ``row[j]`` = -bp
dT_c,p/dz - gp dT_c,p/dz', and the corner's force part ``corner`` (k, k), diagonal:
gp (c_j - dT_c,p/dtheta_j').  It returns the number of element-pulley pairs the
contact kernel evaluated.  bp, gp = 1, 0 or 0, 1 give df/dx and df/dv alone.

``laws`` are the pulley laws at the evaluation time, one row per pulley: a pulley
turned by its law (``free[p] = -1``) its angular velocity (rad/s), a free one its load
torque T_a (N m); in 3D followed by the driver's displacement u (m) and its rate (m/s)
along the drive's ``shift`` direction (Eq. 4.46).
"""
from __future__ import annotations

from typing import NamedTuple

import numpy as np
from numba import njit

from ancf.belts.contact2d import contact_forces
from ancf.belts.contact3d import contact_forces3d
from ancf.common.dispatch import implements
from ancf.core.pattern import scatter
from ancf.elements import dufva2d, plate36

class Drive2D(NamedTuple):
    """The compiled data of a 2D belt drive (SI units)."""

    vidx: np.ndarray     # (nel, 12) element coordinates -> system positions
    midx: np.ndarray     # (nel, 12, 12) element matrix entries -> band storage
    element: tuple       # the Dufva elements' kernel data (DufvaBelt2D.kernel_data)
    S0: np.ndarray       # contact points' shape functions
    w: np.ndarray        # their weights (nel, ng), m
    centres: np.ndarray  # pulley centres (2, 2), m
    radii: np.ndarray    # pulley radii (2,), m
    prm: np.ndarray      # [k_p, c_p, friction law code, its parameters] (contact_vector)
    free: np.ndarray     # (np,) int: the pulley's coordinate j past the belt's, -1: its law
    inertia: np.ndarray  # (k,) the free pulleys' moments of inertia, kg m^2
    damping: np.ndarray  # (k,) their rotational damping, N m s
    weight: np.ndarray   # (n,) the belt's weight as generalised forces F_g, N


class Drive3D(NamedTuple):
    """The compiled data of a 3D belt drive (SI units; fields as :class:`Drive2D`)."""

    vidx: np.ndarray     # (nel, 36)
    midx: np.ndarray     # (nel, 36, 36)
    element: tuple       # the plate36 elements' kernel data (Plate36.kernel_data)
    S0: np.ndarray
    w: np.ndarray        # (nel, ng), m^2
    centres: np.ndarray  # (2, 3), m
    radii: np.ndarray
    prm: np.ndarray
    free: np.ndarray
    inertia: np.ndarray
    damping: np.ndarray
    weight: np.ndarray   # (n,)
    axes: np.ndarray     # pulley axes (2, 3)
    shift: np.ndarray    # direction the driver is moved in (3,)


def drive_forces(drive, E, V, laws, omegas, want_J, g, K, c):
    """Add the elastic forces (g, and K if want_J) and the contact outputs c of the
    elements with coordinates E and velocities V; returns the pairs evaluated."""
    raise NotImplementedError("resolved at compile time by the type of drive")


@implements(drive_forces, Drive2D)
def _forces2d(drive, E, V, laws, omegas, want_J, g, K, c):
    dufva2d.gradient_tangent(E, drive.element, want_J, g, K)
    return contact_forces(E, V, drive.S0, drive.w, drive.centres, drive.radii, omegas, drive.prm,
                          want_J, *c)


@implements(drive_forces, Drive3D)
def _forces3d(drive, E, V, laws, omegas, want_J, g, K, c):
    """The driver's centre is moved by laws[2] along ``shift`` (at the rate laws[3])."""
    plate36.gradient_tangent(E, drive.element, want_J, g, K)
    o, odot = drive.centres.copy(), np.zeros_like(drive.centres)
    o[0] += laws[2] * drive.shift
    odot[0] = laws[3] * drive.shift
    return contact_forces3d(E, V, drive.S0, drive.w, o, drive.axes, drive.radii, omegas, odot,
                            drive.prm, want_J, *c)


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
    returns the pairs the contact kernel evaluated."""
    nel, nd = drive.vidx.shape
    dim = drive.centres.shape[1]
    E, V = np.empty((nel, nd // dim, dim)), np.empty((nel, nd // dim, dim))
    gather(x, drive.vidx, E, V, v)
    g = np.zeros((nel, nd))
    K = np.zeros((nel, nd, nd)) if want_J else np.zeros((0, 0, 0))
    c = _arrays(nel, nd, drive.radii.size, want_J)
    omegas = pulley_speeds(v, laws, drive.free, drive.inertia.size)
    pairs = drive_forces(drive, E, V, laws, omegas, want_J, g, K, c)
    _combine(g, K, c, drive, bp, gp, want_J, laws, omegas, fz, mat, col, row, corner)
    return pairs
