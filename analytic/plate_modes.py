"""Natural frequencies of a simply supported rectangular Kirchhoff plate (Navier's
solution; Leissa, Vibration of Plates, NASA SP-160, 1969, chapter 4).

Plate a x b (m), thickness h (m), Young's modulus E (Pa), Poisson's ratio nu (-), density
rho (kg/m^3), D = E h^3 / (12 (1 - nu^2)) (N m).  D (w_xxxx + 2 w_xxyy + w_yyyy) =
rho h omega^2 w with w = 0 and zero edge moment on all four edges is solved by
w = sin(m pi x / a) sin(n pi y / b), m, n = 1, 2, ...:

    omega_mn = pi^2 (m^2 / a^2 + n^2 / b^2) sqrt(D / (rho h))   (rad/s),  f = omega / (2 pi).

The lowest ``count`` frequencies have m <= count and n <= count (for a fixed n, the count
modes (1..count, n) lie below any m > count), so that grid is sorted; equal frequencies
(the square's (1, 2) and (2, 1)) are ordered by m, then n.

The completely free rectangle has no closed form; :func:`free_ratios` gives its lowest
elastic frequencies by the Rayleigh-Ritz method (Leissa, chapter 4.6) on the products
P_i(xi) P_j(eta) of Legendre polynomials up to ``degree`` on [-1, 1]^2 (complete for the
free plate, no boundary condition to impose: the Ritz values converge from above as the
degree grows), the energy D/2 int (w_xx^2 + w_yy^2 + 2 nu w_xx w_yy + 2 (1 - nu) w_xy^2)
and the kinetic energy rho h/2 omega^2 int w^2 integrated exactly by Gauss-Legendre
quadrature; the three rigid motions (1, xi, eta) are the zero eigenvalues dropped.  The
frequencies come as ratios omega / (pi^2 / a^2 sqrt(D / (rho h))), Exudyn's
(``TestModels/ANCFThinPlateTests.py``) normalisation, which depend on nu and b / a only.
"""
from __future__ import annotations

import math

import numpy as np

from analytic._checks import finite, magnitude, mode_count, positive


def check_magnitudes(a: float, b: float, h: float, E: float, nu: float, rho: float) -> float:
    """sqrt(D / (rho h)) / s^2 (rad/s, s the shorter side) after checking every field
    (ValueError naming it: out of range, or a derived quantity outside [1e-300, 1e300])."""
    a, b, h, E, rho = (positive(k, v) for k, v in
                       (("a", a), ("b", b), ("h", h), ("E", E), ("rho", rho)))
    nu = finite("nu", nu)
    if not -1.0 < nu < 0.5:
        raise ValueError(f"nu must be in (-1, 0.5) (got {nu!r})")
    short = "a" if a <= b else "b"
    c = 1.0 / (12.0 * (1.0 - nu**2))
    magnitude("the bending rigidity D = E h^3 / (12 (1 - nu^2))", {"h": (h, 3), "E": (E, 1)}, c)
    return math.sqrt(magnitude(
        f"the frequency scale squared D / (rho h {short}^4)",
        {"E": (E, 1), "h": (h, 2), "rho": (rho, -1), short: (min(a, b), -4)}, c))


def navier_frequencies(a: float, b: float, h: float, E: float, nu: float, rho: float,
                       count: int = 4) -> tuple[np.ndarray, list[tuple[int, int]]]:
    """(the lowest ``count`` frequencies in Hz, ascending; their (m, n) half-wave numbers
    along a and b)."""
    count = mode_count("count", count)
    scale = check_magnitudes(a, b, h, E, nu, rho)
    s = min(a, b)
    modes = [(m, n) for m in range(1, count + 1) for n in range(1, count + 1)]
    key = {mn: (mn[0] * s / a) ** 2 + (mn[1] * s / b) ** 2 for mn in modes}
    modes = sorted(modes, key=lambda mn: (key[mn], mn))[:count]
    freqs = np.array([key[mn] for mn in modes]) * math.pi**2 * scale / (2.0 * math.pi)
    return freqs, modes


#: rigid motions of the free plate (translation and two tilts): the Ritz zero eigenvalues
FREE_RIGID = 3


def _legendre_1d(degree: int) -> tuple:
    """(int P_i P_j, int P_i' P_j', int P_i'' P_j'', int P_i'' P_j) over [-1, 1], exact."""
    from numpy.polynomial import legendre as L
    g, w = L.leggauss(degree + 2)
    eye = np.eye(degree + 1)
    vals = [np.array([L.legval(g, L.legder(c, k)) for c in eye]) for k in range(3)]
    gram = lambda u, v: (u * w) @ v.T  # noqa: E731
    return gram(vals[0], vals[0]), gram(vals[1], vals[1]), gram(vals[2], vals[2]), \
        gram(vals[2], vals[0])


def free_ratios(nu: float, count: int = 4, degree: int = 16, aspect: float = 1.0) -> np.ndarray:
    """The lowest ``count`` elastic frequencies of the free a x b plate (b = aspect a) as
    ratios omega / (pi^2 / a^2 sqrt(D / (rho h))), ascending (Ritz, Legendre degree
    ``degree`` per direction)."""
    count = mode_count("count", count)
    nu, aspect = finite("nu", nu), positive("aspect", aspect)
    m0, m1, m2, a20 = _legendre_1d(degree)
    sx, sy = 2.0, 2.0 / aspect  # d/dx = (2 / a) d/dxi with a = 1; d/dy = (2 / b) d/deta
    K = (sx**4 * np.kron(m2, m0) + sy**4 * np.kron(m0, m2)
         + nu * sx**2 * sy**2 * (np.kron(a20, a20.T) + np.kron(a20.T, a20))
         + 2.0 * (1.0 - nu) * sx**2 * sy**2 * np.kron(m1, m1))
    import scipy.linalg as sla
    lam = sla.eigh(K, np.kron(m0, m0), eigvals_only=True,
                   subset_by_index=[FREE_RIGID, FREE_RIGID + count - 1])
    return np.sqrt(lam) / math.pi**2
