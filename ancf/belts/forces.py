"""Compiled force evaluations of the belt drives for :mod:`ancf.belts.march`.

One function per model, chosen at compile time by :func:`evaluate` from the type of
the model tuple (``kernel()`` of :class:`ancf.belts.drive2d.BeltDrive`, 9 entries, or of
:class:`ancf.belts.drive3d.Belt3DDrive`, 11 entries: :mod:`ancf.belts.forces3d`),
so the march is written once.
Both return the residual forces ``fz`` (belt: dU/dz - Q_c; ``fz[n]``: -T_c + T_a of
the driven pulley) at (x, v) and, if ``want_J``, the force part of the bordered
iteration matrix: band ``mat`` = bp (K - dQ/dz) - gp dQ/dz' (without M), border
``col`` / ``row`` and the corner's force part (returned with the number of
element-pulley pairs the contact kernel evaluated).

``laws`` are the pulley laws at the evaluation time: [omega_driver rad/s, T_a N m]
in 2D, followed in 3D by the driver's displacement u (m) and its rate (m/s) along
the model's shift direction (Eq. 4.46).
"""
from __future__ import annotations

import numpy as np
from numba import njit
from numba.extending import overload

from ancf.belts.contact2d import contact_forces
from ancf.elements import dufva2d
from ancf.belts.assembly import _arrays, _combine, gather


@njit(cache=True)
def evaluate2d(x, v, laws, mdl, want_J, bp, gp, fz, mat, col, row):
    """The 2D belt drive (Dufva elements, :mod:`ancf.belts.contact2d`)."""
    vidx, midx, eld, S0, w, centres, radii, prm, inertia = mdl
    nel = vidx.shape[0]
    E, V = np.empty((nel, 6, 2)), np.empty((nel, 6, 2))
    gather(x, vidx, E, V, v)
    g = np.zeros((nel, 12))
    K = np.zeros((nel, 12, 12)) if want_J else np.zeros((0, 0, 0))
    dufva2d.gradient_tangent(E, eld, want_J, g, K)
    c = _arrays(nel, 12, radii.size, want_J)
    omegas = np.array([laws[0], v[v.size - 1]])
    pairs = contact_forces(E, V, S0, w, centres, radii, omegas, prm, want_J, *c)
    return _combine(g, K, c, vidx, midx, bp, gp, want_J, laws[1], fz, mat, col, row), pairs


def evaluate(x, v, laws, mdl, want_J, bp, gp, fz, mat, col, row):
    """Dispatch to :func:`evaluate2d` or the 3D ``evaluate3d`` by the model tuple
    (compiled callers only; from Python call :func:`evaluate_any`)."""
    raise NotImplementedError("evaluate is resolved at compile time inside numba functions")


@overload(evaluate)
def _evaluate(x, v, laws, mdl, want_J, bp, gp, fz, mat, col, row):
    if len(mdl) == 9:
        return lambda x, v, laws, mdl, want_J, bp, gp, fz, mat, col, row: evaluate2d(
            x, v, laws, mdl, want_J, bp, gp, fz, mat, col, row)
    from ancf.belts.forces3d import evaluate3d  # the 3D model needs the 3D contact

    return lambda x, v, laws, mdl, want_J, bp, gp, fz, mat, col, row: evaluate3d(
        x, v, laws, mdl, want_J, bp, gp, fz, mat, col, row)


@njit(cache=True)
def evaluate_any(x, v, laws, mdl, want_J, bp, gp, fz, mat, col, row):
    """:func:`evaluate` callable from Python."""
    return evaluate(x, v, laws, mdl, want_J, bp, gp, fz, mat, col, row)
