"""The regularised Coulomb law: mu F_n tanh(|v| / v_reg) against the sliding."""
from __future__ import annotations

import numpy as np
from numba import njit

from ancf.belts.friction.base import FrictionLaw, along, direction
from ancf.common.params import Param

#: its one smooth branch
SMOOTH = 4


@njit(cache=True, inline="always")
def coulomb_force(v, s, Fn, law, f):
    """Regularised Coulomb law: f = -mu F_n tanh(|v| / v_reg) v / |v| (law.mu -,
    law.v_reg m/s; f = 0 at v = 0), smooth, tending to -mu F_n v / |v| for
    |v| >> v_reg, with slope -mu F_n / v_reg through zero.  Returns SMOOTH."""
    mu, vr = law.mu, law.v_reg
    g = mu * Fn * np.tanh(s / vr) / s if s > 0.0 else 0.0
    for i in range(len(v)):
        f[i] = -g * v[i]
    return SMOOTH


@njit(cache=True, inline="always")
def coulomb_chain(branch, v, s, Fn, law, G, gF, D):
    """Derivatives of :func:`coulomb_force` chained through G, gF (see
    :mod:`ancf.belts.friction`): with x = |v| / v_reg, u = v / |v|, h = tanh(x) / |v| and
    q = (x sech^2 x - tanh x) / |v|, df/dv = -mu F_n (h I + q u u^T),
    df/dF_n = -mu tanh(x) u; at v = 0, df/dv = -mu F_n / v_reg I, df/dF_n = 0."""
    mu, vr = law.mu, law.v_reg
    n, m = len(v), len(gF)
    if s == 0.0:
        for i in range(n):
            for c in range(m):
                D[i, c] = -mu * Fn / vr * G[i, c]
        return
    x = s / vr
    th = np.tanh(x)
    h, q = th / s, (x * (1.0 - th * th) - th) / s
    u = direction(v, s)
    for c in range(m):
        ug = along(u, G, c)
        for i in range(n):
            D[i, c] = -mu * (Fn * (h * G[i, c] + q * u[i] * ug) + th * u[i] * gF[c])


COULOMB = FrictionLaw(
    name="coulomb", rank=1, force=coulomb_force, chain=coulomb_chain,
    params=(Param("mu", None, float, "-", "friction coefficient", lo=0, hi=10),
            Param("v_reg", None, float, "m/s", "regularisation speed (tanh(|v| / v_reg))",
                  lo=0, lo_open=True, hi=1e3)))
