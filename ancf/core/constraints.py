"""Linear constraints by elimination: q = T z + g (static) or q = T z + g(t) (dynamic).

Fixed coordinates (clamp, pin, roller), ties (q_i = q_j, e.g. a closed loop) and
prescribed rheonomic coordinates (q_i = f(t), e.g. a driven hub slope) are
eliminated; z are the independent coordinates.  :meth:`Elimination.build` gives
the static ``(T, g, free)`` (prescribed coordinates at t = 0), :meth:`Elimination.selection`
the same with ``T`` as a :class:`Selection` (no scipy: the static solver's numbering needs
no more, and ``ancf run`` of a static scene then loads no scipy.sparse);
:meth:`Elimination.rheonomic` gives ``T`` with the time functions ``g(t)``,
``g'(t)``, ``g''(t)`` for the equations of motion.  The same constraint set can
be handed to the Lagrange-multiplier form (``ancf.core.multipliers``) as
``B q = c(t)`` rows, see :meth:`Elimination.rows`.
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING, Callable, NamedTuple

import numpy as np

if TYPE_CHECKING:
    import scipy.sparse as sp

#: motion(t) -> (value, velocity, acceleration), each an array of len(dofs)
Motion = Callable[[float], tuple]


class Selection(NamedTuple):
    """The 0/1 selection matrix ``T`` (shape (n_dofs, n_free)) of an elimination as the
    column of each global coordinate (-1: none, a fixed or prescribed coordinate)."""

    column: np.ndarray
    shape: tuple

    def tocsr(self) -> "sp.csr_matrix":
        import scipy.sparse as sp
        rows = np.flatnonzero(self.column >= 0)
        return sp.csr_matrix((np.ones(rows.size), (rows, self.column[rows])), shape=self.shape)


class Elimination:
    def __init__(self, n_dofs: int):
        self.n_dofs = n_dofs
        self.fixed: dict[int, float] = {}
        self.ties: dict[int, int] = {}
        self.motions: list[tuple[np.ndarray, Motion]] = []

    def fix(self, dofs, values) -> "Elimination":
        """Prescribe coordinates ``dofs`` to ``values``."""
        for d, v in zip(np.atleast_1d(dofs), np.broadcast_to(values, np.shape(np.atleast_1d(dofs)))):
            self.fixed[int(d)] = float(v)
        return self

    def tie(self, slave: int, master: int) -> "Elimination":
        """Require q[slave] = q[master]."""
        self.ties[int(slave)] = int(master)
        return self

    def prescribe(self, dofs, motion: Motion) -> "Elimination":
        """Rheonomic coordinates: ``q[dofs] = motion(t)[0]``; ``motion(t)`` returns
        (value, velocity, acceleration) arrays of ``len(dofs)``."""
        dofs = np.atleast_1d(np.asarray(dofs, dtype=int))
        overlap = set(dofs.tolist()) & (set(self.fixed) | set(self.ties) | set(self._prescribed()))
        if overlap:
            raise ValueError(f"coordinates {sorted(overlap)} are already constrained")
        self.motions.append((dofs, motion))
        return self

    def _prescribed(self) -> list[int]:
        return [int(d) for dofs, _ in self.motions for d in dofs]

    def _master(self, m: int) -> int:
        while m in self.ties:
            m = self.ties[m]
        return m

    def build(self):
        """(T, g, free): q = T @ z + g with T sparse (n_dofs, n_free); prescribed
        coordinates take their value at t = 0."""
        T, g, free = self.selection()
        return T.tocsr(), g, free

    def selection(self):
        """(T, g, free) of :meth:`build` with T as a :class:`Selection`."""
        T, g0, free, follow = self._structure()
        g = g0.copy()
        for dofs, motion in self.motions:
            g[dofs] = np.asarray(motion(0.0)[0], dtype=float)
        for s, m in follow.items():
            g[s] = g[m]
        return T, g, free

    def _structure(self):
        """T (a :class:`Selection`), constant part of g, free list, and {slave: prescribed
        master}."""
        prescribed = set(self._prescribed())
        dependent = set(self.fixed) | set(self.ties) | prescribed
        free = np.array([i for i in range(self.n_dofs) if i not in dependent], dtype=int)
        column = np.full(self.n_dofs, -1, dtype=np.int64)
        column[free] = np.arange(free.size)
        follow = {}
        for s, m in self.ties.items():
            m = self._master(m)
            if m in self.fixed:
                self.fixed[s] = self.fixed[m]
                continue
            if m in prescribed:
                follow[s] = m
                continue
            column[s] = column[m]
        T = Selection(column, (self.n_dofs, free.size))
        g = np.zeros(self.n_dofs)
        for d, v in self.fixed.items():
            g[d] = v
        return T, g, free, follow

    def rheonomic(self) -> "Rheonomic":
        """The time-dependent elimination q = T z + g(t) (see :class:`Rheonomic`)."""
        T, g0, _, follow = self._structure()
        return Rheonomic(T.tocsr(), g0, list(self.motions), follow)

    def rows(self):
        """The same constraints as rows ``B q = c(t)``: (B sparse (m, n_dofs), c) with
        ``c(t) -> (c, c', c'')``.  One row per fixed, tied and prescribed coordinate."""
        fixed = sorted(self.fixed)
        ties = sorted(self.ties.items())
        presc = [(dofs, motion) for dofs, motion in self.motions]
        r, cidx, val = [], [], []
        for i, d in enumerate(fixed):
            r.append(i), cidx.append(d), val.append(1.0)
        k = len(fixed)
        for i, (s, m) in enumerate(ties):
            r += [k + i, k + i]
            cidx += [s, m]
            val += [1.0, -1.0]
        k += len(ties)
        start = k
        for dofs, _ in presc:
            for d in dofs:
                r.append(k), cidx.append(int(d)), val.append(1.0)
                k += 1
        import scipy.sparse as sp
        B = sp.csr_matrix((val, (r, cidx)), shape=(k, self.n_dofs))
        c_static = np.zeros(k)
        c_static[:len(fixed)] = [self.fixed[d] for d in fixed]

        def c(t):
            c0, c1, c2 = c_static.copy(), np.zeros(k), np.zeros(k)
            j = start
            for dofs, motion in presc:
                v, vd, vdd = motion(t)
                c0[j:j + dofs.size], c1[j:j + dofs.size], c2[j:j + dofs.size] = v, vd, vdd
                j += dofs.size
            return c0, c1, c2
        return B, c


@dataclass
class Rheonomic:
    """q = T z + g(t), q' = T z' + g'(t), q'' = T z'' + g''(t)."""

    T: sp.csr_matrix
    g0: np.ndarray
    motions: list
    follow: dict

    @property
    def time_dependent(self) -> bool:
        return bool(self.motions)

    def g(self, t: float, order: int = 0) -> np.ndarray:
        """d^order g / dt^order at t (order 0, 1, 2)."""
        out = self.g0.copy() if order == 0 else np.zeros_like(self.g0)
        for dofs, motion in self.motions:
            out[dofs] = np.asarray(motion(t)[order], dtype=float)
        for s, m in self.follow.items():
            out[s] = out[m]
        return out
