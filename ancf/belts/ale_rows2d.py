"""The free coordinates' rows of the ALE march of a 2D drive (:mod:`ancf.belts.ale_march2d`):
the free pulleys' (3) and the tensioner arms' (4), with their iteration-matrix entries.

Free pulley j (pulley p) and arm a (coordinate ja, angle psi rad, its pulley p's
coordinate j), as the Lagrangian march's (:func:`ancf.belts.forces._combine_arms`; the
pulley's bearing damping c_j acts on its turn relative to the arm):

    I_j omega_j' - T_c,p + T_a,p(t) + c_j (omega_j - psi') = 0                        (3)
    I_a psi'' - A - preload + k psi + c_a psi' - c_j (omega_j - psi') = 0               (4)

(psi' = 0 for a pulley without an arm.)  A (N m) the belt's moment about the pivot, T_c,p
its friction moment (:mod:`ancf.belts.arm2d`), both at the material velocities V = q' + vb
P q of the belt's coordinates q (m), so by q they move with dX/dq + vb dX/dV P (position)
and dX/dV (rate), by vb with dX/dV . P q (rate).  The arm's angle moves the pulley's
centre: Qp, Tp (the belt's forces' and the moment's derivatives by psi, psi') enter the
belt's rows (1) and (3).  The
entries are those of S = M* + gamma' C + beta' K (module docstring of ale_march2d).
"""
from __future__ import annotations

import numpy as np

from ancf.belts.arm2d import COORD, PRELOAD, PULLEY, STIFFNESS
from ancf.belts.pulleys import RESISTING


def load_torque(rec, law: float, omega: float) -> tuple:
    """(T_a N m, dT_a/domega N m s) of a free pulley's load record ``rec`` at its law's
    value ``law`` (N m) and speed ``omega`` (rad/s): a ``resisting`` load by its tanh law."""
    if rec.law != RESISTING:
        return law, 0.0
    s = np.tanh(omega / rec.omega_reg)
    return abs(law) * s, abs(law) * (1 - s * s) / rec.omega_reg


def _arms(kern):
    """Per arm: (a, its coordinate ja, its pulley's coordinate j, the arm's row)."""
    for a, row in enumerate(kern.arms):
        yield a, int(row[COORD]), int(kern.free[int(row[PULLEY])]), row


def free_rows(system, R, y, yd, ydd, laws, T, A) -> tuple:
    """Rows (3) and (4) into R (full layout) at positions y, rates yd, accelerations ydd;
    ``T`` the belt's moments (np,) N m, ``A`` the arms' (na,) N m.  Returns (the pulley
    speeds (np,) rad/s, dT_a/domega (k,) N m s)."""
    kern, n = system.kern, system.n + 1
    omegas = np.where(kern.free < 0, laws[: kern.free.size], 0.0)
    dTa = np.zeros(system.k)
    for p, j in enumerate(kern.free):
        if j >= 0:
            omegas[p] = yd[n + j]
            Ta, dTa[j] = load_torque(system.loads[j], laws[p], omegas[p])
            R[n + j] = kern.inertia[j] * ydd[n + j] - T[p] + Ta + kern.damping[j] * omegas[p]
    for a, ja, j, row in _arms(kern):
        cj, rel = kern.damping[j], yd[n + j] - yd[n + ja]
        R[n + j] -= cj * yd[n + ja]
        R[n + ja] = (kern.inertia[ja] * ydd[n + ja] - A[a] - row[PRELOAD]
                     + row[STIFFNESS] * y[n + ja] + kern.damping[ja] * yd[n + ja] - cj * rel)
    return omegas, dTa


def free_entries(system, put, d, bp, gp) -> None:
    """The iteration matrix's entries of rows (3), (4) and of the arms' columns:
    ``put(rows, cols, values)`` in the full layout; ``d`` the evaluation's parts (c, arm,
    PE, vb, dTa); bp, gp the coefficients beta', gamma' (s^2, s)."""
    kern, n, P, vb, PE = system.kern, system.n, system.P, d["vb"], d["PE"]
    _, _, _, Qw, _, dTq, dTv, dTw = d["c"]
    vidx = kern.vidx
    for p, j in enumerate(kern.free):
        if j < 0:
            continue
        put(vidx, n + 1 + j, -gp * Qw[:, p, :])
        _moment_row(put, n + 1 + j, dTq[p], dTv[p], P, PE, vb, vidx, bp, gp, n)
        put(n + 1 + j, n + 1 + j, kern.inertia[j]
            + gp * (kern.damping[j] - dTw[p] + d["dTa"][j]))
    _, dAq, dAv, dAw, dAp, Qp, Tp = d["arm"]
    for a, ja, j, row in _arms(kern):
        cj, col = kern.damping[j], n + 1 + ja
        _moment_row(put, col, dAq[a], dAv[a], P, PE, vb, vidx, bp, gp, n)
        put(col, n + 1 + j, -gp * (dAw[a] + cj))
        put(col, col, kern.inertia[ja] + bp * (row[STIFFNESS] - dAp[a, 0])
            + gp * (kern.damping[ja] + cj - dAp[a, 1]))
        put(vidx, col, -bp * Qp[a, 0] - gp * Qp[a, 1])
        put(n + 1 + j, col, -bp * Tp[a, 0] - gp * (Tp[a, 1] + cj))


def _moment_row(put, r, dXq, dXv, P, PE, vb, vidx, bp, gp, n) -> None:
    """Row r's entries of -X (X a moment of the belt: by its element coordinates dXq, by
    its element velocities dXv, (nel, 12)) by the belt's coordinates and by vb."""
    dXE = dXq + vb * np.einsum("eb,eba->ea", dXv, P)
    put(r, vidx, -gp * dXv - bp * dXE)
    put(r, n, -gp * np.sum(dXv * PE))
