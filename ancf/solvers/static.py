"""Static equilibrium: Newton-Raphson with adaptive load stepping.

Solves ``Qe(q) + lambda (Qk + Q(q)) = 0`` for the independent coordinates ``z``
(``q = T z + g``) as the load factor ``lambda`` goes 0 -> 1; ``Qk`` is a constant
load vector and ``Q`` the sum of the model's force terms (``ancf.core.forces``: gravity,
and any term with a value and Jacobians, which statics and dynamics share).  Non-convergence is a
result (``converged=False`` and a ``message``), never an exception or a NaN.
"""
from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from numba import njit

from ancf.core.pattern import ReducedPattern, assemble_group, shared
from ancf.solvers import banded
from ancf.solvers.linear import Singular, factor, stability


@dataclass(kw_only=True)
class StaticResult:
    q: np.ndarray
    converged: bool
    message: str
    load_factor: float
    iterations: int
    load_steps: int
    residual_history: list = field(default_factory=list)  # one list of |r| per load step
    tangent_evaluations: int = 0
    factorizations: int = 0
    pattern: object = None  # the ReducedPattern the solve used
    tangent: object = None  # the reduced tangent at q in the pattern's storage, where the
                            # last iteration assembled it without force terms, else None


@dataclass(frozen=True)
class NewtonOptions:
    n_steps: int = 1            # initial number of load steps
    rtol: float = 1e-8          # |r| <= rtol * |Qk|  (round-off floor is ~1e-10 here)
    xtol: float = 1e-13         # or |dz| <= xtol * (1 + |z|) once |r| <= 1e3 rtol |Qk|
    max_iter: int = 25          # Newton iterations per load step
    min_step: float = 1.0 / 4096  # smallest load increment before giving up
    max_total_iter: int = 5000

    def __post_init__(self):
        for name, lo in (("n_steps", 1), ("max_iter", 1)):
            if int(getattr(self, name)) < lo:
                raise ValueError(f"{name} must be an integer >= {lo} (got {getattr(self, name)})")
        if not self.rtol > 0:
            raise ValueError(f"rtol must be > 0 (got {self.rtol})")


def _roundoff_floor(k_inf: float, z) -> float:
    """Smallest residual that can be resolved: absolute nodal coordinates carry an
    error of eps |q|, which the stiffest terms turn into forces of eps |q| |K|_inf
    (e.g. 1e-5 N for a 64-element beam with EA = 4e8 N)."""
    return 10.0 * np.finfo(float).eps * (1.0 + float(np.abs(z).max(initial=0.0))) * k_inf


@njit(cache=True)
def _newton_band(z, g, group, kl, lam, Qr, tol, xtol, max_iter, hist):
    """The iterations of :meth:`_Newton.run` at one load factor in one compiled call, for
    a compiled element group on band storage without force terms (tol = rtol |Qk|).
    Returns (z, status, iterations, |r|, factorisations, K); status 0 converged, 1 residual
    not finite, 2 singular tangent, 3 out of iterations; |r| per iteration in hist; K the
    tangent at the converged z (band storage), factored in place otherwise."""
    n = z.size
    grad, K = np.zeros(n), np.zeros((n, 3 * kl + 1))
    piv = np.empty(n, dtype=np.int64)
    small, facts, rn = False, 0, 0.0
    for it in range(1, max_iter + 1):
        assemble_group(group, z, g, True, grad, K)
        r = lam * Qr - grad
        rn = np.sqrt(np.dot(r, r))
        hist[it - 1] = rn
        if not np.isfinite(rn):
            return z, 1, it, rn, facts, K
        done = rn <= tol or (small and rn <= 1e3 * tol)
        if not done and it > 1 and rn > 0.25 * hist[it - 2]:  # stalled: at the round-off floor?
            k_inf = 0.0
            for i in range(n):
                k_inf = max(k_inf, np.sum(np.abs(K[i])))
            zmax = np.max(np.abs(z)) if n else 0.0
            done = rn <= 10.0 * 2.220446049250313e-16 * (1.0 + zmax) * k_inf
        if done:
            return z, 0, it, rn, facts, K
        facts += 1
        if banded.lu(K, kl, piv, True) != 0:
            return z, 2, it, rn, facts, K
        banded.solve(K, kl, piv, r)
        if not np.all(np.isfinite(r)):
            return z, 2, it, rn, facts, K
        z = z + r
        small = np.sqrt(np.dot(r, r)) <= xtol * (1.0 + np.sqrt(np.dot(z, z)))
    return z, 3, max_iter, rn, facts, K


@njit(cache=True)
def _march_band(z, g, group, kl, Qr, tol, xtol, max_iter, n_steps, min_step, max_total_iter):
    """:func:`solve_static`'s load stepping over :func:`_newton_band` in one compiled call,
    the same steps: lam 0 -> 1 from increments 1/n_steps, doubled after a step of at most
    4 iterations, halved after a failed one (giving up below min_step, or past
    max_total_iter iterations).  Returns (z, converged, lam, iterations, load steps,
    factorisations, last status, its |r|, K of the last step, |r| of every iteration,
    iterations of each attempt); K the tangent at z when converged."""
    hist = np.zeros(max_iter)
    res, counts = np.empty(8 * max_iter), np.empty(16, dtype=np.int64)
    K = np.zeros((0, 0))
    lam, step, rn = 0.0, 1.0 / n_steps, 0.0
    total = steps = facts = attempts = nres = status = 0
    while lam < 1.0 - 1e-14:
        step = min(step, 1.0 - lam)
        z_new, status, its, rn, f, K = _newton_band(z, g, group, kl, lam + step, Qr, tol,
                                                    xtol, max_iter, hist)
        total += its
        facts += f
        if nres + its > res.size:  # more room: twice as much
            res = np.concatenate((res[:nres], np.empty(res.size + its)))
        if attempts == counts.size:
            counts = np.concatenate((counts, np.empty(counts.size, dtype=np.int64)))
        res[nres:nres + its] = hist[:its]
        counts[attempts] = its
        nres, attempts = nres + its, attempts + 1
        if status == 0:
            z, lam, steps = z_new, lam + step, steps + 1
            step *= 2.0 if its <= 4 else 1.0
        else:
            step *= 0.5
            if step < min_step or total > max_total_iter:
                break
    ok = status == 0
    return z, ok, lam, total, steps, facts, status, rn, K, res[:nres], counts[:attempts]


@njit(cache=True)
def _assemble_group(group, z, g, grad, K):
    """:func:`~ancf.core.pattern.assemble_group` with the tangent, called from Python."""
    assemble_group(group, z, g, True, grad, K)


class _Newton:
    """Newton iterations on the reduced system ``T^T (lam (Qk + Q(q)) - dU/dq) = 0``, assembled
    straight into the pattern's storage and solved by the pattern's solver."""

    def __init__(self, assembly, pattern, g, Qk_r, opt, forces, q0):
        self.assembly, self.pattern, self.g, self.Qk_r, self.opt = assembly, pattern, g, Qk_r, opt
        self.forces = forces
        self.scale = max(np.linalg.norm(Qk_r + self._force(q0, 1.0, None)), 1.0)
        self.tangents = self.factorizations = 0
        self.compiled = pattern.compiled(assembly)

    def _assemble(self, z):
        """(T^T dU/dq, T^T K T in the pattern's storage) at z: one compiled call where
        the element group allows it."""
        if self.compiled is None:
            return self.pattern.assemble(self.assembly, self.pattern.expand(z, self.g))
        grad, K = np.zeros(self.pattern.n), self.pattern.zeros_matrix()
        _assemble_group(self.compiled, z, self.g, grad, K)
        return grad, K

    def _force(self, q, lam, K):
        """lam T^T Q(q), subtracting lam T^T dQ/dq T from the stored tangent K if given."""
        if self.forces is None:
            return 0.0
        q = q if q is not None else self.pattern.expand(self._z, self.g)
        zero = np.zeros_like(q)
        if K is not None:
            Kq, _ = self.forces.jacobians(q, zero, 0.0)
            if Kq is not None:
                self.pattern.add_global(K, Kq, -lam)
        return lam * self.pattern.reduce(self.forces.value(q, zero, 0.0))

    def run(self, z, lam, history):
        """Iterate at load factor lam; returns (z, converged, iterations, why)."""
        opt, small_step = self.opt, False
        for it in range(1, opt.max_iter + 1):
            grad, K = self._assemble(z)
            self.tangents += 1
            self._z = z
            r = lam * self.Qk_r + self._force(None, lam, K) - grad
            rn = float(np.linalg.norm(r))
            history.append(rn)
            if not np.isfinite(rn):
                return z, False, it, "residual is not finite"
            stalled = len(history) > 1 and rn > 0.25 * history[-2]  # no longer contracting
            if rn <= opt.rtol * self.scale or (small_step and rn <= 1e3 * opt.rtol * self.scale) or (
                    stalled and rn <= _roundoff_floor(self.pattern.inf_norm(K), z)):
                return z, True, it, ""
            try:
                self.factorizations += 1
                dz = factor(self.pattern, K, overwrite=True).solve(r)
            except Singular as exc:
                return z, False, it, f"singular tangent stiffness ({exc})"
            z = z + dz
            small_step = np.linalg.norm(dz) <= opt.xtol * (1.0 + np.linalg.norm(z))
        return z, False, opt.max_iter, f"no convergence in {opt.max_iter} iterations (|r| = {rn:.3e})"

    def march(self, z) -> StaticResult:
        """The whole load stepping in one compiled call (:func:`_march_band`), for a
        compiled element group without force terms."""
        opt, pattern = self.opt, self.pattern
        z, ok, lam, total, steps, facts, status, rn, K, res, counts = _march_band(
            z, self.g, self.compiled, pattern.kl, self.Qk_r, opt.rtol * self.scale, opt.xtol,
            opt.max_iter, opt.n_steps, opt.min_step, opt.max_total_iter)
        flat, histories, start = res.tolist(), [], 0
        for its in counts.tolist():
            histories.append(flat[start:start + its])
            start += its
        message = "converged" if ok else _given_up(_why(status, rn, opt.max_iter), lam, opt)
        return StaticResult(
            q=pattern.expand(z, self.g), converged=ok, message=message,
            load_factor=1.0 if ok else lam, iterations=total, load_steps=steps,
            residual_history=histories, tangent_evaluations=total, factorizations=facts,
            pattern=pattern, tangent=K if ok else None)


def _why(status: int, rn: float, max_iter: int) -> str:
    """The reason of :func:`_newton_band`'s status 1, 2 or 3."""
    return ("residual is not finite",
            "singular tangent stiffness (zero pivot or non-finite solution)",
            f"no convergence in {max_iter} iterations (|r| = {rn:.3e})")[status - 1]


def _given_up(why: str, lam: float, opt: NewtonOptions) -> str:
    return (f"No convergence: {why}; load factor reached {lam:.4f} "
            f"(increment fell below {opt.min_step:g})")


def solve_static(assembly, elimination, Qk, q0, options: NewtonOptions | None = None,
                 forces=None) -> StaticResult:
    """Equilibrium under the external load vector ``Qk`` (global, N) and the force terms
    ``forces`` (an ``ancf.core.forces.Forces``, or None), starting at ``q0``."""
    opt = options or NewtonOptions()
    T, g, _ = elimination.selection()
    pattern = shared(assembly, T) if forces is None else ReducedPattern(
        assembly.n_dofs, [grp.dofmap for grp in assembly.groups] + forces.dofmaps(), T)
    z = pattern.restrict(q0)
    newton = _Newton(assembly, pattern, g, pattern.reduce(Qk), opt, forces, pattern.expand(z, g))
    if newton.compiled is not None and forces is None:
        return newton.march(z)
    lam, step = 0.0, 1.0 / opt.n_steps
    total, steps, histories, why = 0, 0, [], ""
    result = lambda ok, msg, lf: StaticResult(  # noqa: E731
        q=pattern.expand(z, g), converged=ok, message=msg, load_factor=lf, iterations=total,
        load_steps=steps, residual_history=histories, tangent_evaluations=newton.tangents,
        factorizations=newton.factorizations, pattern=pattern)
    while lam < 1.0 - 1e-14:
        step = min(step, 1.0 - lam)
        hist = []
        z_new, ok, its, why = newton.run(z, lam + step, hist)
        total += its
        histories.append(hist)
        if ok:
            z, lam, steps = z_new, lam + step, steps + 1
            step *= 2.0 if its <= 4 else 1.0
        else:
            step *= 0.5
            if step < opt.min_step or total > opt.max_total_iter:
                return result(False, _given_up(why, lam, opt), lam)
    return result(True, "converged", 1.0)


def stability_at(assembly, pattern, q, forces=None, tangent=None):
    """(negative, zero, lowest/largest) eigenvalues of the reduced tangent at q, by inertia.
    With force terms (``forces``, at full load) the tangent is K - dQ/dq, of which the
    symmetric part is taken (a moment about a fixed axis has a non-symmetric load
    stiffness in general; the inertia needs a symmetric matrix).  ``tangent``: K at q in
    the pattern's storage if at hand (a solve's ``StaticResult.tangent``: the same numbers,
    no assembly), else assembled."""
    K = pattern.assemble(assembly, q)[1] if tangent is None else tangent
    Kq = None if forces is None else forces.jacobians(q, np.zeros_like(q), 0.0)[0]
    if Kq is not None:
        pattern.add_global(K, 0.5 * (Kq + Kq.T), -1.0)
    return stability(pattern, K)
