"""The tri-linear creep-rate law of the thesis (Eq. 3.23, Fig. 3.3)."""
from __future__ import annotations

import numpy as np
from numba import njit

from ancf.belts.friction.base import FrictionLaw, along, direction
from ancf.common.params import Param

#: its branches (those of :func:`ancf.belts.contact3d.contact_state3d`)
LINEAR, SATURATED = 2, 3


@njit(cache=True, inline="always")
def creep_rate_force(v, s, Fn, law, f):
    """Tri-linear creep-rate law (Eq. 3.23, Fig. 3.3): f = -nu_s v while
    nu_s |v| <= mu F_n, else the Coulomb force -mu F_n v / |v| (law.mu -, law.nu_s
    kg/(m s) or kg/(m^2 s)).  Returns LINEAR or SATURATED."""
    mu, nu = law.mu, law.nu_s
    if nu * s <= mu * Fn:
        for i in range(len(v)):
            f[i] = -nu * v[i]
        return LINEAR
    if len(v) == 1:  # the direction v / |v| is sign(v), exactly
        f[0] = -np.sign(v[0]) * mu * Fn
        return SATURATED
    for i in range(len(v)):
        f[i] = -mu * Fn * v[i] / s
    return SATURATED


@njit(cache=True, inline="always")
def creep_rate_chain(branch, v, s, Fn, law, G, gF, D):
    """Derivatives of :func:`creep_rate_force` chained through G, gF (see
    :mod:`ancf.belts.friction`): linear, df/dv = -nu_s I, df/dF_n = 0; saturated, with
    u = v / s and g = mu F_n / s, df/dv = -g (I - u u^T), df/dF_n = -mu u."""
    mu, nu = law.mu, law.nu_s
    n, m = len(v), len(gF)
    if branch == LINEAR:
        for i in range(n):
            for c in range(m):
                D[i, c] = -nu * G[i, c]
        return
    g = mu * Fn / s
    u = direction(v, s)
    for c in range(m):
        ug = along(u, G, c)
        for i in range(n):
            D[i, c] = -mu * u[i] * gF[c] - g * (G[i, c] - u[i] * ug)


CREEP_RATE = FrictionLaw(
    name="creep-rate", rank=0, force=creep_rate_force, chain=creep_rate_chain,
    params=(Param("mu", None, float, "-", "friction coefficient", lo=0, hi=10),
            Param("nu_s", None, float, "kg/(m s)", "creep-rate factor (Fig. 3.3)", lo=0,
                  lo_open=True, hi=1e9)))
