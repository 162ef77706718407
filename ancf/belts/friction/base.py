"""The contract of a friction law (:class:`FrictionLaw`), its registry, and the helper
the laws share.

A law is one :class:`FrictionLaw` made in its own module of this package (found and
imported by :mod:`ancf.belts.friction`): its name, its parameters (a drive file's
[friction] keys, units, ranges: :class:`ancf.common.params.Param`), its compiled pair
``force`` and ``chain`` (signatures in :mod:`ancf.belts.friction`) and whether it carries
a state per contact point.  The kernels read the parameters by name from the contact
record (``law.mu``, ``law.nu_s``, ...: :func:`ancf.belts.friction.contact_record`),
whose fields are the parameter names of every registered law.
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Callable

from numba import njit
from numba.extending import overload

from ancf.common.params import Param

#: every law made, by name (:class:`FrictionLaw` registers itself)
REGISTRY: dict = {}


@dataclass(frozen=True, kw_only=True)
class FrictionLaw:
    """One friction law: ``force``/``chain`` compiled (``inline="always"``), ``params``
    its parameters in the order a drive file's values come in, ``state`` whether it
    carries a state z per contact point (then force(v, z0, h, F_n, law, f, z1) and
    chain(branch, v, z0, h, F_n, law, G, gF, D)), ``rank`` its place among the laws (the
    order drive-file messages list them in, stateless laws before those with a state)."""

    name: str
    params: tuple[Param, ...]
    force: Callable
    chain: Callable
    rank: int
    state: bool = False

    def __post_init__(self):
        if self.name in REGISTRY:
            raise ValueError(f"friction law {self.name!r} made twice")
        REGISTRY[self.name] = self


@njit(cache=True, inline="always")
def along(u, G, c):
    """sum_j u_j G[j, c]: the rate of |v| along the direction u = v / |v| (a tuple) per unit
    of the chained coordinate c (G = dv/dcoordinates); the saturated laws' u u^T part."""
    ug = 0.0
    for j in range(len(u)):
        ug += u[j] * G[j, c]
    return ug


def direction(v, s):
    """v / s as a tuple of v's length (compiled callers only)."""
    raise NotImplementedError("resolved at compile time by the length of v")


@overload(direction, inline="always")
def _direction(v, s):
    return {1: lambda v, s: (v[0] / s,),
            2: lambda v, s: (v[0] / s, v[1] / s),
            3: lambda v, s: (v[0] / s, v[1] / s, v[2] / s)}.get(v.count)
