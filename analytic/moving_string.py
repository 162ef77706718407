"""Transverse natural frequencies of an axially moving string span (Wickert & Mote,
Classical vibration analysis of axially moving continua, J. Appl. Mech. 57 (1990) 738-744).

A span of length L (m) between two fixed guides, tension T (N), mass per unit length
rho_A (kg/m), travelling at v (m/s): the transverse displacement w(x, t) obeys

    rho_A (w_tt + 2 v w_xt + v^2 w_xx) - T w_xx = 0,   w(0, t) = w(L, t) = 0,

whose free vibrations have the frequencies (Hz)

    f_n = n c (1 - v^2 / c^2) / (2 L),   c = sqrt(T / rho_A),   n = 1, 2, ...

(each mode a wave pair travelling at c + v and c - v).  They exist for |v| < c only: at
|v| >= c no transverse wave travels upstream, the span loses its restoring stiffness
(T - rho_A v^2 <= 0, divergence at v = c) and has no free vibration.
"""
from __future__ import annotations

import math

import numpy as np

from analytic._checks import finite, magnitude, mode_count, positive


def wave_speed(T: float, rho_A: float, L: float) -> float:
    """c = sqrt(T / rho_A) (m/s) after checking T, rho_A, L > 0 and c / L within
    [1e-300, 1e300] (ValueError naming the field otherwise)."""
    T, rho_A, L = positive("T", T), positive("rho_A", rho_A), positive("L", L)
    magnitude("the frequency scale sqrt(T / rho_A) / L", {"T": (T, 0.5), "rho_A": (rho_A, -0.5),
                                                          "L": (L, -1)})
    return math.sqrt(T) / math.sqrt(rho_A)


def check_speed(T: float, rho_A: float, v: float, L: float) -> float:
    """c (m/s), or ValueError naming v when |v| >= c (no free vibration, see the module doc)."""
    c = wave_speed(T, rho_A, L)
    v = finite("v", v)
    if abs(v) >= c:
        raise ValueError(f"v = {v!r} is out of range: allowed |v| < c = sqrt(T / rho_A) = "
                         f"{c:.6g} m/s (at |v| >= c no transverse wave travels upstream: the "
                         "span has no free vibration)")
    return c


def span_frequencies(T: float, rho_A: float, v: float, L: float, count: int = 3) -> np.ndarray:
    """The first ``count`` transverse frequencies of the span (Hz, ascending)."""
    count = mode_count("count", count)
    c = check_speed(T, rho_A, v, L)
    beta = v / c
    f1 = c * (1.0 - beta) * (1.0 + beta) / (2.0 * L)
    return np.arange(1, count + 1) * f1
