"""Constraints by Lagrange multipliers: the augmented form of thesis Eq. 2.32.

    [ M   C_e^T ] [ e'' ]   [ Q   ]
    [ C_e   0   ] [ lam ] = [ Q_d ],   Q_d = -C_tt - (C_e e')_e e' - 2 C_et e'

(the thesis prints ``-C_t``; the second time derivative of C(e, t) = 0 gives
``C_tt``, as the 2003 report's Eq. 24 has it).  A constraint object exposes
``value(q, t)`` (C), ``jacobian(q, t)`` (C_e, sparse), ``time_derivative(q, t)``
(C_t) and ``qd(q, v, t)`` (Q_d).  :class:`LinearConstraints` (``B q = c(t)``) is
the one used now; a nonlinear constraint only needs these four methods (and sets
``constant_jacobian = False``).

Drift control: the index-1 form (used with scipy's integrators) replaces Q_d by
the Baumgarte-stabilised ``Q_d - 2 alpha C' - beta^2 C``
(:class:`Baumgarte`); the generalised-alpha scheme enforces ``C(q, t) = 0``
itself at every step (index-3 form), so it has no position drift.
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Callable

import numpy as np
import scipy.sparse as sp


@dataclass
class LinearConstraints:
    """C(q, t) = B q - c(t) with ``c(t) -> (c, c', c'')``."""

    B: sp.csr_matrix
    c: Callable[[float], tuple]
    constant_jacobian: bool = True

    @classmethod
    def from_elimination(cls, elimination) -> "LinearConstraints":
        """The fixed, tied and prescribed coordinates of an :class:`ancf.core.constraints.Elimination`."""
        B, c = elimination.rows()
        return cls(B, c)

    @property
    def m(self) -> int:
        return self.B.shape[0]

    def value(self, q, t) -> np.ndarray:
        return self.B @ q - self.c(t)[0]

    def jacobian(self, q, t) -> sp.csr_matrix:
        return self.B

    def time_derivative(self, q, t) -> np.ndarray:
        """C_t = -c'(t)."""
        return -self.c(t)[1]

    def qd(self, q, v, t) -> np.ndarray:
        """Q_d = -C_tt = c''(t) ((C_e e')_e = 0 and C_et = 0 for constant B)."""
        return self.c(t)[2]


@dataclass(frozen=True)
class Baumgarte:
    """Q_d -> Q_d - 2 alpha (C_e e' + C_t) - beta^2 C (alpha, beta in 1/s;
    alpha = beta is the critically damped choice, 0 switches it off)."""

    alpha: float = 20.0
    beta: float = 20.0

    def qd(self, con, q, v, t) -> np.ndarray:
        out = con.qd(q, v, t)
        if self.alpha:
            out = out - 2.0 * self.alpha * (con.jacobian(q, t) @ v + con.time_derivative(q, t))
        if self.beta:
            out = out - self.beta ** 2 * con.value(q, t)
        return out

    def qd_jacobians(self, con, q, t):
        """d(stabilised Q_d)/dq and d/dv for linear constraints (sparse, m x n)."""
        B = con.jacobian(q, t)
        return -self.beta ** 2 * B, -2.0 * self.alpha * B
