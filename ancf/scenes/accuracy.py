"""Accuracy checks of a finished run, per scene kind: the run did what was asked,
but these say when its result is not to be trusted (the ``warnings`` list).  The
checks of one scene only sit in its file (its ``warn``); these are the shared ones:

* statics: Newton accepted a point at the round-off floor, above the requested
  residual; the stability of the equilibrium was not checked;
* fixed-step integration: the step against the period of the first bending mode
  (Euler-Bernoulli estimate, the fastest motion the results are meant to resolve).
"""
from __future__ import annotations

import math


def _root(f, a: float, b: float) -> float:
    """The root of f in [a, b] (a sign change) by bisection to round-off; scipy's brentq
    would cost every `ancf run` the import of scipy.optimize (0.24 s)."""
    fa = f(a)
    for _ in range(200):
        m = 0.5 * (a + b)
        if m in (a, b):
            break
        fm = f(m)
        if (fm < 0) == (fa < 0):
            a, fa = m, fm
        else:
            b = m
    return 0.5 * (a + b)


STEPS_PER_PERIOD = 20        # fixed steps per resolved period below this: too coarse
# first roots of the Euler-Bernoulli frequency equations (beta L)
PINNED_FREE = _root(lambda x: math.tan(x) - math.tanh(x), 3.5, 4.5)
CLAMPED_FREE = _root(lambda x: math.cos(x) * math.cosh(x) + 1.0, 1.0, 3.0)


def bending_period(p: dict, beta_l: float) -> float:
    """First bending period of a uniform beam, s."""
    EI = p["E"] * p["b"] * p["h"] ** 3 / 12.0
    rho_a = p["rho"] * p["b"] * p["h"]
    return 2.0 * math.pi / (beta_l**2 * math.sqrt(EI / (rho_a * p["L"] ** 4)))


def finite(v) -> bool:
    return isinstance(v, (int, float)) and math.isfinite(v)


def static(p: dict, res) -> list[str]:
    out = []
    hist = [h for h in res.extra.get("residuals") or [] if h]
    # the scenes' loads: F on a free DOF, and the 3D beams' tip moments (N m)
    target = p["rtol"] * max(math.hypot(p["F"], *(p.get(f"M{c}", 0.0) for c in "xyz")), 1.0)
    if res.converged and hist and hist[-1][-1] > target:
        out.append(f"Newton stopped at the round-off floor: final residual {hist[-1][-1]:.3g} N "
                   f"is above the requested rtol |load| = {target:.3g} N; the result holds only "
                   "the digits double precision resolves here")
    if res.converged and res.results.get("negative_tangent_eigenvalues") is None:
        out.append(f"stability of the equilibrium not checked (stability_check = "
                   f"{p['stability_check']})")
    return out


def step(p: dict, period: float, what: str) -> list[str]:
    """A warning when generalised-α's fixed step resolves ``what`` (its ``period``, s) with
    fewer than :data:`STEPS_PER_PERIOD` steps."""
    if p["integrator"] != "generalized-alpha" or p["dt"] * STEPS_PER_PERIOD <= period:
        return []
    return [f"dt = {p['dt']:g} s resolves the {what} (period {period:.3g} s) with "
            f"{period / p['dt']:.3g} steps, fewer than {STEPS_PER_PERIOD}: the motion is not resolved"]
