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
in the kernel's variables x, and ``prm`` is the drive's contact vector
(:func:`contact_vector`): [k_p, c_p, the law's code, its parameters in the order of
:data:`PARAMS`]; a law reads its parameters from prm[3:].  v and gF are tuples: their
lengths are part of their types, so each kernel gets the law compiled for its sizes
(loops of known length), and the law is compiled into the kernel's own code (``inline="always"``): a
call per contact point costs measurable time.  The derivatives are those of the branch
the point is on (exact away from the switching surfaces).

:data:`LAWS` maps a name to a law; the kernels call :func:`force` and :func:`chain`,
which choose the law at run time by its code prm[2] (its index in :data:`ALL_PARAMS`, an
if-chain compiled into the kernels: one comparison per contact point), so one compiled
kernel runs every law.  :data:`LAW` names the thesis's law (belt2d, belt3d).  A new law
is one more pair of functions, one more row of :data:`LAWS` and :data:`PARAMS`, and one
more branch of :func:`force` and :func:`chain`; tests/belts/test_friction.py checks every
row's derivatives and that the dispatch reaches it.

A law with a state per contact point (:data:`STATE_LAWS`: the bristle law, a spring
whose deflection z is carried from step to step) takes z0 (the state at the last
converged step) and the step h, and gives the trial state z1; the planar kernel
(:mod:`ancf.belts.contact2d`) of a drive that carries a state calls every law through
:func:`state_force` and :func:`state_chain` (one that does not, compiled without the
state, calls :func:`force` and :func:`chain`: the stateless laws' code and cost), and the
march makes z1 the new z0 when a step converges
(:func:`ancf.solvers.alpha_march.system_accept`).
"""
from __future__ import annotations

import numpy as np
from numba import njit
from numba.extending import overload

from ancf.common.params import Param

#: branch codes of the creep-rate law (those of :func:`ancf.belts.contact3d.contact_state3d`)
#: and of the regularised Coulomb law (one smooth branch) and the bristle law (stick, slip)
LINEAR, SATURATED, SMOOTH, STICK, SLIP = 2, 3, 4, 5, 6


@njit(cache=True, inline="always")
def creep_rate_force(v, s, Fn, prm, f):
    """Tri-linear creep-rate law (Eq. 3.23, Fig. 3.3): f = -nu_s v while
    nu_s |v| <= mu F_n, else the Coulomb force -mu F_n v / |v| (mu = prm[3] -,
    nu_s = prm[4] kg/(m s) or kg/(m^2 s)).  Returns LINEAR or SATURATED."""
    mu, nu = prm[3], prm[4]
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
    mu, nu = prm[3], prm[4]
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


@njit(cache=True, inline="always")
def coulomb_force(v, s, Fn, prm, f):
    """Regularised Coulomb law: f = -mu F_n tanh(|v| / v_reg) v / |v| (mu = prm[3] -,
    v_reg = prm[4] m/s; f = 0 at v = 0), smooth, tending to -mu F_n v / |v| for
    |v| >> v_reg, with slope -mu F_n / v_reg through zero.  Returns SMOOTH."""
    mu, vr = prm[3], prm[4]
    g = mu * Fn * np.tanh(s / vr) / s if s > 0.0 else 0.0
    for i in range(len(v)):
        f[i] = -g * v[i]
    return SMOOTH


@njit(cache=True, inline="always")
def coulomb_chain(branch, v, s, Fn, prm, G, gF, D):
    """Derivatives of :func:`coulomb_force` chained through G, gF (see the module): with
    x = |v| / v_reg, u = v / |v|, h = tanh(x) / |v| and q = (x sech^2 x - tanh x) / |v|,
    df/dv = -mu F_n (h I + q u u^T), df/dF_n = -mu tanh(x) u; at v = 0,
    df/dv = -mu F_n / v_reg I, df/dF_n = 0."""
    mu, vr = prm[3], prm[4]
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
        ug = 0.0
        for j in range(n):
            ug += u[j] * G[j, c]
        for i in range(n):
            D[i, c] = -mu * (Fn * (h * G[i, c] + q * u[i] * ug) + th * u[i] * gF[c])


@njit(cache=True, inline="always")
def bristle_force(v, z0, h, Fn, prm, f, z1):
    """Bristle law (a tangential spring k_t = prm[4] and damper d_t = prm[5] between the
    belt and the pulley surface, capped by Coulomb, mu = prm[3]), one step of length h (s)
    from the bristle deflection z0 (n-tuple, m) of the last converged step, backward
    Euler: the trial deflection z0 + h v gives w = k_t z0 + (k_t h + d_t) v and the trial
    force -w; stick while |w| <= mu F_n (f = -w, z1 = z0 + h v), else slip
    (f = -mu F_n w / |w|, z1 = mu F_n w / (k_t |w|): the spring at the Coulomb limit).
    Fills f and the step's deflection z1 (n,), m; returns STICK or SLIP.  With k_t = 0
    it is the creep-rate law with nu_s = d_t (:func:`creep_rate_force`)."""
    mu, kt, dt = prm[3], prm[4], prm[5]
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
def bristle_chain(branch, v, z0, h, Fn, prm, G, gF, D):
    """Derivatives of :func:`bristle_force` by v and F_n chained through G, gF (z0 and h
    are the march's, fixed within a step): with c = k_t h + d_t, stick: df/dv = -c I,
    df/dF_n = 0; slip, with u = w / |w|: df/dv = -mu F_n c / |w| (I - u u^T),
    df/dF_n = -mu u."""
    mu, kt, dt = prm[3], prm[4], prm[5]
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


#: laws with a state per contact point, carried across steps (their force and chain take
#: the state z0 of the last converged step and the step h, and give the trial state z1;
#: :func:`state_force`, :func:`state_chain`): the 2D drive carries it per contact point
#: (:mod:`ancf.belts.contact2d`, accepted on converged steps, :mod:`ancf.belts.system`)
STATE_LAWS = {"bristle": (bristle_force, bristle_chain)}

#: their parameters, in the order of prm[3:]
STATE_PARAMS = {"bristle": (
    Param("mu", None, float, "-", "friction coefficient", lo=0, hi=10),
    Param("stiffness", None, float, "N/m^2", "bristle stiffness k_t per unit length", lo=0,
          hi=1e12),
    Param("damping", None, float, "N s/m^2", "bristle damping d_t per unit length", lo=0,
          hi=1e9))}

#: name -> (force, chain); a law's code in the kernels' prm is its index here
LAWS = {"creep-rate": (creep_rate_force, creep_rate_chain),
        "coulomb": (coulomb_force, coulomb_chain)}

#: each law's parameters as a drive file's [friction] table gives them (ranges checked
#: there), in the order of the law's entries of prm (prm[3], prm[4], ...)
PARAMS = {
    "creep-rate": (
        Param("mu", None, float, "-", "friction coefficient", lo=0, hi=10),
        Param("nu_s", None, float, "kg/(m s)", "creep-rate factor (Fig. 3.3)", lo=0,
              lo_open=True, hi=1e9)),
    "coulomb": (
        Param("mu", None, float, "-", "friction coefficient", lo=0, hi=10),
        Param("v_reg", None, float, "m/s", "regularisation speed (tanh(|v| / v_reg))", lo=0,
              lo_open=True, hi=1e3))}

#: the law of the thesis (belt2d, belt3d)
LAW = "creep-rate"

#: every law by name (the stateless ones first) with its parameters: what a drive file's
#: [friction] table may name
ALL_PARAMS = {**PARAMS, **STATE_PARAMS}

#: the kernels' code of each law (a float: prm is a float vector)
CODES = {name: float(i) for i, name in enumerate(ALL_PARAMS)}

#: length of prm: k_p, c_p, the law's code and the most parameters a law has
PRM_SIZE = 3 + max(len(p) for p in (*PARAMS.values(), *STATE_PARAMS.values()))


def contact_vector(k_p: float, c_p: float, law: str, *values) -> np.ndarray:
    """The kernels' prm: [k_p, c_p, code of ``law``, its ALL_PARAMS ``values`` in order, 0
    ...] (PRM_SIZE); ValueError naming the law unless it is a row of ALL_PARAMS given its
    values."""
    if law not in ALL_PARAMS or len(values) != len(ALL_PARAMS[law]):
        allowed = "; ".join(f"{k} ({', '.join(q.name for q in v)})"
                            for k, v in ALL_PARAMS.items())
        raise ValueError(f"friction law {law!r} with {len(values)} values; allowed: {allowed}")
    prm = np.zeros(PRM_SIZE)
    prm[:3] = k_p, c_p, CODES[law]
    prm[3:3 + len(values)] = values
    return prm


_CREEP_RATE, _BRISTLE = CODES["creep-rate"], CODES["bristle"]


def has_state(prm) -> bool:
    """Whether the law of the contact vector prm carries a state (a row of STATE_LAWS)."""
    return prm[2] == _BRISTLE


@overload(has_state, inline="always")
def _has_state(prm):
    return lambda prm: prm[2] == _BRISTLE


@njit(cache=True, inline="always")
def force(v, s, Fn, prm, f):
    """The force of the law whose code is prm[2] (a row of LAWS: every row is a branch
    here, tests/belts/test_friction.py; a law with a state is :func:`state_force`'s)."""
    if prm[2] == _CREEP_RATE:
        return creep_rate_force(v, s, Fn, prm, f)
    return coulomb_force(v, s, Fn, prm, f)


@njit(cache=True, inline="always")
def chain(branch, v, s, Fn, prm, G, gF, D):
    """The derivatives of the law whose code is prm[2] (as :func:`force`)."""
    if prm[2] == _CREEP_RATE:
        creep_rate_chain(branch, v, s, Fn, prm, G, gF, D)
    else:
        coulomb_chain(branch, v, s, Fn, prm, G, gF, D)


@njit(cache=True, inline="always")
def state_force(v, s, Fn, prm, f, z0, h, z1):
    """The force of any law (code prm[2]): a law with a state (STATE_LAWS) steps from z0
    (n-tuple, m) over h (s) and fills z1 (n,); a stateless one is :func:`force` and leaves
    z1 as it is."""
    if prm[2] == _BRISTLE:
        return bristle_force(v, z0, h, Fn, prm, f, z1)
    return force(v, s, Fn, prm, f)


@njit(cache=True, inline="always")
def state_chain(branch, v, s, Fn, prm, G, gF, D, z0, h):
    """The derivatives of any law (as :func:`state_force`; z0 and h fixed)."""
    if prm[2] == _BRISTLE:
        bristle_chain(branch, v, z0, h, Fn, prm, G, gF, D)
    else:
        chain(branch, v, s, Fn, prm, G, gF, D)
