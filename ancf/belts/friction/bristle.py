"""The bristle law: a tangential spring and damper per contact point capped by Coulomb,
whose deflection is a state carried from step to step."""
from __future__ import annotations

import numpy as np
from numba import njit

from ancf.belts.friction.base import FrictionLaw
from ancf.common.params import Param

#: its branches
STICK, SLIP = 5, 6


@njit(cache=True, inline="always")
def bristle_force(v, z0, h, Fn, law, f, z1):
    """Bristle law (a tangential spring k_t = law.stiffness and damper
    d_t = law.damping between the belt and the pulley surface, capped by Coulomb,
    mu = law.mu), one step of length h (s) from the bristle deflection z0 (n-tuple, m) of
    the last converged step, backward Euler: the trial deflection z0 + h v gives
    w = k_t z0 + (k_t h + d_t) v and the trial force -w; stick while |w| <= mu F_n
    (f = -w, z1 = z0 + h v), else slip (f = -mu F_n w / |w|, z1 = mu F_n w / (k_t |w|):
    the spring at the Coulomb limit).  Fills f and the step's deflection z1 (n,), m;
    returns STICK or SLIP.  With k_t = 0 it is the creep-rate law with nu_s = d_t
    (:func:`ancf.belts.friction.creep_rate.creep_rate_force`)."""
    mu, kt, dt = law.mu, law.stiffness, law.damping
    c = kt * h + dt
    wn = 0.0
    for i in range(len(v)):
        f[i] = -(kt * z0[i] + c * v[i])
        wn += f[i] * f[i]
    wn = np.sqrt(wn)
    if wn <= mu * Fn:
        for i in range(len(v)):
            z1[i] = z0[i] + h * v[i]
        return STICK
    for i in range(len(v)):
        f[i] = np.sign(f[i]) * mu * Fn if len(v) == 1 else f[i] * mu * Fn / wn  # sign exactly
        z1[i] = -f[i] / kt if kt > 0.0 else 0.0
    return SLIP


@njit(cache=True, inline="always")
def bristle_chain(branch, v, z0, h, Fn, law, G, gF, D):
    """Derivatives of :func:`bristle_force` by v and F_n chained through G, gF (z0 and h
    are the march's, fixed within a step): with c = k_t h + d_t, stick: df/dv = -c I,
    df/dF_n = 0; slip, with u = w / |w|: df/dv = -mu F_n c / |w| (I - u u^T),
    df/dF_n = -mu u."""
    mu, kt, dt = law.mu, law.stiffness, law.damping
    c = kt * h + dt
    n, m = len(v), len(gF)
    if branch == STICK:
        for i in range(n):
            for k in range(m):
                D[i, k] = -c * G[i, k]
        return
    wn = 0.0
    for i in range(n):
        wn += (kt * z0[i] + c * v[i]) ** 2
    wn = np.sqrt(wn)
    g = mu * Fn * c / wn
    for k in range(m):
        ug = 0.0
        for j in range(n):
            ug += (kt * z0[j] + c * v[j]) / wn * G[j, k]
        for i in range(n):
            u = (kt * z0[i] + c * v[i]) / wn
            D[i, k] = -mu * u * gF[k] - g * (G[i, k] - u * ug)


BRISTLE = FrictionLaw(
    name="bristle", rank=2, state=True, force=bristle_force, chain=bristle_chain,
    params=(Param("mu", None, float, "-", "friction coefficient", lo=0, hi=10),
            Param("stiffness", None, float, "N/m^2", "bristle stiffness k_t per unit length",
                  lo=0, hi=1e12),
            Param("damping", None, float, "N s/m^2", "bristle damping d_t per unit length",
                  lo=0, hi=1e9)))
