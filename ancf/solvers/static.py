"""Static equilibrium: Newton-Raphson with adaptive load stepping.

Solves ``Qe(q) + lambda Qk = 0`` for the independent coordinates ``z``
(``q = T z + g``) as the load factor ``lambda`` goes 0 -> 1.  Non-convergence is a
result (``converged=False`` and a ``message``), never an exception or a NaN.
"""
from __future__ import annotations

import warnings
from dataclasses import dataclass, field

import numpy as np
import scipy.sparse.linalg as spla


@dataclass
class StaticResult:
    q: np.ndarray
    converged: bool
    message: str
    load_factor: float
    iterations: int
    load_steps: int
    residual_history: list = field(default_factory=list)  # one list of |r| per load step


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


class _Singular(Exception):
    pass


def _solve(K, r):
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        try:
            dz = spla.splu(K.tocsc()).solve(r)
        except (RuntimeError, Warning) as exc:
            raise _Singular(str(exc)) from None
    if not np.all(np.isfinite(dz)):
        raise _Singular("non-finite Newton step")
    return dz


def _roundoff_floor(Kr, z) -> float:
    """Smallest residual that can be resolved: absolute nodal coordinates carry an
    error of eps |q|, which the stiffest terms turn into forces of eps |q| |K|_inf
    (e.g. 1e-5 N for a 64-element beam with EA = 4e8 N)."""
    k_inf = float(abs(Kr).sum(axis=1).max())
    return 10.0 * np.finfo(float).eps * (1.0 + float(np.abs(z).max(initial=0.0))) * k_inf


def _newton(assembly, T, g, z, Qk, lam, opt, history):
    """Newton iterations at load factor lam; returns (z, converged, iterations, why)."""
    TT = T.T.tocsr()
    scale = max(np.linalg.norm(TT @ Qk), 1.0)
    small_step = False
    for it in range(1, opt.max_iter + 1):
        grad, K = assembly.gradient_tangent(T @ z + g)
        r = TT @ (lam * Qk - grad)
        rn = float(np.linalg.norm(r))
        history.append(rn)
        if not np.isfinite(rn):
            return z, False, it, "residual is not finite"
        Kr = TT @ K @ T
        stalled = len(history) > 1 and rn > 0.25 * history[-2]  # no longer contracting
        if rn <= opt.rtol * scale or (small_step and rn <= 1e3 * opt.rtol * scale) or (
                stalled and rn <= _roundoff_floor(Kr, z)):
            return z, True, it, ""
        try:
            dz = _solve(Kr, r)
        except _Singular as exc:
            return z, False, it, f"singular tangent stiffness ({exc})"
        z = z + dz
        small_step = np.linalg.norm(dz) <= opt.xtol * (1.0 + np.linalg.norm(z))
    return z, False, opt.max_iter, f"no convergence in {opt.max_iter} iterations (|r| = {rn:.3e})"


def solve_static(assembly, elimination, Qk, q0, options: NewtonOptions | None = None) -> StaticResult:
    """Equilibrium under the external load vector ``Qk`` (global, N), starting at ``q0``."""
    opt = options or NewtonOptions()
    T, g, free = elimination.build()
    z = np.asarray(q0, dtype=float)[free].copy()
    lam, step = 0.0, 1.0 / opt.n_steps
    total, steps, histories, why = 0, 0, [], ""
    while lam < 1.0 - 1e-14:
        step = min(step, 1.0 - lam)
        hist = []
        z_new, ok, its, why = _newton(assembly, T, g, z, Qk, lam + step, opt, hist)
        total += its
        histories.append(hist)
        if ok:
            z, lam, steps = z_new, lam + step, steps + 1
            step *= 2.0 if its <= 4 else 1.0
        else:
            step *= 0.5
            if step < opt.min_step or total > opt.max_total_iter:
                msg = (f"No convergence: {why}; load factor reached {lam:.4f} "
                       f"(increment fell below {opt.min_step:g})")
                return StaticResult(T @ z + g, False, msg, lam, total, steps, histories)
    return StaticResult(T @ z + g, True, "converged", 1.0, total, steps, histories)
