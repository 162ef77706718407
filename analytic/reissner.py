"""Geometrically exact planar (Reissner / Simo-Reissner) cantilever under a dead tip load.

Reference for the large-deflection cantilever of Kerkkänen 2006 (thesis section 2.4,
Figure 2.4, Tables 2.3-2.4) and the 2003 report (Figure 3, Tables 3-5): length
``L`` = 2.0 m, rectangular section ``b`` x ``h`` (b = 0.1 m), ``E`` = 2.07e11 N/m^2,
tip force ``F = -5.0e8 h^3`` N in the y direction (dead load: its direction is fixed).

* Model 1: h = b = 0.1 m, nu = 0.3, F = -5.0e5 N.
* Model 2: h = 0.5 m, b = 0.1 m, nu = 0.0, F = -6.25e7 N.

Units: SI (N, m, Pa, rad).

Equations (arclength ``s`` of the undeformed reference line, 0 <= s <= L)
--------------------------------------------------------------------------
Reissner's planar beam with extension ``eps``, shear ``gamma`` and bending::

    x' = (1 + eps) cos(theta) - gamma sin(theta)
    y' = (1 + eps) sin(theta) + gamma cos(theta)
    theta' = M / (E I)                      (theta: rotation of the cross-section)
    M' = Fx y' - Fy x'

With a dead tip load the internal force (in the global frame) is constant and
equal to ``(Fx, Fy)``; its section components are ``N = Fx cos(theta) + Fy sin(theta)``
(normal) and ``V = -Fx sin(theta) + Fy cos(theta)`` (shear), with the linear elastic
laws ``eps = N/(E A)``, ``gamma = V/(k_s G A)``, ``G = E/(2(1+nu))``,
``A = b h``, ``I = b h^3/12``.  The moment equation follows from
``M(s) = (x(L) - x(s)) Fy - (y(L) - y(s)) Fx`` (moment of the tip load about the
section at s), so ``M(L) = 0`` and, for Fy < 0, ``M(0) < 0`` and the beam bends
down.  Boundary conditions: ``x(0) = y(0) = theta(0) = 0`` (clamped at the
origin, beam along +x) and ``M(L) = 0``.

Numerics: :func:`scipy.integrate.solve_bvp` on the scaled unknowns
``(x/L, y/L, theta, M L/(E I))`` over ``xi = s/L`` in [0, 1], with continuation in
the load factor (each step seeded with the previous solution, halving the step on
failure) and a final solve at the requested tolerance ``tol`` (relative
collocation residual, also used as the boundary-condition tolerance).  Failures
are reported with ``converged = False`` and the solver message, never raised.

Validation (E = 2.07e11 Pa, L = 2 m, k_s = 5/6, tol = 1e-10; ~0.03 s each)
--------------------------------------------------------------------------
=========  ==========================  =========================  ==================
model      this reference (x, y) [m]   BEAM188, 64 el. (x, y)     difference [m]
=========  ==========================  =========================  ==================
Model 1    (1.8552323, -0.6808864)     (1.85515, -0.68108)        (+8.2e-5, +1.9e-4)
Model 2    (1.8510980, -0.7045180)     (1.85145, -0.70337)        (-3.5e-4, -1.15e-3)
=========  ==========================  =========================  ==================

The BVP solution agrees with an independent shooting solution (DOP853, rtol 1e-12)
to ~1e-15 m and moves < 1e-13 m when tol goes from 1e-10 to 1e-11, so the
differences above belong to BEAM188 (a discretisation with its own section
shear stiffness), not to this reference.  The larger Model 2 gap (h = 0.5 m, shear
dominated) matches the papers' remark that BEAM188 is slightly stiffer there than
the ANCF elements (proposed element -0.71050, Omar-Shabana -0.70667 at 64 el.).

Small loads reproduce the linear Timoshenko cantilever
``F L^3/(3 E I) + F L/(k_s G A)`` (:func:`analytic.timoshenko.cantilever_tip_deflection`).
"""
from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np
from scipy.integrate import solve_bvp

from analytic._checks import finite, positive

__all__ = ["ReissnerResult", "tip_position", "default_tip_force", "MODELS", "BEAM188_64"]

#: Cantilever models of the papers (E [Pa], nu, L [m], h [m], b [m], F [N]).
MODELS = {
    "model1": {"E": 2.07e11, "nu": 0.3, "L": 2.0, "h": 0.1, "b": 0.1, "F": -5.0e8 * 0.1**3},
    "model2": {"E": 2.07e11, "nu": 0.0, "L": 2.0, "h": 0.5, "b": 0.1, "F": -5.0e8 * 0.5**3},
}
#: ANSYS BEAM188 tip positions (x, y) [m] with 64 elements (thesis Tables 2.3-2.4,
#: identical in report Tables 3-4).
BEAM188_64 = {"model1": (1.85515, -0.68108), "model2": (1.85145, -0.70337)}


@dataclass
class ReissnerResult:
    """Solution of the Reissner cantilever.

    tip_x, tip_y: tip position [m]; tip_rotation: cross-section rotation theta(L) [rad];
    converged: True when every continuation step and the final solve succeeded;
    message: solver / continuation summary (the failure reason when not converged);
    s: arclength mesh [m]; x, y: deformed reference line [m]; theta: rotation [rad];
    M: bending moment [N m]; load_factor: fraction of the load reached.
    When not converged, the tip values are NaN (flagged by ``converged=False`` and
    explained in ``message``) and the arrays hold the last accepted continuation
    step at ``load_factor`` (the straight initial guess if no step succeeded).
    """

    tip_x: float
    tip_y: float
    tip_rotation: float
    converged: bool
    message: str
    s: np.ndarray = field(repr=False)
    x: np.ndarray = field(repr=False)
    y: np.ndarray = field(repr=False)
    theta: np.ndarray = field(repr=False)
    M: np.ndarray = field(default_factory=lambda: np.empty(0), repr=False)
    load_factor: float = 1.0


def default_tip_force(h: float) -> float:
    """Tip force of the papers, F = -5.0e8 h^3 [N] (h in m)."""
    return -5.0e8 * h**3


def tip_position(E: float, nu: float, L: float, h: float, b: float, F: float | None = None,
                 Fx: float = 0.0, ks: float = 5.0 / 6.0, tol: float = 1e-10,
                 max_nodes: int = 20_000) -> ReissnerResult:
    """Tip position of the geometrically exact Reissner cantilever under a dead tip load.

    E: Young's modulus [Pa]; nu: Poisson's ratio [-], in (-1, 0.5]; L: length [m];
    h: section height [m] (bending plane); b: width [m]; F: signed vertical (y) tip
    force [N] (negative = down; ``None`` = the papers' -5.0e8 h^3); Fx: horizontal
    tip force [N]; ks: shear correction factor [-]; tol: solve_bvp tolerance of the
    final solve (relative residual; also the boundary-condition tolerance; values
    below about 1e-11 approach the round-off floor and may fail to converge);
    max_nodes: solve_bvp mesh limit.

    Raises ValueError for invalid inputs (naming the field and the allowed range);
    solver failures are returned as ``converged=False`` with the message.
    """
    E = positive("E", E)
    L = positive("L", L)
    h = positive("h", h)
    b = positive("b", b)
    ks = positive("ks", ks)
    tol = positive("tol", tol)
    nu = finite("nu", nu)
    if not -1.0 < nu <= 0.5:
        raise ValueError(f"nu must be in (-1, 0.5] (got {nu!r})")
    Fy = default_tip_force(h) if F is None else finite("F", F)
    Fx = finite("Fx", Fx)
    if int(max_nodes) < 10:
        raise ValueError(f"max_nodes must be >= 10 (got {max_nodes!r})")

    G = E / (2.0 * (1.0 + nu))
    A, I = b * h, b * h**3 / 12.0
    EA, GA, EI = E * A, ks * G * A, E * I
    cL = L * L / EI  # scale of the moment equation in the scaled variables

    def make_fun(lam: float):
        fx, fy = lam * Fx, lam * Fy

        def fun(xi, Y):
            th, kap = Y[2], Y[3]
            c, s_ = np.cos(th), np.sin(th)
            eps = (fx * c + fy * s_) / EA
            gam = (-fx * s_ + fy * c) / GA
            dx = (1.0 + eps) * c - gam * s_
            dy = (1.0 + eps) * s_ + gam * c
            return np.vstack((dx, dy, kap, cL * (fx * dy - fy * dx)))

        def jac(xi, Y):
            th = Y[2]
            c, s_ = np.cos(th), np.sin(th)
            eps = (fx * c + fy * s_) / EA
            gam = (-fx * s_ + fy * c) / GA
            deps = (-fx * s_ + fy * c) / EA      # d eps / d theta
            dgam = (-fx * c - fy * s_) / GA      # d gamma / d theta
            ddx = deps * c - (1.0 + eps) * s_ - dgam * s_ - gam * c
            ddy = deps * s_ + (1.0 + eps) * c + dgam * c - gam * s_
            n = Y.shape[1]
            J = np.zeros((4, 4, n))
            J[0, 2] = ddx
            J[1, 2] = ddy
            J[2, 3] = 1.0
            J[3, 2] = cL * (fx * ddy - fy * ddx)
            return J

        return fun, jac

    def bc(ya, yb):
        return np.array([ya[0], ya[1], ya[2], yb[3]])

    def bc_jac(ya, yb):
        Ja, Jb = np.zeros((4, 4)), np.zeros((4, 4))
        Ja[0, 0] = Ja[1, 1] = Ja[2, 2] = 1.0
        Jb[3, 3] = 1.0
        return Ja, Jb

    # Initial guess: straight, unloaded beam.
    xi = np.linspace(0.0, 1.0, 41)
    Y = np.vstack((xi, np.zeros_like(xi), np.zeros_like(xi), np.zeros_like(xi)))

    step_tol = max(tol, 1e-6)  # continuation steps need not be tight
    lam, dlam, min_dlam = 0.0, 0.125, 1.0 / 4096
    steps = 0
    last_msg = "not started"
    while lam < 1.0:
        trial = min(1.0, lam + dlam)
        fun, jac = make_fun(trial)
        sol, last_msg = _solve(fun, jac, bc, bc_jac, xi, Y, step_tol, max_nodes)
        if sol is not None:
            lam, xi, Y = trial, sol.x, sol.y
            steps += 1
            dlam = min(2 * dlam, 0.25)
        else:
            dlam /= 2
            if dlam < min_dlam:
                return _failed(f"load continuation stalled at load factor {lam:.6g}: "
                               f"{last_msg}", xi, Y, L, EI, lam)

    # Final solve at the requested tolerance, seeded with the last continuation step.
    fun, jac = make_fun(1.0)
    sol, last_msg = _solve(fun, jac, bc, bc_jac, xi, Y, tol, max_nodes)
    if sol is None:
        hint = " (tol is near the round-off floor; try tol >= 1e-11)" if tol < 1e-11 else ""
        return _failed(f"final solve at tol={tol:g} failed: {last_msg}{hint}",
                       xi, Y, L, EI, 1.0)
    xi, Y = sol.x, sol.y
    rms = float(np.max(sol.rms_residuals)) if sol.rms_residuals.size else 0.0
    msg = (f"{sol.message} ({steps} load steps, {xi.size} nodes, "
           f"max rms residual {rms:.2e})")
    return ReissnerResult(
        tip_x=float(Y[0, -1] * L), tip_y=float(Y[1, -1] * L), tip_rotation=float(Y[2, -1]),
        converged=True, message=msg, s=xi * L, x=Y[0] * L, y=Y[1] * L, theta=Y[2].copy(),
        M=Y[3] * EI / L, load_factor=1.0)


def _solve(fun, jac, bc, bc_jac, xi, Y, tol, max_nodes):
    """One solve_bvp call; returns (solution or None, message). Never raises."""
    try:
        with np.errstate(all="ignore"):
            sol = solve_bvp(fun, bc, xi, Y, fun_jac=jac, bc_jac=bc_jac, tol=tol,
                            max_nodes=int(max_nodes), bc_tol=tol)
    except Exception as exc:  # noqa: BLE001 - reported through the result
        return None, f"solve_bvp raised {type(exc).__name__}: {exc}"
    if not sol.success or not np.all(np.isfinite(sol.y)):
        return None, sol.message if not sol.success else "non-finite solution"
    return sol, sol.message


def _failed(msg, xi, Y, L, EI, lam) -> ReissnerResult:
    nan = float("nan")
    return ReissnerResult(tip_x=nan, tip_y=nan, tip_rotation=nan, converged=False,
                          message=msg, s=xi * L, x=Y[0] * L, y=Y[1] * L, theta=Y[2].copy(),
                          M=Y[3] * EI / L, load_factor=lam)


if __name__ == "__main__":  # pragma: no cover - manual report
    import time

    for name, m in MODELS.items():
        t0 = time.perf_counter()
        r = tip_position(**m)
        dt = time.perf_counter() - t0
        bx, by = BEAM188_64[name]
        print(f"{name}: tip ({r.tip_x:.6f}, {r.tip_y:.6f}) rot {r.tip_rotation:.6f}  "
              f"BEAM188-64 ({bx}, {by})  d=({r.tip_x - bx:+.2e}, {r.tip_y - by:+.2e})  "
              f"{dt:.2f}s  {r.message}")
