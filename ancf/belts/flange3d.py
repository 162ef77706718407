"""Flanged pulleys of the plate belt: a side wall at each end of a pulley's face with
penalty contact on the belt's edges, so a belt that walks along a misaligned axis
(:mod:`ancf.belts.tracking3d`) is held; compiled (numba), forces and their exact
derivatives, added to the plate belt's contact (:func:`ancf.belts.forces.drive_forces`).

Geometry.  Pulley j (centre o, m; unit axis p; radius R, m) has its mid-face point
f = (o_x, o_y, z_m) on its axis line (z_m = w / 2, where the laid belt's mid-line runs:
:meth:`ancf.belts.drive3d.Belt3DDrive.align`), its face of width F between two walls
normal to p at the axial coordinates s = +-F / 2, each a disc of height H above the rim.
At a point r of one of the belt's two edges (the plate's mid surface at y = 0 and y = w,
n Gauss points per element along x; n^2 the contact rule, :mod:`ancf.belts.contact3d`):

    s      = (r - o) . p - (z_m - o_z) p_z            axial coordinate from f, m    (1)
    sigma  = sign(s),  delta = sigma s - F / 2        the wall it is beyond, by delta (m)
    N      = (r - o) - ((r - o) . p) p,  rho = |N|    radial vector and distance, m
    P      = k_f delta + c_f sigma p . (rdot - odot)  wall pressure per unit edge length
    F_f    = max(P, 0) g(rho)  if delta > 0 and rho < R + H, else 0        N/m       (2)
    f      = -sigma F_f p                             force per unit length on the belt

with g the wall's rim: 1 up to rho = R + H / 2, then 3 xi^2 - 2 xi^3, xi = (R + H - rho)
/ (H / 2), to 0 at R + H (a rounded rim: the force is continuous as an edge point rises
over it).  The walls are frictionless: f is along the axis, so it has no moment about it
and does not depend on the pulley's angular velocity; the pulley's rotation does not move
its walls (they turn in their own planes).  The generalised force and its derivatives,
over each element's edge points (weights w_q, m):

    Q_e     += sum_q w_q S_q^T f_q
    dQ/de    = sum_q w_q S_q^T (-sigma p) (dF_f/dr) S_q,
    dF_f/dr  = g k_f sigma p + P g'(rho) N / rho,       dF_f/drdot = g c_f sigma p      (3)

(on the active branch P > 0, delta > 0, rho < R + H; tests/belts/test_flange3d.py checks
them by finite differences).  The penalty per unit edge length is the rim's per unit area
times the belt's thickness h, k_f = k_p h and c_f = c_p h (the edge's area per unit length
pressed by the wall as the rim presses the belt's face).  The axial force of the flanges on
the belt, per pulley, is sum_q w_q f_q . p (N), the reaction on the pulley its negative.

A drive file turns the flanges on per pulley (``flanges``, ``face_width_m``,
``flange_height_m``: :data:`ancf.belts.drive_data.FLANGES`); :func:`flanges_of` builds the
compiled data, :class:`Flanges` (no flanged pulley: :data:`NO_FLANGES`, and the kernel is
not called: the drive is bit for bit the one without flanges).
"""
from __future__ import annotations

from typing import NamedTuple

import numpy as np
from numba import njit

from ancf.belts.contact3d import _mid_surface, _unit_axis
from ancf.core.quadrature import gauss01
from ancf.elements.basis import plate36_S

#: the columns of a flanged pulley's row: its pulley index, z_m (m), F / 2 (m), H (m),
#: k_f (N/m^2), c_f (N s/m^2)
PULLEY, MID, HALF, HEIGHT, STIFF, DAMP = range(6)
COLUMNS = 6
#: the face width a flanged pulley gets when the file gives none: the belt's width times
#: 1 + FACE_CLEARANCE (5 % of the belt's width between each edge and its wall)
FACE_CLEARANCE = 0.1


class Flanges(NamedTuple):
    """The compiled data of the flanged pulleys (module docstring)."""

    S: np.ndarray      # (nel, 2 n, 12) plate36 shape functions at the edge points
    w: np.ndarray      # (nel, 2 n) their Gauss weights, m
    table: np.ndarray  # (nf, COLUMNS) one row per flanged pulley
    #: (np, 3) per pulley its crown c (m), mid-face z_m (m), half face W / 2 (m); (0, 3)
    #: when no pulley is crowned (ancf.belts.contact3d_state, crowned rims)
    crowns: np.ndarray = np.zeros((0, 3))


NO_FLANGES = Flanges(S=np.zeros((0, 0, 12)), w=np.zeros((0, 0)), table=np.zeros((0, COLUMNS)),
                     crowns=np.zeros((0, 3)))


def edge_points(lengths, width: float, n: int) -> tuple:
    """(S (nel, 2 n, 12), w (nel, 2 n) m): the n Gauss points along x of each element's
    edges y = 0 (points 0..n-1) and y = width (n..2n-1); ``lengths`` (nel,) m."""
    a = np.asarray(lengths, dtype=float)[:, None]
    t, wg = gauss01(n)
    X = np.concatenate([t, t])[None, :] * a
    Y = np.concatenate([np.zeros(n), np.full(n, width)])[None, :] + 0.0 * a
    S = plate36_S(X, Y, a + 0.0 * X, np.full_like(X, width))
    return np.ascontiguousarray(S), np.ascontiguousarray(np.concatenate([wg, wg])[None, :] * a)


def face_width(params: dict, width: float) -> float:
    """A pulley's face width F (m) from its keys: ``face_width_m``, or 0 for the belt's
    width times 1 + :data:`FACE_CLEARANCE`."""
    given = params["face_width_m"]
    return given if given > 0 else (1.0 + FACE_CLEARANCE) * width


def flanges_of(drive, desc) -> Flanges:
    """The :class:`Flanges` of a description's pulleys with ``flanges = true`` on the plate
    belt ``drive`` (:data:`NO_FLANGES` when none has)."""
    s, rows = drive.spec, []
    for j, q in enumerate(desc.pulleys):
        if q.params.get("flanges", False):
            rows.append((j, 0.5 * s.width + q.params.get("face_offset_m", 0.0),
                         0.5 * face_width(q.params, s.width),
                         q.params["flange_height_m"], s.k_p * s.h, s.c_p * s.h))
    if not rows:
        return NO_FLANGES
    S, w = edge_points(drive.lengths, s.width, int(round(np.sqrt(s.contact_points))))
    return Flanges(S=S, w=w, table=np.array(rows, dtype=float))


@njit(cache=True)
def _rim(rho, R, H):
    """g(rho) and g'(rho) (1/m) of the wall's rounded rim (module docstring)."""
    half = 0.5 * H
    if rho <= R + half:
        return 1.0, 0.0
    xi = (R + H - rho) / half
    return xi * xi * (3.0 - 2.0 * xi), -6.0 * xi * (1.0 - xi) / half


@njit(cache=True)
def flange_forces3d(E, V, S, w, table, o, odot, axes, radii, want_J, Q, Kq, Cv, Fa):
    """Add the flanges' forces on the belt's edges (Eqs 1-3) to Q (nel, 36) N and, if
    ``want_J``, their derivatives to Kq, Cv (nel, 36, 36) (dQ/de, dQ/dedot), and each
    pulley's axial force on the belt sum w f . p to Fa (np,) N.  E, V (nel, 12, 3), o,
    odot (np, 3), axes, radii as :func:`ancf.belts.contact3d.contact_forces3d`; S, w,
    table of a :class:`Flanges`.  Returns the number of edge points pressed."""
    nel, ne = w.shape
    ns = S.shape[2]
    r, v, p, dF = np.zeros(3), np.zeros(3), np.zeros(3), np.zeros(6)
    N = np.zeros(3)
    pressed = 0
    for i in range(table.shape[0]):
        j = int(table[i, PULLEY])
        half, H, kf, cf = table[i, HALF], table[i, HEIGHT], table[i, STIFF], table[i, DAMP]
        _unit_axis(axes, j, p)
        R = radii[j]
        mid = (table[i, MID] - o[j, 2]) * p[2]
        for e in range(nel):
            for q in range(ne):
                _mid_surface(E, V, S, e, q, r, v)
                ap = (r[0] - o[j, 0]) * p[0] + (r[1] - o[j, 1]) * p[1] + (r[2] - o[j, 2]) * p[2]
                s = ap - mid
                sig = 1.0 if s > 0.0 else -1.0
                delta = sig * s - half
                if delta <= 0.0:
                    continue
                for c in range(3):
                    N[c] = r[c] - o[j, c] - ap * p[c]
                rho = np.sqrt(N[0] * N[0] + N[1] * N[1] + N[2] * N[2])
                if rho >= R + H:
                    continue
                vn = sig * ((v[0] - odot[j, 0]) * p[0] + (v[1] - odot[j, 1]) * p[1]
                            + (v[2] - odot[j, 2]) * p[2])
                P = kf * delta + cf * vn
                if P <= 0.0:
                    continue
                g, dg = _rim(rho, R, H)
                F = P * g
                if F <= 0.0:
                    continue
                pressed += 1
                ww = w[e, q]
                Fa[j] -= ww * sig * F
                for k in range(ns):
                    sk = ww * S[e, q, k]
                    for d in range(3):
                        Q[e, 3 * k + d] -= sk * sig * F * p[d]
                if not want_J:
                    continue
                for c in range(3):
                    dF[c] = g * kf * sig * p[c] + P * dg * N[c] / rho
                    dF[3 + c] = g * cf * sig * p[c]
                for k in range(ns):
                    sk = ww * S[e, q, k]
                    for m in range(ns):
                        skm = sk * S[e, q, m]
                        for d in range(3):
                            fd = -sig * p[d] * skm
                            for c in range(3):
                                Kq[e, 3 * k + d, 3 * m + c] += fd * dF[c]
                                Cv[e, 3 * k + d, 3 * m + c] += fd * dF[3 + c]
    return pressed


@njit(cache=True)
def add_flanges(E, V, fl, o, odot, axes, radii, want_J, c):
    """The flanges ``fl`` (a :class:`Flanges`) into the contact outputs ``c`` (Q, Kq, Cv, ...
    of :func:`ancf.belts.forces._arrays`), if any pulley has them; returns the points pressed."""
    if fl.table.shape[0] == 0:
        return 0
    return flange_forces3d(E, V, fl.S, fl.w, fl.table, o, odot, axes, radii, want_J, c[0],
                           c[1], c[2], np.zeros(radii.shape[0]))


def axial_forces(drive, E, V, o, odot) -> np.ndarray:
    """The flanges' axial force on the belt (np,) N at element coordinates E, V (nel, 12, 3)
    and pulley centres o, velocities odot (np, 3): sum w f . p per pulley (0 unflanged)."""
    fl, npul = drive.flanges, drive.radii.size
    Fa = np.zeros(npul)
    if fl.table.shape[0]:
        nel = E.shape[0]
        flange_forces3d(E, V, fl.S, fl.w, fl.table, o, odot, drive.axes, drive.radii, False,
                        np.zeros((nel, 36)), np.zeros((0, 36, 36)), np.zeros((0, 36, 36)), Fa)
    return Fa
