"""Friction laws of the belt-pulley contact, compiled (numba): the friction force on the
belt from its sliding velocity over the pulley surface and the normal force, and the
law's exact derivatives; used by both contact kernels (:mod:`ancf.belts.contact2d`,
:mod:`ancf.belts.contact3d`), which supply the geometry (normal, tangent plane,
penetration, sliding velocity) and chain the derivatives through r, rdot and omega.

A law acts on the sliding velocity v (n-tuple) in the tangent plane, m/s: n = 1 for the
planar kernel (v = v_t along t, Eq. 3.25), n = 3 for the plate (v = v_s, the sliding
velocity with its normal part removed), its speed s = |v| (m/s) and the normal force
F_n > 0 (N/m in 2D, N/m^2 in 3D).  It is one :class:`~ancf.belts.friction.base.FrictionLaw`
in a module of its own in this package (found here by :func:`_load`), with a pair of
compiled functions:

    force(v, s, F_n, law, f) -> branch     f (n,) friction force, N/m or N/m^2
    chain(branch, v, s, F_n, law, G, gF, D)
        D[i, c] = sum_j df_i/dv_j G[j, c] + df_i/dF_n gF[c],   i < n, c < m

where ``branch`` is the law's own code for the piece it is on (the kernels report it),
G (n, m) = dv/dx and gF (m-tuple) = dF_n/dx are the derivatives of the law's arguments
in the kernel's variables x, and ``law`` is the drive's contact record
(:func:`contact_record`: a numba record of the fields of :data:`CONTACT`, k_p, c_p, the
law's code and every law's parameters by name; a law reads its own, ``law.mu``).  v and
gF are tuples: their lengths are part of their types, so each kernel gets the law
compiled for its sizes (loops of known length), and the law is compiled into the
kernel's own code (``inline="always"``): a call per contact point costs measurable time.
The derivatives are those of the branch the point is on (exact away from the switching
surfaces).

:data:`LAWS` maps a name to a law's pair; the kernels call :func:`force` and
:func:`chain`, which choose the law at run time by its code ``law.law`` (its index in
:data:`ALL_PARAMS`): an if-chain made from the registry (:func:`_pick`) and compiled into
the kernels, one comparison per law per contact point, so one compiled kernel runs every
law.  :data:`LAW` names the thesis's law (belt2d, belt3d).  A new law is one module of
this package making its FrictionLaw; tests/belts/test_friction.py checks every law's
derivatives and that the dispatch reaches it.

A law with a state per contact point (:data:`STATE_LAWS`: the bristle law, a spring
whose deflection z is carried from step to step) takes z0 (the state at the last
converged step) and the step h, and gives the trial state z1; the planar kernel
(:mod:`ancf.belts.contact2d`) calls every law through :func:`state_force` and
:func:`state_chain` (a stateless law through them is :func:`force` and :func:`chain`, its
z empty: one compiled march for every law), and the
march makes z1 the new z0 when a step converges
(:func:`ancf.solvers.alpha_march.system_accept`).
"""
from __future__ import annotations

import importlib
import pkgutil

import numpy as np
from numba import njit
from numba.extending import overload

from ancf.belts.friction.base import REGISTRY


def _load() -> list:
    """Every law of this package's modules, stateless ones first, each group by rank."""
    for mod in pkgutil.iter_modules(__path__):
        importlib.import_module(f"{__name__}.{mod.name}")
    return sorted(REGISTRY.values(), key=lambda law: (law.state, law.rank))


_ALL = _load()

# the branch codes tests and kernels name (each law's module declares its own)
from ancf.belts.friction.bristle import SLIP, STICK, bristle_chain, bristle_force  # noqa: E402
from ancf.belts.friction.coulomb import SMOOTH  # noqa: E402
from ancf.belts.friction.creep_rate import LINEAR, SATURATED  # noqa: E402

#: name -> (force, chain) of the stateless laws
LAWS = {law.name: (law.force, law.chain) for law in _ALL if not law.state}

#: laws with a state per contact point, carried across steps (their force and chain take
#: the state z0 of the last converged step and the step h, and give the trial state z1;
#: :func:`state_force`, :func:`state_chain`): the 2D drive carries it per contact point
#: (:mod:`ancf.belts.contact2d`, accepted on converged steps, :mod:`ancf.belts.system`)
STATE_LAWS = {law.name: (law.force, law.chain) for law in _ALL if law.state}

#: each stateless law's parameters as a drive file's [friction] table gives them (ranges
#: checked there), in the order contact_record takes their values
PARAMS = {law.name: law.params for law in _ALL if not law.state}

#: the parameters of the laws with a state
STATE_PARAMS = {law.name: law.params for law in _ALL if law.state}

#: the law of the thesis (belt2d, belt3d)
LAW = "creep-rate"

#: every law by name (the stateless ones first) with its parameters: what a drive file's
#: [friction] table may name
ALL_PARAMS = {**PARAMS, **STATE_PARAMS}

#: the kernels' code of each law (the record's field ``law``)
CODES = {name: i for i, name in enumerate(ALL_PARAMS)}

#: the contact record's fields: k_p (N/m^2, N/m^3 in 3D), c_p (N s/m^2, N s/m^3), the
#: law's code, then every law's parameters by name (a name shared by laws is one field)
CONTACT = np.dtype((np.record, [("k_p", "f8"), ("c_p", "f8"), ("law", "i8")] + [
    (name, "f8") for name in dict.fromkeys(p.name for ps in ALL_PARAMS.values() for p in ps)]))


def contact_record(k_p: float, c_p: float, law: str, *values) -> np.record:
    """The kernels' contact record (:data:`CONTACT`): k_p, c_p, the code of ``law`` and
    its ALL_PARAMS ``values`` in order under their names, every other field 0;
    ValueError naming the law unless it is a row of ALL_PARAMS given its values."""
    if law not in ALL_PARAMS or len(values) != len(ALL_PARAMS[law]):
        allowed = "; ".join(f"{k} ({', '.join(q.name for q in v)})"
                            for k, v in ALL_PARAMS.items())
        raise ValueError(f"friction law {law!r} with {len(values)} values; allowed: {allowed}")
    rec = np.zeros(1, CONTACT)[0]
    rec.k_p, rec.c_p, rec.law = k_p, c_p, CODES[law]
    for param, value in zip(ALL_PARAMS[law], values):
        rec[param.name] = value
    return rec


_FIRST_STATE = len(PARAMS)  # the laws with a state have the last codes


def has_state(law) -> bool:
    """Whether the law of the contact record ``law`` carries a state (a row of
    STATE_LAWS)."""
    return law.law >= _FIRST_STATE


@overload(has_state, inline="always")
def _has_state(law):
    return lambda law: law.law >= _FIRST_STATE


# ------------------------------------------------ the kernels' dispatch, made from the laws
def _pick(laws, tail):
    """The compiled force and chain that run the first of ``laws`` (FrictionLaw, all
    stateless or all with a state) whose code is ``law.law``, else ``tail`` (a pair of
    the stateless signature; None: the last law runs unconditionally)."""
    head, rest = laws[0], laws[1:]
    force, chain = head.force, head.chain
    if not rest and tail is None:
        return force, chain
    code = CODES[head.name]
    else_force, else_chain = _pick(rest, tail) if rest else tail
    if head.state:
        @njit(inline="always")
        def pick_force(v, s, Fn, law, f, z0, h, z1):
            if law.law == code:
                return force(v, z0, h, Fn, law, f, z1)
            return else_force(v, s, Fn, law, f, z0, h, z1)

        @njit(inline="always")
        def pick_chain(branch, v, s, Fn, law, G, gF, D, z0, h):
            if law.law == code:
                chain(branch, v, z0, h, Fn, law, G, gF, D)
            else:
                else_chain(branch, v, s, Fn, law, G, gF, D, z0, h)
        return pick_force, pick_chain

    @njit(inline="always")
    def pick_force(v, s, Fn, law, f):
        if law.law == code:
            return force(v, s, Fn, law, f)
        return else_force(v, s, Fn, law, f)

    @njit(inline="always")
    def pick_chain(branch, v, s, Fn, law, G, gF, D):
        if law.law == code:
            chain(branch, v, s, Fn, law, G, gF, D)
        else:
            else_chain(branch, v, s, Fn, law, G, gF, D)
    return pick_force, pick_chain


@njit(inline="always")
def _stateless_force(v, s, Fn, law, f, z0, h, z1):
    """A stateless law's force in the signature of a law with a state (z1 left as it is)."""
    return force(v, s, Fn, law, f)


@njit(inline="always")
def _stateless_chain(branch, v, s, Fn, law, G, gF, D, z0, h):
    chain(branch, v, s, Fn, law, G, gF, D)


#: force(v, s, F_n, law, f) -> branch and chain(branch, v, s, F_n, law, G, gF, D) of the
#: stateless law whose code is law.law (every row of LAWS is a branch: test_friction.py)
force, chain = _pick([law for law in _ALL if not law.state], None)

#: state_force(v, s, F_n, law, f, z0, h, z1) -> branch and
#: state_chain(branch, v, s, F_n, law, G, gF, D, z0, h) of any law: one with a state steps
#: from z0 (n-tuple, m) over h (s) and fills z1 (n,); a stateless one is force and chain
state_force, state_chain = _pick([law for law in _ALL if law.state],
                                 (_stateless_force, _stateless_chain))
