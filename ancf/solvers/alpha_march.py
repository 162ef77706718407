"""The compiled march of the generalised-alpha scheme, shared by every system that
has one (the elimination form of beams, :mod:`ancf.solvers.alpha_compiled`; the belt
drives, :mod:`ancf.belts.system`).

Recurrence of :mod:`ancf.solvers.generalized_alpha` (Arnold & Brüls 2007): the unknown
of a step t_n -> t_{n+1} = t_n + h is the acceleration acc1 = q''_{n+1}, and

    a1 = ((1 - alpha_f) acc1 + alpha_f q''_n - alpha_m a_n) / (1 - alpha_m)
    q_{n+1} = q_n + h q'_n + h^2 ((1/2 - beta) a_n + beta a1)
    q'_{n+1} = q'_n + h ((1 - gamma) a_n + gamma a1)

with beta' = h^2 beta (1 - alpha_f) / (1 - alpha_m), gamma' = h gamma (1 - alpha_f) /
(1 - alpha_m) the derivatives of q_{n+1}, q'_{n+1} by acc1.  Modified Newton on the
residual r(acc1) = M acc1 + f(q_{n+1}, q'_{n+1}, t_{n+1}):

* the iteration matrix and its factors are kept across iterations and steps; they are
  refreshed (new matrix, new factors) when there are none, the step size changed, an
  increment fails to contract (|d_k| > refresh_ratio |d_{k-1}|, :data:`REFRESH_RATIO`
  unless the settings say otherwise) or was damped; with ``refresh`` ``once``
  (:data:`REFRESH`) an increment that contracts too slowly refreshes them only if they
  were not refreshed within the step yet (a growing or a damped one always does): where
  contact states switch within a step, a second fresh matrix contracts little better;
* converged when beta' |d|_inf <= tol (1 + |q|_inf) over the system's first m
  coordinates, q at the step's start or at the last full evaluation as the system
  says, and beta' lam |d_i| <= tol for the others (a position increment);
* the converged step's state (``accept``, :data:`ACCEPT`): ``applied``, the iterate
  the last increment leads to (where a damped system has just evaluated its residual to
  damp it), or ``evaluated`` (damped systems only): the last evaluated iterate, once the
  increment from it is below the tolerance, without applying it.  ``evaluated`` saves
  one residual evaluation per step (the one at the end of the last increment); the two
  differ by that increment, within the tolerance;
* a step that fails with kept factors is retried once with fresh ones (pivoted); one
  that fails with fresh factors ends the march with NEWTON_FAILED, the state at the
  step's start and no factors, and the caller takes it with smaller steps.  With
  ``give_up`` = g > 0 (:func:`newton_settings`; 0, never, the default) a step gives up
  sooner: at its g-th damped increment if |r| is still above half its value after the
  first (a contact point switching back and forth across a jump of its force, a cycle
  no damping breaks at this step size: the 2D belt's entry damping c_p d'), and
  without the pivoted retry once it had refactored unpivoted and still failed;
* the march also ends on the step budget (BUDGET), non-finite coordinates
  (NON_FINITE) or coordinates above ``limit`` (BLOW_UP), and stores the states after
  the steps it is asked to keep (``slot``).

What belongs to the system (the record ``system``, a NamedTuple whose class chooses
the implementations at compile time, :mod:`ancf.common.dispatch`): the step's
prescribed data (:func:`system_prepare`), residual and iteration matrix
(:func:`system_residual`), factorisation (:func:`system_factor`) and solve
(:func:`system_solve`), what it keeps from a converged step (:func:`system_accept`: a
state of its own beside the march's, such as a friction law's per contact point; the
trial state of the step's last residual, which is at the accepted iterate: a damped
Newton step evaluates where its increment ends, and once more where backtracking ran out), and (:func:`system_tests`) the coordinates the blow-up and
convergence tests look at, the positions the convergence test scales by and whether
an increment is damped by backtracking (halved at most MAX_BACKTRACKS times until |r|
decreases by the Armijo factor 1 - 1e-4 lam; this breaks the 2-cycles of belt points
switching between sticking, sliding and no contact).

Counters ``count``: 0 residual evaluations, 1 iteration matrices, 2 factorisations,
3 solves (= Newton iterations), 4 steps; entries past 4 belong to the system.
``st`` = (q, q', q'', a) is updated in place; ``hf`` (1,) holds the step size (s) the kept
factors belong to (nan: none); ``newton`` is :func:`newton_settings`'s vector.
"""
from __future__ import annotations

import numpy as np
from numba import njit

from ancf.common.dispatch import as_struct
from ancf.common.leaf import leaf

DONE, NEWTON_FAILED, NON_FINITE, BLOW_UP, BUDGET = 0, 1, 2, 3, 4
#: contraction ratio above which the kept iteration matrix is refreshed (the default)
REFRESH_RATIO = 0.5
MAX_BACKTRACKS = 8  # trial lengths 1, 1/2, ... 1/128 of a Newton increment
CONVERGED, FAILED, GIVEN_UP = 0, 1, 2  # a step's outcome (_step)
#: the state a converged step takes (module docstring), the first the default
ACCEPT = ("applied", "evaluated")
#: when an increment that contracts too slowly refreshes the kept matrix (module
#: docstring): always, or once per step; the first the default
REFRESH = ("contraction", "once")


def newton_settings(tol: float, refresh_ratio: float = REFRESH_RATIO,
                    accept: str = ACCEPT[0], refresh: str = REFRESH[0],
                    give_up: int = 0) -> np.ndarray:
    """The march's Newton settings [tol, refresh_ratio, accept's index in ACCEPT,
    refresh's index in REFRESH, give_up] (module docstring); ValueError naming a setting
    out of its range."""
    if not 0.0 < refresh_ratio < 1.0:
        raise ValueError(f"refresh_ratio must be in (0, 1) (got {refresh_ratio!r})")
    if not 0 <= give_up <= 12:
        raise ValueError(f"give_up must be in [0, 12] (got {give_up!r})")
    for name, value, allowed in (("accept", accept, ACCEPT), ("refresh", refresh, REFRESH)):
        if value not in allowed:
            raise ValueError(f"{name} must be one of {', '.join(allowed)} (got {value!r})")
    return np.array([tol, refresh_ratio, float(ACCEPT.index(accept)),
                     float(REFRESH.index(refresh)), float(give_up)])


def system_prepare(system, k):
    """Set the system's data of the step ending at step time index k."""
    raise NotImplementedError("resolved at compile time by the type of system")


def system_residual(system, x1, v1, acc1, k, bp, gp, want_J, count, r):
    """r = residual at (x1, v1, acc1) and step time index k; if want_J, the force part
    of the iteration matrix (beta' bp, gamma' gp) into the system's storage."""
    raise NotImplementedError("resolved at compile time by the type of system")


def system_factor(system, bp, pivoting) -> bool:
    """Factor the iteration matrix (pivoting asked for fresh factors); False if singular."""
    raise NotImplementedError("resolved at compile time by the type of system")


def system_solve(system, d):
    """d = S^-1 d in place with the kept factors."""
    raise NotImplementedError("resolved at compile time by the type of system")


def system_accept(system, slot):
    """The step just taken converged (its state is the march's): make the system's trial
    state its state (a friction law's, :mod:`ancf.belts.system`; nothing for most
    systems) and keep it in output slot ``slot`` (-1: none)."""
    raise NotImplementedError("resolved at compile time by the type of system")


def system_tests(system):
    """(m, from_start, damped, moving): the blow-up and convergence tests look at the
    first m coordinates; the convergence test scales by the positions at the step's start
    (from_start) or at the last full evaluation; Newton increments are damped; the
    residual depends on the velocities (else they are not formed during the iteration)."""
    raise NotImplementedError("resolved at compile time by the type of system")


@leaf
def _trial(acc1, st, h, cf, moving, x1, v1, a1):
    """x1, v1, a1 = (q_{n+1}, q'_{n+1}, a_{n+1}) of the recurrence for the acceleration
    acc1, in place (without ``moving``, v1 is left as it is: a residual that does not
    read it)."""
    x, v, acc, a = st
    am, af, gamma, beta = cf
    for i in range(x.size):
        a1[i] = ((1 - af) * acc1[i] + af * acc[i] - am * a[i]) / (1 - am)
        x1[i] = x[i] + h * v[i] + h * h * ((0.5 - beta) * a[i] + beta * a1[i])
        if moving:
            v1[i] = v[i] + h * ((1 - gamma) * a[i] + gamma * a1[i])


@njit(cache=True)
def kinematics(acc1, st, h, cf):
    """(q_{n+1}, q'_{n+1}, a_{n+1}) of the recurrence for the acceleration acc1."""
    x1, v1, a1 = np.empty(acc1.size), np.empty(acc1.size), np.empty(acc1.size)
    _trial(acc1, st, h, cf, True, x1, v1, a1)
    return x1, v1, a1


@njit(cache=True, inline="always")
def _evaluate(system, acc1, st, h, k, cf, bp, gp, want_J, count, r, moving, x1, v1, a1):
    """Residual at acc1 into r (and the iteration matrix if want_J); q_{n+1}, q'_{n+1}
    and a_{n+1} into x1, v1, a1."""
    _trial(acc1, st, h, cf, moving, x1, v1, a1)
    system_residual(system, x1, v1, acc1, k, bp, gp, want_J, count, r)
    count[0] += 1


@njit(cache=True)
def _backtrack(system, acc1, d, st, h, k, cf, bp, gp, count, r, rt, moving, x1, v1, a1):
    """Length lam of the damped increment; rt = residual at the last trial."""
    rn, lam = np.sqrt(np.dot(r, r)), 1.0
    for _ in range(MAX_BACKTRACKS):
        _evaluate(system, acc1 + lam * d, st, h, k, cf, bp, gp, False, count, rt, moving, x1, v1, a1)
        if np.sqrt(np.dot(rt, rt)) <= (1 - 1e-4 * lam) * rn:
            break
        lam *= 0.5
    return lam


@njit(cache=True)
def _converged(bp, dn, lam, d, xs, m, tol):
    """beta' dn <= tol (1 + |xs[:m]|_inf) and beta' lam |d_i| <= tol for i >= m."""
    ok = bp * dn <= tol * (1 + np.max(np.abs(xs[:m])))
    for i in range(m, d.size):
        ok = ok and bp * lam * abs(d[i]) <= tol
    return ok


@njit(cache=True)
def _take(acc1, st, h, cf, x1, v1, a1):
    """The step's state from its accepted acceleration acc1 (x1, v1, a1: work)."""
    _trial(acc1, st, h, cf, True, x1, v1, a1)
    x, v, acc, a = st
    x[:] = x1
    v[:] = v1
    acc[:] = acc1
    a[:] = a1


@njit(cache=True)
def _step(h, k, st, system, hf, cf, count, newton, max_iter, fresh):
    """One step of size h ending at step time index k: CONVERGED, FAILED, or GIVEN_UP (a
    failure that fresh factors would repeat: ``give_up``, module docstring)."""
    x, v, acc, a = st
    am, af, gamma, beta = cf
    tol, ratio, evaluated, once = newton[0], newton[1], newton[2] == 1.0, newton[3] == 1.0
    give_up = int(newton[4])
    bp = h * h * beta * (1 - af) / (1 - am)
    gp = h * gamma * (1 - af) / (1 - am)
    system_prepare(system, k)
    acc1 = acc.copy()
    r, rt = np.zeros(acc.size), np.zeros(acc.size)
    m, from_start, damped, moving = system_tests(system)
    evaluated = evaluated and damped
    refresh = fresh or hf[0] != h
    x1, v1, a1 = np.empty(acc.size), v.copy(), np.empty(acc.size)  # at the last evaluation
    have_r, d_prev, refreshed, damped_n, r_first = False, np.inf, False, 0, np.inf
    for _ in range(max_iter):
        if not have_r:
            _evaluate(system, acc1, st, h, k, cf, bp, gp, refresh, count, r, moving, x1, v1, a1)
        if refresh:
            count[1] += 1
            count[2] += 1
            if not system_factor(system, bp, fresh):
                hf[0] = np.nan
                return FAILED
            hf[0] = h
            refresh, refreshed = False, True
        d = -r
        system_solve(system, d)
        count[3] += 1
        if evaluated and _converged(bp, np.max(np.abs(d[:m])), 1.0, d, x if from_start else x1,
                                    m, tol):
            _take(acc1, st, h, cf, x1, v1, a1)  # the evaluated iterate, r its residual
            return CONVERGED
        lam = 1.0
        if damped:
            lam = _backtrack(system, acc1, d, st, h, k, cf, bp, gp, count, r, rt, moving, x1, v1, a1)
            r[:] = rt
            have_r = True
            if give_up > 0 and lam < 1.0:  # the bookkeeping of give_up only
                damped_n += 1
                if damped_n == 1:
                    r_first = np.sqrt(np.dot(r, r))
            if 0 < give_up <= damped_n and np.sqrt(np.dot(r, r)) > 0.5 * r_first:
                return GIVEN_UP if refreshed else FAILED
        if lam == 1.0:
            acc1 += d
        else:
            acc1 += lam * d
        dn = lam * np.max(np.abs(d[:m]))
        if not np.isfinite(dn):
            return FAILED
        if not evaluated and _converged(bp, dn, lam, d, x if from_start else x1, m, tol):
            if lam == 0.5 ** MAX_BACKTRACKS:  # backtracking ran out: last residual elsewhere
                _evaluate(system, acc1, st, h, k, cf, bp, gp, False, count, rt, moving, x1, v1,
                          a1)
            _take(acc1, st, h, cf, x1, v1, a1)
            return CONVERGED
        if (dn > ratio * d_prev and not (once and refreshed and dn <= d_prev)) or lam < 1.0:
            refresh = True
            if have_r:
                _evaluate(system, acc1, st, h, k, cf, bp, gp, True, count, r, moving, x1, v1, a1)
        d_prev = dn
    return GIVEN_UP if give_up > 0 and refreshed else FAILED


@njit(cache=True)
def march(ts, k, k_stop, st, system, hf, cf, count, newton, max_iter, limit, max_steps, slot,
          out_x, out_v):
    """Steps ts[k] -> ts[k_stop] (s); returns (status, step index reached).  The states
    after the steps i with slot[i] >= 0 go to out_x/out_v[slot[i]]; at most max_steps
    steps are counted in count[4]."""
    system = as_struct(system)
    x, v = st[0], st[1]
    backup = (x.copy(), v.copy(), st[2].copy(), st[3].copy())
    while k < k_stop:
        if count[4] >= max_steps:
            return BUDGET, k
        h = ts[k + 1] - ts[k]
        for i in range(4):
            backup[i][:] = st[i]
        ok = False
        for attempt in range(2):  # kept factors, then fresh ones: one _step compilation
            outcome = _step(h, k + 1, st, system, hf, cf, count, newton, max_iter, attempt == 1)
            ok = outcome == CONVERGED
            if ok:
                break
            for i in range(4):
                st[i][:] = backup[i]
            if outcome == GIVEN_UP:
                break
        if not ok:
            hf[0] = np.nan
            return NEWTON_FAILED, k
        k += 1
        count[4] += 1
        system_accept(system, slot[k])
        if not np.all(np.isfinite(x)):
            return NON_FINITE, k
        if np.max(np.abs(x[: system_tests(system)[0]])) > limit:
            return BLOW_UP, k
        if slot[k] >= 0:
            out_x[slot[k]] = x
            out_v[slot[k]] = v
    return DONE, k
