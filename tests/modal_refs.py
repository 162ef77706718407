"""Reference natural frequencies for tests/test_modes.py, kept in one place with the
signatures of the analytic modules that will replace them (``analytic/beam_modes.py``:
``euler_bernoulli``, ``timoshenko``; ``analytic/plate_modes.py``: ``navier_frequencies``).
All in Hz; ``support`` is ``"cantilever"`` (clamped at x = 0, free at L) or
``"simply-supported"``.

* Euler-Bernoulli: f_n = (beta_n L)^2 / (2 pi L^2) sqrt(E I / (rho A)), beta_n L = n pi
  (simply supported) or the roots of cos x cosh x = -1 (cantilever, by brentq).
* Timoshenko (shear and rotary inertia, Timoshenko 1921): simply supported, the lower
  root of the quadratic in omega^2 per mode number k = n pi / L,
  (rho^2 I / (ks G)) omega^4 - (rho A + rho I k^2 (1 + E / (ks G))) omega^2 + E I k^4 = 0;
  either support from the transfer matrix of the first-order form of
  ks G A (w'' - psi') + rho A omega^2 w = 0, E I psi'' + ks G A (w' - psi) + rho I omega^2 psi = 0
  (state [w, w', psi, psi'], exp(A(omega) L)), the roots of the determinant of its end
  conditions bracketed on a grid and refined by brentq; exact to 1e-8 up to L/h = 100,
  beyond which the evanescent shear waves, exp(L sqrt(ks G A / (E I))), swamp the
  determinant (1e-3 wrong at L/h = 400).
* Navier: the simply supported Kirchhoff plate, omega_mn = pi^2 ((m/a)^2 + (n/b)^2)
  sqrt(D / (rho h)), D = E h^3 / (12 (1 - nu^2)).
"""
from __future__ import annotations

import math

import numpy as np
from scipy.linalg import expm
from scipy.optimize import brentq


def _cantilever_roots(count: int) -> list[float]:
    """The first ``count`` roots of cos x cosh x = -1 (1.8751, 4.6941, ...): one in each
    interval ((n - 1/2) pi - 1, (n - 1/2) pi + 1)."""
    f = lambda x: math.cos(x) * math.cosh(x) + 1.0  # noqa: E731
    return [brentq(f, (n - 0.5) * math.pi - 1.0, (n - 0.5) * math.pi + 1.0)
            for n in range(1, count + 1)]


def euler_bernoulli(support, L, E, I, rho, A, count=3) -> list[float]:
    beta_L = ([n * math.pi for n in range(1, count + 1)] if support == "simply-supported"
              else _cantilever_roots(count))
    return [x**2 / (2.0 * math.pi * L**2) * math.sqrt(E * I / (rho * A)) for x in beta_L]


def timoshenko_simply_supported(L, E, G, I, A, rho, ks, count=3) -> list[float]:
    """The closed form (lower root of the quadratic in omega^2 per mode number)."""
    out = []
    for n in range(1, count + 1):
        k = n * math.pi / L
        a = rho**2 * I / (ks * G)
        b = -(rho * A + rho * I * k**2 * (1.0 + E / (ks * G)))
        c = E * I * k**4
        w2 = 2.0 * c / (-b + math.sqrt(b * b - 4.0 * a * c))  # the lower root, no cancellation
        out.append(math.sqrt(w2) / (2.0 * math.pi))
    return out


def _determinant(omega, support, L, E, G, I, A, rho, ks) -> float:
    kGA = ks * G * A
    P = expm(L * np.array([[0.0, 1.0, 0.0, 0.0],
                           [-rho * A * omega**2 / kGA, 0.0, 0.0, 1.0],
                           [0.0, 0.0, 0.0, 1.0],
                           [0.0, -kGA / (E * I), (kGA - rho * I * omega**2) / (E * I), 0.0]]))
    if support == "cantilever":  # w = psi = 0 at 0; moment psi' = 0, shear w' - psi = 0 at L
        return float(np.linalg.det(np.array([P[3], P[1] - P[2]])[:, [1, 3]]))
    return float(np.linalg.det(P[[0, 3]][:, [1, 2]]))  # w = psi' = 0 at both ends


def timoshenko_transfer(support, L, E, G, I, A, rho, ks, count=3) -> list[float]:
    """The roots of the end-condition determinant, bracketed on a grid of 400 points per
    Euler-Bernoulli mode up to 1.5 times the (count + 1)-th of them."""
    top = 1.5 * euler_bernoulli(support, L, E, I, rho, A, count + 1)[-1] * 2.0 * math.pi
    grid = np.linspace(top / (400 * (count + 1)), top, 400 * (count + 1))
    d = [_determinant(w, support, L, E, G, I, A, rho, ks) for w in grid]
    args = (support, L, E, G, I, A, rho, ks)
    roots = [brentq(_determinant, grid[i], grid[i + 1], args=args)
             for i in range(grid.size - 1) if np.sign(d[i]) != np.sign(d[i + 1])]
    return [w / (2.0 * math.pi) for w in roots[:count]]


def timoshenko(support, L, E, G, I, A, rho, ks, count=3) -> list[float]:
    if support == "simply-supported":
        return timoshenko_simply_supported(L, E, G, I, A, rho, ks, count)
    return timoshenko_transfer(support, L, E, G, I, A, rho, ks, count)


def navier_frequencies(a, b, h, E, nu, rho, count=4):
    """(frequencies (count,) ascending, [(m, n)] their half-wave numbers)."""
    D = E * h**3 / (12.0 * (1.0 - nu**2))
    modes = sorted((math.pi / 2.0 * ((m / a) ** 2 + (n / b) ** 2) * math.sqrt(D / (rho * h)),
                    (m, n)) for m in range(1, count + 1) for n in range(1, count + 1))[:count]
    return [f for f, _ in modes], [mn for _, mn in modes]
