"""Friction laws of the belt-pulley contact, compiled (numba): the friction force on the
belt from its sliding velocity over the pulley surface and the normal force, and the
law's exact derivatives; used by both contact kernels (:mod:`ancf.belts.contact2d`,
:mod:`ancf.belts.contact3d`), which supply the geometry (normal, tangent plane,
penetration, sliding velocity) and chain the derivatives through r, rdot and omega.

A law acts on the sliding velocity v (n-tuple) in the tangent plane, m/s: n = 1 for the
planar kernel (v = v_t along t, Eq. 3.25), n = 3 for the plate (v = v_s, the sliding
velocity with its normal part removed), its speed s = |v| (m/s) and the normal force
F_n > 0 (N/m in 2D, N/m^2 in 3D).  It is a pair of compiled functions:

    force(v, s, F_n, prm, f) -> branch     f (n,) friction force, N/m or N/m^2
    chain(branch, v, s, F_n, prm, G, gF, D)
        D[i, c] = sum_j df_i/dv_j G[j, c] + df_i/dF_n gF[c],   i < n, c < m

where ``branch`` is the law's own code for the piece it is on (the kernels report it),
G (n, m) = dv/dx and gF (m-tuple) = dF_n/dx are the derivatives of the law's arguments
in the kernel's variables x, and ``prm`` = [k_p, c_p, mu, nu_s] is the drive's contact
vector (a law reads what it needs from it).  v and gF are tuples: their lengths are part
of their types, so each kernel gets the law compiled for its sizes (loops of known
length), and the law is compiled into the kernel's own code (``inline="always"``): a
call per contact point costs measurable time.  The derivatives are those of the branch
the point is on (exact away from the switching surfaces).

:data:`LAWS` maps a name to a law; :data:`LAW` names the one the kernels are compiled
with, :func:`force` and :func:`chain` are its functions (numba binds them when it
compiles the kernels).  A new law is one more pair of functions and one more row of
:data:`LAWS` (and :data:`LAW`, to compile the kernels with it); tests/test_friction.py
checks every row's derivatives.
"""
from __future__ import annotations

import numpy as np
from numba import njit
from numba.extending import overload

from ancf.common.params import Param

#: branch codes of the creep-rate law (those of :func:`ancf.belts.contact3d.contact_state3d`)
LINEAR, SATURATED = 2, 3


@njit(cache=True, inline="always")
def creep_rate_force(v, s, Fn, prm, f):
    """Tri-linear creep-rate law (Eq. 3.23, Fig. 3.3): f = -nu_s v while
    nu_s |v| <= mu F_n, else the Coulomb force -mu F_n v / |v| (mu = prm[2] -,
    nu_s = prm[3] kg/(m s) or kg/(m^2 s)).  Returns LINEAR or SATURATED."""
    mu, nu = prm[2], prm[3]
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
def creep_rate_chain(branch, v, s, Fn, prm, G, gF, D):
    """Derivatives of :func:`creep_rate_force` chained through G, gF (see the module):
    linear, df/dv = -nu_s I, df/dF_n = 0; saturated, with u = v / s and g = mu F_n / s,
    df/dv = -g (I - u u^T), df/dF_n = -mu u."""
    mu, nu = prm[2], prm[3]
    n, m = len(v), len(gF)
    if branch == LINEAR:
        for i in range(n):
            for c in range(m):
                D[i, c] = -nu * G[i, c]
        return
    g = mu * Fn / s
    u = direction(v, s)
    for c in range(m):
        ug = 0.0
        for j in range(n):
            ug += u[j] * G[j, c]
        for i in range(n):
            D[i, c] = -mu * u[i] * gF[c] - g * (G[i, c] - u[i] * ug)


def direction(v, s):
    """v / s as a tuple of v's length (compiled callers only)."""
    raise NotImplementedError("resolved at compile time by the length of v")


@overload(direction, inline="always")
def _direction(v, s):
    return {1: lambda v, s: (v[0] / s,),
            2: lambda v, s: (v[0] / s, v[1] / s),
            3: lambda v, s: (v[0] / s, v[1] / s, v[2] / s)}.get(v.count)


#: name -> (force, chain)
LAWS = {"creep-rate": (creep_rate_force, creep_rate_chain)}

#: each law's parameters as a drive file's [friction] table gives them (ranges checked there)
PARAMS = {"creep-rate": (
    Param("mu", None, float, "-", "friction coefficient", lo=0, hi=10),
    Param("nu_s", None, float, "kg/(m s)", "creep-rate factor (Fig. 3.3)", lo=0, lo_open=True,
          hi=1e9))}

#: the law the contact kernels are compiled with
LAW = "creep-rate"

force, chain = LAWS[LAW]
