"""Transverse natural frequencies of an axially moving tensioned beam span (Wickert & Mote,
Classical vibration analysis of axially moving continua, J. Appl. Mech. 57 (1990) 738-744).

A belt's free span of length L (m), tension T (N), bending stiffness EI (N m^2), mass per
unit length rho_A (kg/m), travelling at v (m/s): the transverse displacement w(x, t) obeys

    rho_A (w_tt + 2 v w_xt + v^2 w_xx) - T w_xx + EI w_xxxx = 0                      (1)

with both ends ``"pinned"`` (w = w_xx = 0) or ``"clamped"`` (w = w_x = 0) at x = 0, L.

Exact frequencies.  In xi = x / L, k = kappa L (kappa the wavenumber, 1/m) and the
dimensionless frequency Omega = omega L^2 sqrt(rho_A / EI), with the tension and speed
parameters tau = T L^2 / EI and V = v L sqrt(rho_A / EI), w = exp(i (k xi + Omega s)),
s = t sqrt(EI / rho_A) / L^2, solves (1) when (d/ds, d/dxi: w_ss -> -Omega^2,
w_xis -> -k Omega, w_xixi -> -k^2, w_xixixixi -> k^4)

    k^4 + (tau - V^2) k^2 - 2 V Omega k - Omega^2 = 0,                               (2)

four roots k_j(Omega) (polished by Newton's method).  w = sum_j c_j exp(i k_j (xi - 1/2))
meets the four end conditions when the 4 x 4 boundary determinant D(Omega) vanishes:

    pinned:  rows exp(-+ i k_j / 2), k_j^2 exp(-+ i k_j / 2)
    clamped: rows exp(-+ i k_j / 2), k_j   exp(-+ i k_j / 2)                         (3)

D is antisymmetric in the k_j, so F = D / prod_{i<j} (k_j - k_i) is a symmetric (root-order
free) analytic function of the coefficients of (2), and since those are real, conjugating
(3) only swaps the rows of the two ends (two transpositions): F is real.  Each column is
scaled by exp(-|Im k_j| / 2) / (1 + |k_j|^2) > 0 (entries bounded, sign of F kept).  F is
scanned from Omega ~ 0 upward in steps of 1/20 of the smallest gap between the estimates

    Omega_n ~ n pi (tau + q_n^2 - V^2) / sqrt(tau + q_n^2),  q_n = (n + d) pi          (4)

(d = 0 pinned, exact at V = 0; d = 1 clamped), and its sign changes refined by Brent's
method; f_n = Omega_n sqrt(EI / rho_A) / (2 pi L^2) (Hz).

Critical speed.  At omega = 0, (1) is the Euler buckling problem EI w'''' + (rho_A v^2 - T)
w'' = 0, whose first load is pi^2 EI / L^2 (pinned) or 4 pi^2 EI / L^2 (clamped):

    rho_A v_c^2 = T + pi^2 EI / L^2 (pinned),   T + 4 pi^2 EI / L^2 (clamped).       (5)

Below v_c the stiffness int ((T - rho_A v^2) w'^2 + EI w''^2) dx is positive definite and
the gyroscopic span vibrates freely; at |v| >= v_c it diverges (no free vibration).
tau is limited to 1e12 (bending layers sqrt(EI / T) down to 1e-6 L).
"""
from __future__ import annotations

import math

import numpy as np
from scipy.optimize import brentq

from analytic._checks import finite, magnitude, mode_count, positive
from analytic.moving_string import wave_speed

ENDS = {"pinned": 0, "clamped": 1}  # d of eq. (4); the buckling load is (1 + d)^2 pi^2 EI / L^2
TAU_MAX = 1e12
STEPS_PER_GAP = 20


def _check_ends(ends) -> int:
    if ends not in ENDS:
        raise ValueError(f"ends = {ends!r} is out of range: allowed 'pinned' or 'clamped'")
    return ENDS[ends]


def _tau(T: float, rho_A: float, L: float, EI: float) -> float:
    """tau = T L^2 / EI after checking T, rho_A, L, EI > 0 and the scales (ValueError)."""
    wave_speed(T, rho_A, L)
    EI = positive("EI", EI)
    magnitude("the frequency scale sqrt(EI / rho_A) / L^2",
              {"EI": (EI, 0.5), "rho_A": (rho_A, -0.5), "L": (L, -2)})
    tau = magnitude("T L^2 / EI", {"T": (T, 1), "L": (L, 2), "EI": (EI, -1)})
    if tau > TAU_MAX:
        raise ValueError(f"EI = {EI!r} is out of range: T L^2 / EI = {tau:.3g} exceeds "
                         f"{TAU_MAX:.0e} (bending layers below 1e-6 L); allowed EI >= "
                         f"{T * L * L / TAU_MAX:.6g} N m^2")
    return tau


def critical_speed(T: float, rho_A: float, L: float, EI: float, ends: str = "pinned") -> float:
    """v_c (m/s) of eq. (5): the speed at which the first frequency falls to zero."""
    d = _check_ends(ends)
    _tau(T, rho_A, L, EI)
    return math.sqrt((T + (1 + d) ** 2 * math.pi ** 2 * EI / L ** 2) / rho_A)


def _wavenumbers(tau: float, V: float, Om: np.ndarray) -> np.ndarray:
    """The four roots k of eq. (2) for each Omega (shape (n, 4)), Newton-polished."""
    n = Om.size
    comp = np.zeros((n, 4, 4))
    comp[:, 1:, :3] = np.eye(3)
    comp[:, 0, 1], comp[:, 0, 2], comp[:, 0, 3] = V * V - tau, 2 * V * Om, Om * Om
    k = np.linalg.eigvals(comp)
    a, b, c = tau - V * V, (2 * V * Om)[:, None], (Om * Om)[:, None]
    for _ in range(3):
        dq = 4 * k ** 3 + 2 * a * k - b
        step = np.divide(k ** 4 + a * k * k - b * k - c, dq, out=np.zeros_like(k), where=dq != 0)
        k = k - step
    return k


def _boundary_function(tau: float, V: float, d: int, Om) -> np.ndarray:
    """F(Omega) of the module doc: real, zero at the natural frequencies."""
    Om = np.atleast_1d(np.asarray(Om, dtype=float))
    k = _wavenumbers(tau, V, Om)
    g = 1.0 / (1.0 + np.abs(k) ** 2)
    em = np.exp(-0.5j * k - 0.5 * np.abs(k.imag)) * g
    ep = np.exp(0.5j * k - 0.5 * np.abs(k.imag)) * g
    p = k ** (2 - d)
    D = np.linalg.det(np.stack([em, p * em, ep, p * ep], axis=1))
    i, j = np.triu_indices(4, 1)
    return (D / np.prod(k[:, j] - k[:, i], axis=1)).real


def _frequency_estimates(tau: float, V: float, d: int, count: int) -> np.ndarray:
    """Omega_n of eq. (4), n = 1 .. count."""
    n = np.arange(1, count + 1)
    t = tau + ((n + d) * np.pi) ** 2
    return n * np.pi * (t - V * V) / np.sqrt(t)


def _scan(F, lo: float, step: float, count: int) -> list:
    """The first ``count`` sign changes of F above ``lo``: a geometric grid up to ``step``,
    then a uniform one, each bracket refined by Brent's method."""
    roots, grid = [], np.geomspace(lo, step, 40)
    while len(roots) < count:
        vals = F(grid)
        for a, b, fa, fb in zip(grid[:-1], grid[1:], vals[:-1], vals[1:]):
            if fb == 0 or fa * fb < 0:
                roots.append(b if fb == 0 else
                             brentq(lambda x: F(x)[0], a, b, xtol=1e-300, rtol=1e-15))
        grid = grid[-1] + step * np.arange(0, 200)
    return roots[:count]


def span_frequencies(T: float, rho_A: float, v: float, L: float, EI: float, count: int = 3,
                     ends: str = "pinned") -> np.ndarray:
    """The first ``count`` transverse frequencies of the span (Hz, ascending), exact (eqs.
    (2)-(3)); ValueError naming v when |v| >= critical_speed (eq. (5))."""
    count = mode_count("count", count)
    v_c = critical_speed(T, rho_A, L, EI, ends)
    v = finite("v", v)
    if abs(v) >= v_c:
        raise ValueError(f"v = {v!r} is out of range: allowed |v| < v_c = {v_c:.6g} m/s, "
                         f"rho_A v_c^2 = T + {(1 + ENDS[ends]) ** 2} pi^2 EI / L^2 ({ends} "
                         "ends; at |v| >= v_c the span diverges: no free vibration)")
    tau, d, V = _tau(T, rho_A, L, EI), ENDS[ends], v * L * math.sqrt(rho_A / EI)
    est = _frequency_estimates(tau, V, d, count + 1)
    step = np.min(np.diff(est)) / STEPS_PER_GAP
    Om = _scan(lambda x: _boundary_function(tau, V, d, x), 1e-3 * min(est[0], step), step, count)
    return np.sort(Om) * math.sqrt(EI / rho_A) / (2 * math.pi * L * L)
