"""Compiled force evaluation of the 3D belt drive (:mod:`ancf.belts.drive3d`) for the
march of :mod:`ancf.belts.march` (dispatched by :func:`ancf.belts.forces.evaluate`).
"""
from __future__ import annotations

import numpy as np
from numba import njit

from ancf.belts.contact3d import contact_forces3d
from ancf.elements import plate36
from ancf.belts.assembly import _arrays, _combine, gather


@njit(cache=True)
def evaluate3d(x, v, laws, mdl, want_J, bp, gp, fz, mat, col, row):
    """The 3D belt drive (plate36 elements, :mod:`ancf.belts.contact3d`); the driver's centre
    is moved by laws[2] along ``shift`` (at the rate laws[3])."""
    vidx, midx, eld, S0, w, centres, radii, prm, inertia, axes, shift = mdl
    nel = vidx.shape[0]
    E, V = np.empty((nel, 12, 3)), np.empty((nel, 12, 3))
    gather(x, vidx, E, V, v)
    g = np.zeros((nel, 36))
    K = np.zeros((nel, 36, 36)) if want_J else np.zeros((0, 0, 0))
    plate36.gradient_tangent(E, eld, want_J, g, K)
    c = _arrays(nel, 36, radii.size, want_J)
    omegas = np.array([laws[0], v[v.size - 1]])
    o, odot = centres.copy(), np.zeros_like(centres)
    o[0] += laws[2] * shift
    odot[0] = laws[3] * shift
    pairs = contact_forces3d(E, V, S0, w, o, axes, radii, omegas, odot, prm, want_J, *c)
    return _combine(g, K, c, vidx, midx, bp, gp, want_J, laws[1], fz, mat, col, row), pairs
