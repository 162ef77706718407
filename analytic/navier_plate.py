"""Centre deflection of a simply supported rectangular Kirchhoff plate under a uniform
pressure (Timoshenko & Woinowsky-Krieger, Theory of Plates and Shells, 5.30-5.31).

Plate a x b (m), thickness h (m), ``D = E h^3 / (12 (1 - nu^2))`` (N m), pressure p
(Pa).  Navier's double series of the centre deflection (m),

    w_c = 16 p / (pi^6 D) sum_{m, n odd} (-1)^((m + n)/2 - 1) / (m n (m^2/a^2 + n^2/b^2)^2),

is summed over n in closed form (Lévy's single series, 5.31): with s = min(a, b) the
shorter side, r = max(a, b) / s >= 1 and alpha_m = m pi r / 2,

    w_c = 4 p s^4 / (pi^5 D) [5 pi^5 / 1536 - sum_{m odd} (-1)^((m-1)/2) c(alpha_m) / m^5],
    c(alpha) = (alpha tanh(alpha) + 2) / (2 cosh(alpha))
             = (alpha tanh(alpha) + 2) e^(-alpha) / (1 + e^(-2 alpha)),

where 5 pi^5 / 1536 = sum_{m odd} (-1)^((m-1)/2) / m^5 (Dirichlet's beta(5)) and c is
written with e^(-alpha) alone, so nothing overflows for any aspect ratio (c -> 0 as
r -> inf: the infinite strip).  Summing along the shorter side makes alpha_m >= m pi / 2,
so the terms fall at least like e^(-m pi / 2): the cost is bounded independently of the
aspect ratio (at most about 25 terms at rtol = 1e-14).

Truncation: (alpha + 2) e^(-alpha) bounds c and decreases in alpha, and the bound of term
m + 2 is at most 3 e^(-pi) < 0.13 times that of term m, so after the last summed term M
the rest is at most ``t(M + 2) / (1 - 3 e^(-pi))`` with t(m) = (alpha_m + 2) e^(-alpha_m)
/ m^5; terms are added until this is below ``rtol`` times the bracket.  ``terms`` (the
second value returned, ``terms`` / ``navier_terms`` in the CLI's JSON) counts the odd m
summed in the correction series (it used to be the largest odd index of the truncated
double series; both are the number of series terms the value rests on along one index).

Inputs whose derived quantities leave double precision (D, s^4, p s^4 / D outside
[1e-300, 1e300]) are refused up front with a ValueError naming the field
(:func:`check_magnitudes`).
"""
from __future__ import annotations

import math

import numpy as np

from analytic._checks import finite, magnitude, positive

BETA5 = 5.0 * math.pi**5 / 1536.0  # sum over odd m of (-1)^((m-1)/2) / m^5
MAX_TERMS = 200  # never reached: alpha_m >= m pi / 2 ends the sum well before
_RATIO = 1.0 / (1.0 - 3.0 * math.exp(-math.pi))


def rigidity(E: float, nu: float, h: float) -> float:
    """D = E h^3 / (12 (1 - nu^2)), N m."""
    return E * h**3 / (12.0 * (1.0 - nu**2))


def check_magnitudes(a: float, b: float, h: float, E: float, nu: float, p: float) -> tuple:
    """(s, r, D, p s^4 / D) after checking that each is a normal double (ValueError naming
    the field otherwise): s the shorter side, r = longer / shorter."""
    a, b, h, E = (positive(k, v) for k, v in (("a", a), ("b", b), ("h", h), ("E", E)))
    nu, p = finite("nu", nu), finite("p", p)
    if not -1.0 < nu < 0.5:
        raise ValueError(f"nu must be in (-1, 0.5) (got {nu!r})")
    short = "a" if a <= b else "b"
    s, r = min(a, b), max(a, b) / min(a, b)
    c = 1.0 / (12.0 * (1.0 - nu**2))
    D = magnitude("the bending rigidity D = E h^3 / (12 (1 - nu^2))",
                  {"h": (h, 3), "E": (E, 1)}, c)
    magnitude(f"the shorter side to the fourth, {short}^4", {short: (s, 4)})
    scale = magnitude(f"the deflection scale p {short}^4 / D", {
        "p": (p, 1), short: (s, 4), "h": (h, -3), "E": (E, -1)}, 1.0 / c)
    return s, r, D, scale


def _c(alpha: float) -> float:
    """(alpha tanh(alpha) + 2) / (2 cosh(alpha)) without overflow."""
    if alpha > 745.0:  # e^(-alpha) is 0 in double precision
        return 0.0
    e1, e2 = math.exp(-alpha), math.exp(-2.0 * alpha)
    return (alpha * (1.0 - e2) / (1.0 + e2) + 2.0) * e1 / (1.0 + e2)


def _bound(alpha: float, m: int) -> float:
    if alpha > 745.0:
        return 0.0
    return (alpha + 2.0) * math.exp(-alpha) / m**5


def centre_deflection(a: float, b: float, h: float, E: float, nu: float, p: float,
                      rtol: float = 1e-10) -> tuple[float, int]:
    """(w_c in m along the pressure, the number of odd m summed in Lévy's correction
    series) to relative truncation error below ``rtol`` (see the module doc)."""
    rtol = positive("rtol", rtol)
    s, r, D, scale = check_magnitudes(a, b, h, E, nu, p)
    a1 = math.pi / 2.0 * r  # alpha_1 >= pi / 2; may be inf for r near the overflow
    corr, terms, m = 0.0, 0, 1
    while terms < MAX_TERMS:
        alpha = m * a1
        sign = 1.0 if (m // 2) % 2 == 0 else -1.0
        corr += sign * _c(alpha) / m**5
        terms += 1
        m += 2
        if _bound(m * a1, m) * _RATIO <= rtol * (BETA5 - corr):
            break
    bracket = BETA5 - corr
    return 4.0 / math.pi**5 * scale * bracket, terms


def coefficient(b_over_a: float, rtol: float = 1e-14) -> float:
    """alpha in w_c = alpha p a^4 / D (Timoshenko's Table 8), for the side ratio b / a >= 1."""
    w, _ = centre_deflection(1.0, b_over_a, 1.0, 12.0, 0.0, 1.0, rtol=rtol)  # D = 1, p = 1
    return w


def levy_centre_deflection(a: float, b: float, h: float, E: float, nu: float, p: float,
                           terms: int = 50) -> float:
    """w_c (m) from Lévy's single series as printed (the first ``terms`` odd m, summed
    along a with hyperbolic functions of m pi b / (2 a); overflows for b >> a): a
    cross-check of :func:`centre_deflection` at moderate aspect ratios."""
    m = np.arange(1, 2 * terms, 2, dtype=float)
    al = m * math.pi * b / (2.0 * a)
    sign = np.where(((m - 1) / 2) % 2 == 0, 1.0, -1.0)
    s = np.sum(sign / m**5 * (1.0 - (al * np.tanh(al) + 2.0) / (2.0 * np.cosh(al))))
    return 4.0 * p * a**4 / (math.pi**5 * rigidity(E, nu, h)) * float(s)
