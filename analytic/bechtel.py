"""Bechtel et al.'s steady extensible belt on two equal pulleys (thesis section 4.1;
Bechtel, Vohra, Jacob, Carlson, J. Appl. Mech. 67 (2000) 197-206).

Assumptions (thesis 4.1, items 1-6): planar, steady (everything at a place s is
independent of time), the belt only stretches (no bending), it never leaves the pulleys
(wrap pi on each, spans of length ``l_s = pi R`` as in Table 4.1, geometric belt length
``L = 4 pi R``), Coulomb friction ``mu``.  On each pulley the belt first sticks (speed
= rim speed, so T and v constant, no friction) and then slips over an arc ``phi`` at the
exit, where ``n = T - G v`` follows Eq. 4.2: ``dn / dtheta = -+ mu n``.  In the spans T
and v are constant (Eqs 4.3-4.4).  The driver pulls the tight span in, so
``omega_driver = v_tight / R`` and ``omega_driven = v_slack / R`` (Eq. 4.48).

Reading of the thesis (stated here because section 4.1 only summarises [5]):

* Reference state of Eq. 4.1 = the unstretched belt: ``T_o = 0``, stretch
  ``lambda = v / v_o`` (mass conservation), so ``T = k (lambda - 1)`` with ``k = E A``
  (N) of the unstretched section; ``rhoA`` is the mass per unstretched length (kg/m) and
  the mass flow is ``G = rhoA v_o`` (kg/s).
* ``T_i`` (N) is the installation tension: the uniform tension of the same belt at rest on
  the same pulleys, so its unstretched length is ``L / (1 + T_i / k)``.  That length (the
  belt's mass) is kept when it runs: ``int (T_i - T(s)) / lambda(s) ds = 0`` over the
  stretched length L (the form that stays well conditioned as k -> infinity).
* ``T_a`` (N m) is taken off the driven pulley: the moment of the friction on it,
  ``R int f ds = R (n_tight - n_slack)`` (the thesis: "when the friction force is
  integrated ... the moment corresponding to the applied opposing torque is achieved").

With ``n_s = T_slack - G v_slack`` (N) as the one unknown, everything else is closed form
(:func:`_state`); ``n_s`` is found by Brent's method to ``XTOL_N`` from the mass
condition.  The capstan variant drops the inertia from the momentum equations (G = 0 in
Eqs 4.2-4.3: ``n = T``), i.e. it is the same solution at ``rhoA = 0``.  The largest
transmissible torque is the ``T_a`` whose slip arc is the whole wrap, ``phi = pi``.

Defaults: Table 4.1 Model 2 (R, mu, omega_0, rhoA = rho w h = 0.02 kg/m), k = 0.2 kN
(Figs 4.11-4.18; = E w h with the E = 1.6667e6 Pa of the plate model), T_i = 50 N (thesis,
after Fig. 4.10), T_a = 2 N m (Eq. 4.47 at steady state).  The thesis's "approximately
14.6 %" slower driven pulley (k = 0.2 kN, read off Fig. 4.14) is not reproduced: this
model gives 15.16 % (capstan 14.71 %); see tests/scenes/test_bechtel.py.
"""
from __future__ import annotations

import math
import sys
from dataclasses import dataclass

import numpy as np
from scipy.optimize import brentq

from ancf.common.params import InputError, Param

#: Table 4.1, Model 2: R (m), mu (-), omega_0 (rad/s), rho (kg/m^3), w and h (m)
MODEL2 = {"R": 0.05, "mu": 0.6, "omega": 500.0, "rho": 166.667, "w": 0.04, "h": 0.003}
#: absolute tolerance of Brent's method on n_s and on the torque, N and N m
XTOL_N = 1e-12
RTOL = 4e-15

PARAMS = (
    Param("k", 0.2e3, float, "N", "axial stiffness E A (thesis: 0.2 kN compliant, 25 kN stiff)",
          lo=1e-6, hi=1e12),
    Param("R", MODEL2["R"], float, "m", "radius of both pulleys", lo=0, lo_open=True, hi=10),
    Param("omega", MODEL2["omega"], float, "rad/s", "driver angular velocity", lo=0, lo_open=True,
          hi=1e5),
    Param("mu", MODEL2["mu"], float, "-", "Coulomb friction coefficient", lo=1e-6, hi=10),
    Param("T_i", 50.0, float, "N", "installation tension (uniform, belt at rest)",
          lo=0, lo_open=True, hi=1e9),
    Param("T_a", 2.0, float, "N m", "torque taken off the driven pulley", lo=0, hi=1e9),
    Param("rhoA", MODEL2["rho"] * MODEL2["w"] * MODEL2["h"], float, "kg/m",
          "mass per unstretched length (default rho w h of Model 2)", lo=0, hi=1e3),
)


@dataclass(frozen=True)
class Belt:
    """Steady state: tensions (N), speeds (m/s), slip arc (rad), the unknown n_s (N)."""

    k: float
    R: float
    omega: float
    mu: float
    rhoA: float
    T_tight: float
    T_slack: float
    n_tight: float
    n_slack: float
    v_o: float

    @property
    def lam_tight(self) -> float:
        return 1.0 + self.T_tight / self.k

    @property
    def lam_slack(self) -> float:
        return 1.0 + self.T_slack / self.k

    @property
    def v_tight(self) -> float:
        return self.v_o * self.lam_tight

    @property
    def v_slack(self) -> float:
        return self.v_o * self.lam_slack

    @property
    def slip_arc(self) -> float:
        """Slip arc of either pulley (equal pulleys: the same ratio n_t / n_s), rad."""
        return math.log1p((self.n_tight - self.n_slack) / self.n_slack) / self.mu

    @property
    def a(self) -> float:
        """k - rhoA v_o^2 = (k + n) / lambda, N."""
        return (self.k + self.n_tight) / self.lam_tight


def _state(p: dict, n_s: float, T_a: float) -> Belt:
    """Closed form for a given n_s = T_slack - G v_slack (N) and torque T_a (N m).

    v_tight = omega R with v_o = v_tight / lambda_t gives k lam_t - m / lam_t = k + n_t,
    m = rhoA (omega R)^2, solved without cancellation: T_t = n_t + 2 k m / (S + k + n_t).
    """
    k, m = p["k"], p["rhoA"] * (p["omega"] * p["R"]) ** 2
    n_t = n_s + T_a / p["R"]
    T_t = n_t + 2.0 * k * m / (math.hypot(k + n_t, 2.0 * math.sqrt(k * m)) + k + n_t)
    T_s = (k * (T_t - T_a / p["R"]) + n_s * T_t) / (k + n_t)
    v_o = p["omega"] * p["R"] / (1.0 + T_t / k)
    return Belt(k, p["R"], p["omega"], p["mu"], p["rhoA"], T_t, T_s, n_t, n_s, v_o)


def mass_residual(b: Belt, T_i: float) -> float:
    """int (T_i - T) / lambda ds over the belt, N m (0: the installed belt's mass)."""
    phi, R, k = b.slip_arc, b.R, b.k
    stick = math.pi * R + R * (math.pi - phi)  # span + stick arc at T_t, and again at T_s
    spans = stick * ((T_i - b.T_tight) / b.lam_tight + (T_i - b.T_slack) / b.lam_slack)
    # one slip arc: lambda = (k + n) / a, n = n_s e^(mu theta); int dtheta / lambda closed form
    log_ratio = math.log1p((b.n_tight - b.n_slack) / (k + b.n_slack))
    arc = R * (phi * (T_i - b.rhoA * b.v_o ** 2 * (T_i + k) / k)
               - (T_i + k) * (b.a / k) * log_ratio / b.mu)
    return spans + 2.0 * arc


def _n_min(p: dict, T_a: float) -> float:
    """Smallest n_s (N): slip over the whole wrap, phi = pi (positive normal force at T_a = 0)."""
    return T_a / (p["R"] * math.expm1(p["mu"] * math.pi)) if T_a > 0 else sys.float_info.min


def _full_slip_residual(p: dict, T_a: float) -> float:
    return mass_residual(_state(p, _n_min(p, T_a), T_a), p["T_i"])


def _bracket_up(f, x0: float) -> float:
    """An x >= x0 with f(x) < 0 for a decreasing f (doubling), else InputError."""
    x = x0
    for _ in range(200):
        if f(x) < 0:
            return x
        x *= 2.0
    raise InputError("T_i: no steady state found (the belt never reaches its installed mass)")


def max_torque(p: dict) -> float:
    """Largest T_a (N m) the belt transmits: the slip arc covers the whole wrap."""
    if _full_slip_residual(p, 0.0) <= 0:
        v = p["omega"] * p["R"]
        raise InputError(f"omega = {p['omega']!r} is out of range: the belt leaves the pulleys "
                         f"(centrifugal tension rhoA v^2 = {p['rhoA'] * v * v:.4g} N exceeds what "
                         f"T_i = {p['T_i']!r} N allows); allowed: a lower omega or a higher T_i")
    f = lambda T_a: _full_slip_residual(p, T_a)  # noqa: E731
    hi = _bracket_up(f, p["T_i"] * p["R"])
    return brentq(f, 0.0, hi, xtol=XTOL_N, rtol=RTOL)


def check(p: dict) -> None:
    """Field ranges (InputError naming the field) as in :data:`PARAMS`."""
    for par in PARAMS:
        par.check(p[par.name])


def steady(p: dict, capstan: bool = False) -> tuple[Belt, float]:
    """(steady belt, largest transmissible torque N m); ``capstan``: inertia neglected."""
    check(p)
    p = dict(p, rhoA=0.0) if capstan else p
    top = max_torque(p)
    if p["T_a"] > top:
        raise InputError(f"T_a = {p['T_a']!r} N m is out of range; allowed: [0, {top:.6g}] N m "
                         "(the largest transmissible torque, slip over the whole wrap)")
    f = lambda n_s: mass_residual(_state(p, n_s, p["T_a"]), p["T_i"])  # noqa: E731
    lo = _n_min(p, p["T_a"])
    n_s = lo if f(lo) <= 0 else brentq(f, lo, _bracket_up(f, max(lo, p["T_i"])), xtol=XTOL_N,
                                       rtol=RTOL)  # f(lo) <= 0 only at T_a = max, round-off
    return _state(p, n_s, p["T_a"]), top


def summary(b: Belt, top: float) -> dict:
    """The JSON result keys (N, m/s, rad, -, N m)."""
    return {"T_tight_N": b.T_tight, "T_slack_N": b.T_slack, "v_tight": b.v_tight,
            "v_slack": b.v_slack, "slip_arc_driver_rad": b.slip_arc,
            "slip_arc_driven_rad": b.slip_arc, "omega_ratio": b.lam_slack / b.lam_tight,
            "max_torque_Nm": top}


def results(p: dict) -> dict:
    """Full model and capstan variant (``capstan``: an object with the same keys)."""
    return {**summary(*steady(p)), "capstan": summary(*steady(p, capstan=True))}


def _arc(b: Belt, n_in: float, sign: float, n: int):
    """Slip arc profile: n(theta) = n_in e^(sign mu theta); returns (theta, n) rad, N."""
    th = np.linspace(0.0, b.slip_arc, n)
    return th, n_in * np.exp(sign * b.mu * th)


def _pulley(b: Belt, n_in: float, sign: float, n: int):
    """(s from the pulley entry m, n N, friction on the belt N/m) over one pulley."""
    stick = b.R * (math.pi - b.slip_arc)
    th, n_arc = _arc(b, n_in, sign, n)
    s = np.concatenate([np.linspace(0.0, stick, n), stick + b.R * th])
    nn = np.concatenate([np.full(n, n_in), n_arc])
    fric = np.concatenate([np.zeros(n), -sign * b.mu * n_arc / b.R])
    return s, nn, fric


def distributions(params: dict, capstan: bool = False, n: int = 50) -> dict:
    """Arrays along the belt from the driver's entry: ``s`` (m, stretched arc length),
    ``T`` (N), ``v`` (m/s), ``normal`` and ``friction`` (N/m of stretched length; friction
    on the belt, positive along its motion).  Spans carry no contact force."""
    b, _ = steady(params, capstan)
    l_s, half = math.pi * b.R, math.pi * b.R
    s1, n1, f1 = _pulley(b, b.n_tight, -1.0, n)          # driver: n_t -> n_s
    s2, n2, f2 = _pulley(b, b.n_slack, 1.0, n)           # driven: n_s -> n_t
    span = np.linspace(0.0, l_s, n)
    s = np.concatenate([s1, half + span, half + l_s + s2, 2 * half + l_s + span])
    nn = np.concatenate([n1, np.full(n, b.n_slack), n2, np.full(n, b.n_tight)])
    zero = np.zeros(n)
    lam = (b.k + nn) / b.a
    normal = np.concatenate([n1 / b.R, zero, n2 / b.R, zero])
    return {"s": s, "T": b.k * (lam - 1.0), "v": b.v_o * lam, "normal": normal,
            "friction": np.concatenate([f1, zero, f2, zero])}
