"""Navier's double series: a simply supported rectangular Kirchhoff plate under a
uniform pressure (Timoshenko & Woinowsky-Krieger, Theory of Plates and Shells, 5.30).

Plate a x b (m), thickness h (m), ``D = E h^3 / (12 (1 - nu^2))`` (N m), pressure p
(Pa).  The centre deflection (m) is

    w_c = 16 p / (pi^6 D) sum_{m, n odd} (-1)^((m + n)/2 - 1) / (m n (m^2/a^2 + n^2/b^2)^2).

Truncation: with M = max(m, n) and L = max(a, b), every dropped term is at most
L^4 / (m n M^4) in magnitude, so the terms with M > N sum to at most
``2 L^4 int_N^inf (1 + ln x) / x^5 dx = L^4 ((1 + ln N) / (2 N^4) + 1 / (8 N^4))``;
N is raised until this bound is below ``rtol`` times the partial sum.

:func:`levy_centre_deflection` is Lévy's single series of the same problem
(5.31), an independent check of the double series.
"""
from __future__ import annotations

import math

import numpy as np

from analytic._checks import positive


def rigidity(E: float, nu: float, h: float) -> float:
    """D = E h^3 / (12 (1 - nu^2)), N m."""
    return E * h**3 / (12.0 * (1.0 - nu**2))


def tail_bound(N: int, a: float, b: float) -> float:
    """Upper bound of |sum over max(m, n) > N| of the double series (m^4)."""
    L4 = max(a, b) ** 4
    return L4 * ((1.0 + math.log(N)) / (2.0 * N**4) + 1.0 / (8.0 * N**4))


def _partial_sum(N: int, a: float, b: float) -> float:
    k = np.arange(1, N + 1, 2, dtype=float)
    m, n = k[:, None], k[None, :]
    sign = np.where(((m + n) / 2 - 1) % 2 == 0, 1.0, -1.0)
    return float(np.sum(sign / (m * n * (m**2 / a**2 + n**2 / b**2) ** 2)))


def centre_deflection(a: float, b: float, h: float, E: float, nu: float, p: float,
                      rtol: float = 1e-10) -> tuple[float, int]:
    """(w_c in m along the pressure, N the largest odd index summed) to relative
    truncation error below ``rtol``."""
    a, b, h, E, rtol = (positive(k, v) for k, v in (("a", a), ("b", b), ("h", h), ("E", E),
                                                     ("rtol", rtol)))
    N = 1
    while tail_bound(N, a, b) > rtol * abs(_partial_sum(N, a, b)):
        N += 2
    return 16.0 * p / (math.pi**6 * rigidity(E, nu, h)) * _partial_sum(N, a, b), N


def levy_centre_deflection(a: float, b: float, h: float, E: float, nu: float, p: float,
                           terms: int = 50) -> float:
    """w_c (m) from Lévy's single series (the first ``terms`` odd m)."""
    m = np.arange(1, 2 * terms, 2, dtype=float)
    al = m * math.pi * b / (2.0 * a)
    sign = np.where(((m - 1) / 2) % 2 == 0, 1.0, -1.0)
    s = np.sum(sign / m**5 * (1.0 - (al * np.tanh(al) + 2.0) / (2.0 * np.cosh(al))))
    return 4.0 * p * a**4 / (math.pi**5 * rigidity(E, nu, h)) * float(s)
