"""The elimination form as a system of the compiled generalised-alpha march
(:mod:`ancf.solvers.alpha_march`).

Applies to a :class:`~ancf.solvers.dynamics.ReducedModel` with one compiled element
group (:meth:`ancf.core.pattern.ReducedPattern.compiled`) and constant external forces
(gravity), fixed, tied and prescribed (rheonomic) coordinates: the pendulum and the
spinning beam.  Unknowns: the independent coordinates z in the pattern's numbering
(``ReducedPattern.order``); residual and iteration matrix

    r = M_r z'' - Q_r + T^T dU/dq + T^T M g'',     S = M_r + beta' K_r

(K_r = T^T d2U/dq2 T, band storage, factored with pivoting).  Prescribed coordinates
take their value at each step end from the table ``gvals``, their accelerations enter
as ``Mp @ gdd``.  Plain Newton increments; converged when beta' |d|_inf <= tol (1 +
|z|_inf) at the last evaluation (the test of :mod:`ancf.solvers.generalized_alpha`).
A step the march cannot take goes to the Python stepper, which halves it.
"""
from __future__ import annotations

from typing import NamedTuple

import numpy as np

from ancf.common.dispatch import implements
from ancf.core.pattern import assemble_group
from ancf.solvers import banded
from ancf.solvers.alpha_march import (system_accept, system_factor, system_prepare,
                                      system_residual, system_solve, system_tests)


class ReducedSystem(NamedTuple):
    """Arrays of the elimination form (pattern numbering, SI units), with work storage."""

    group: tuple         # the compiled element group
    Mb: np.ndarray       # M_r, band storage, kg
    kl: int              # half-bandwidth
    Qr: np.ndarray       # T^T Q, constant loads, N
    Mp: np.ndarray       # T^T M columns of the prescribed coordinates, kg
    gdd: np.ndarray      # their accelerations at the step times (nts, npresc), m/s^2
    presc: np.ndarray    # the prescribed coordinates (global numbering)
    gvals: np.ndarray    # their values at the step times (nts, npresc), m
    g0: np.ndarray       # g of q = T z + g at t = 0
    gq: np.ndarray       # work: g at the step end
    inertial: np.ndarray  # work: Mp @ gdd at the step end, N
    grad: np.ndarray     # work: T^T dU/dq at the last evaluation, N
    K: np.ndarray        # work: K_r at the last evaluation with want_J, N/m
    S: np.ndarray        # work: the iteration matrix, then its band LU
    piv: np.ndarray      # work: its pivots


@implements(system_prepare, ReducedSystem)
def _prepare(system, k):
    system.gq[:] = system.g0
    for j in range(system.presc.size):
        system.gq[system.presc[j]] = system.gvals[k, j]
    if system.presc.size:
        system.inertial[:] = system.Mp @ system.gdd[k]


@implements(system_residual, ReducedSystem)
def _residual(system, x1, v1, acc1, k, bp, gp, want_J, count, r):
    assemble_group(system.group, x1, system.gq, want_J, system.grad, system.K)
    r[:] = banded.matvec(system.Mb, system.kl, acc1) - system.Qr + system.grad + system.inertial


@implements(system_factor, ReducedSystem)
def _factor(system, bp, pivoting):
    """S = M_r + beta' K_r, always pivoted."""
    system.S[:, :] = system.Mb + bp * system.K
    return banded.lu(system.S, system.kl, system.piv, bool(True)) == 0  # not a literal: one lu


@implements(system_solve, ReducedSystem)
def _solve(system, d):
    banded.solve(system.S, system.kl, system.piv, d)


@implements(system_accept, ReducedSystem)
def _accept(system, slot):
    """No state beside the march's."""


@implements(system_tests, ReducedSystem)
def _tests(system):
    """All coordinates, scaled at the last evaluation, plain Newton, no velocities (the
    elimination form's forces depend on positions only)."""
    return system.Mb.shape[0], False, False, False


class CompiledAlpha:
    """The system, coefficients and counters of the compiled march for one model;
    :meth:`applies` says whether the model can use it."""

    def __init__(self, model, opt, ts):
        asm, rheo, p = model.assembly, model.rheo, model.pattern
        presc = np.array(sorted({int(d) for dofs, _ in rheo.motions for d in dofs} | set(rheo.follow)),
                         dtype=np.int64)
        gvals = np.array([rheo.g(t)[presc] for t in ts]) if presc.size else np.zeros((ts.size, 0))
        gdd = np.array([rheo.g(t, 2)[presc] for t in ts]) if presc.size else np.zeros((ts.size, 0))
        Mcols = model.M_full[:, presc].toarray() if presc.size else np.zeros((asm.n_dofs, 0))
        Mp = np.zeros((p.n, presc.size))
        np.add.at(Mp, p.zsel, Mcols[p.qsel])
        Q = model.forces.value(rheo.g0, np.zeros(asm.n_dofs), 0.0)
        g0 = np.array(rheo.g0, dtype=float)
        self.system = ReducedSystem(group=p.compiled(asm), Mb=model.Mb, kl=p.kl, Qr=p.reduce(Q),
                                    Mp=Mp, gdd=gdd, presc=presc, gvals=gvals, g0=g0,
                                    gq=g0.copy(), inertial=np.zeros(p.n), grad=np.zeros(p.n),
                                    K=p.zeros_matrix(), S=p.zeros_matrix(),
                                    piv=np.zeros(p.n, dtype=np.int64))
        self.hf = np.array([np.nan])
        self.cf = np.array(opt.coefficients())
        self.count = np.zeros(5, dtype=np.int64)

    @staticmethod
    def applies(model) -> bool:
        from ancf.core.forces import Gravity
        p = getattr(model, "pattern", None)
        return (getattr(model, "form", "") == "elimination" and p is not None and p.band
                and p.compiled(model.assembly) is not None
                and all(isinstance(t, Gravity) for t in model.forces.terms))
