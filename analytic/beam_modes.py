"""Natural frequencies of a straight uniform beam, Euler-Bernoulli and Timoshenko, for two
supports: ``"cantilever"`` (clamped at x = 0, free at x = L) and ``"simply-supported"``
(pinned at both ends).  SI units: L (m), E and G (Pa), I (m^4), A (m^2), rho (kg/m^3),
ks (-); frequencies in Hz, ascending.

Euler-Bernoulli (Timoshenko & Young, Vibration Problems in Engineering):
EI w'''' = rho A omega^2 w, w = sum of cos, sin, cosh, sinh (beta x), and the boundary
conditions give the frequency equations

    cantilever:        cos(beta L) cosh(beta L) = -1
    simply supported:  sin(beta L) = 0
    omega_n = (beta_n L)^2 sqrt(E I / (rho A L^4)),

whose roots are found by Brent's method, root n bracketed in [(n-1) pi, n pi] (the
cantilever, written cos x + 1/cosh x = 0) or [(n-1/2) pi, (n+1/2) pi].

Timoshenko (Huang, J. Appl. Mech. 28 (1961) 579-584; Han, Benaroya & Wei, J. Sound Vib.
225 (1999) 935-988), deflection w and section rotation psi:

    ks G A (w'' - psi') + rho A omega^2 w = 0
    E I psi'' + ks G A (w' - psi) + rho I omega^2 psi = 0.

In xi = x / L and Omega = omega / omega_0, omega_0 = sqrt(E I / (rho A L^4)), with the
slenderness r^2 = I / (A L^2) and e = E / (ks G), w ~ exp(s xi) gives for lambda = s^2

    lambda^2 + Omega^2 r^2 (1 + e) lambda + Omega^2 (Omega^2 r^4 e - 1) = 0,

two real roots: lambda_- < 0 always (cos, sin (beta xi), beta^2 = -lambda_-), and
lambda_+ > 0 below the cut-off Omega_c = 1 / (r^2 sqrt(e)) (omega_c = sqrt(ks G A /
(rho I)); exp(+-alpha xi)), lambda_+ < 0 above it (cos, sin (alpha xi): the second
spectrum).  Each exponential carries psi L = (lambda + mu) / s w, mu = Omega^2 r^2 e.

* Simply supported: w = sin(n pi xi) solves it for k = n pi, the closed form
  r^4 e Omega^4 - (r^2 (1 + e) k^2 + 1) Omega^2 + k^4 = 0, two roots per n (the lower one
  the bending spectrum, the upper one at or above Omega_c the second spectrum); n = 0
  adds the shear mode w = 0, psi = const exactly at Omega_c.
* Cantilever: the 4 x 4 determinant of w(0) = 0, psi(0) = 0, psi'(L) = 0, w'(L) = psi(L)
  on that basis (exp(-alpha xi), exp(alpha (xi - 1)): entries bounded for any alpha L),
  scanned in Omega with steps of at most pi/16 in beta and alpha (read off the simply
  supported dispersion relation), its sign changes refined by Brent's method.  Below and
  above the cut-off the basis differs, so the scan stops at Omega_c (1 -+ 1e-9) on both
  sides: both spectra are found, merged in ascending order; a mode within 1e-9 of the
  cut-off, or two modes closer than the scan step, are not resolved.  The shear row
  L (w' - psi) = -mu / s w is written out (w' and psi nearly cancel in a slender beam).
  :func:`determinant_roots` also takes the simply supported rows (w = psi' = 0 at both
  ends): the tests' cross-check of the closed form.
"""
from __future__ import annotations

import math

import numpy as np
from scipy.optimize import brentq

from analytic._checks import magnitude, mode_count, positive

SUPPORTS = ("cantilever", "simply-supported")
STEPS_PER_PI = 16  # scan points per pi of phase along the beam (determinant method)
CUTOFF_GAP = 1e-9  # relative gap left on both sides of the cut-off by the scan
RTOL = 1e-15  # Brent's relative tolerance (scipy's floor: 4 machine epsilon)


def _check(support: str, count, **fields) -> int:
    """``count`` as an int after checking ``support``, ``count`` and that each field is > 0
    (ValueError naming the field otherwise)."""
    if support not in SUPPORTS:
        raise ValueError(f"support must be one of {', '.join(SUPPORTS)} (got {support!r})")
    for k, v in fields.items():
        positive(k, v)
    return mode_count("count", count)


def scale(L: float, E: float, I: float, rho: float, A: float) -> float:
    """omega_0 = sqrt(E I / (rho A L^4)) (rad/s), its magnitude checked."""
    return math.sqrt(magnitude("the frequency scale E I / (rho A L^4)",
                               {"E": (E, 1), "I": (I, 1), "rho": (rho, -1), "A": (A, -1),
                                "L": (L, -4)}))


def _clamped_free(x: float) -> float:
    """cos x + 1 / cosh x, written without overflow: zero where cos x cosh x = -1."""
    return math.cos(x) + 2.0 * math.exp(-x) / (1.0 + math.exp(-2.0 * x))


def euler_bernoulli(support: str, L: float, E: float, I: float, rho: float, A: float,
                    count: int = 3) -> np.ndarray:
    """The first ``count`` natural frequencies (Hz, ascending) of the Euler-Bernoulli beam."""
    count = _check(support, count, L=L, E=E, I=I, rho=rho, A=A)
    f, shift = (_clamped_free, 1.0) if support == "cantilever" else (math.sin, 0.5)
    roots = [brentq(f, (n - shift) * math.pi, (n + 1 - shift) * math.pi, xtol=1e-15, rtol=RTOL)
             for n in range(1, count + 1)]
    return np.array(roots) ** 2 * scale(L, E, I, rho, A) / (2.0 * math.pi)


def groups(L: float, E: float, G: float, I: float, A: float, ks: float) -> tuple:
    """(r^2 = I / (A L^2), e = E / (ks G)), their magnitudes checked."""
    r2 = magnitude("the slenderness I / (A L^2)", {"I": (I, 1), "A": (A, -1), "L": (L, -2)})
    e = magnitude("the ratio E / (ks G)", {"E": (E, 1), "ks": (ks, -1), "G": (G, -1)})
    return r2, e


def cutoff(r2: float, e: float) -> float:
    """Omega_c = 1 / (r^2 sqrt(e)): omega_c = sqrt(ks G A / (rho I)) over omega_0."""
    return 1.0 / (r2 * math.sqrt(e))


def simply_supported(r2: float, e: float, k: float) -> tuple[float, float]:
    """(Omega_1, Omega_2): both roots of the closed form for the wave number k (per unit
    xi); Omega_2 is inf where it overflows, far above every mode sought."""
    B = r2 * (1.0 + e) * k**2 + 1.0
    root = math.sqrt((r2 * (1.0 - e) * k**2) ** 2 + 2.0 * r2 * (1.0 + e) * k**2 + 1.0)
    low = math.sqrt(2.0 * k**4 / (B + root))  # B^2 - 4 r^4 e k^4, without cancellation
    return low, cutoff(r2, e) * math.sqrt((B + root) / 2.0)


def _lambdas(r2: float, e: float, om: float) -> tuple[float, float, float]:
    """(lambda_+, lambda_-, mu) at Omega = om."""
    B = om**2 * r2 * (1.0 + e)
    C = om**2 * (om**2 * r2**2 * e - 1.0)
    root = math.sqrt((om**2 * r2 * (1.0 - e)) ** 2 + 4.0 * om**2)  # B^2 - 4 C
    return -2.0 * C / (B + root), -(B + root) / 2.0, om**2 * r2 * e


def _columns(lam: float, mu: float, xi: float) -> list:
    """For the two solutions of lambda: (w, L psi, L^2 psi', L (w' - psi)) at xi, per
    solution."""
    f = lam + mu
    if lam > 0:
        a = math.sqrt(lam)
        u, v = math.exp(-a * xi), math.exp(a * (xi - 1.0))
        return [(u, -f / a * u, f * u, mu / a * u), (v, f / a * v, f * v, -mu / a * v)]
    k = math.sqrt(-lam)
    c, s = math.cos(k * xi), math.sin(k * xi)
    return [(c, f * s / k, f * c, -mu * s / k), (s, -f * c / k, f * s, mu * c / k)]


def determinant(support: str, r2: float, e: float, om: float) -> float:
    """The frequency determinant at Omega = om (zero at a natural frequency; columns
    scaled to unit largest entry, which keeps its sign)."""
    lp, lm, mu = _lambdas(r2, e, om)
    rows = []
    for lam in (lp, lm):
        for (w0, p0, m0, _), (w1, p1, m1, q1) in zip(_columns(lam, mu, 0.0),
                                                      _columns(lam, mu, 1.0)):
            col = (w0, p0, m1, q1) if support == "cantilever" else (w0, m0, w1, m1)
            rows.append(np.array(col) / max(map(abs, col)))
    return float(np.linalg.det(np.array(rows).T))


def _scan_grid(r2: float, e: float, j_max: int) -> np.ndarray:
    """Omega where beta (lower branch) or alpha (upper branch) is a multiple of
    pi / STEPS_PER_PI, up to j_max multiples."""
    ks = np.arange(1, j_max + 1) * math.pi / STEPS_PER_PI
    both = [simply_supported(r2, e, k) for k in ks]
    return np.unique([om for pair in both for om in pair if math.isfinite(om)])


def determinant_roots(support: str, r2: float, e: float, count: int) -> np.ndarray:
    """The lowest ``count`` zeros of :func:`determinant` (Omega), both spectra."""
    oc = cutoff(r2, e)
    j_max = STEPS_PER_PI * (count + 2)
    while True:
        grid = _scan_grid(r2, e, j_max)
        below, above = grid[grid < oc], grid[grid > oc]
        parts = [np.append(below, oc * (1 - CUTOFF_GAP))]
        if above.size:
            parts.append(np.insert(above, 0, oc * (1 + CUTOFF_GAP)))
        roots = []
        for part in parts:
            d = [determinant(support, r2, e, om) for om in part]
            roots += [brentq(lambda om: determinant(support, r2, e, om), part[i], part[i + 1],
                             xtol=1e-14 * part[i], rtol=RTOL)
                      for i in range(len(part) - 1) if d[i] * d[i + 1] < 0]
        if len(roots) >= count:
            return np.sort(roots)[:count]
        j_max *= 2


def timoshenko(support: str, L: float, E: float, G: float, I: float, A: float, rho: float,
               ks: float, count: int = 3) -> np.ndarray:
    """The first ``count`` natural frequencies (Hz, ascending) of the Timoshenko beam,
    both spectra merged (see the module doc for what is done at and above the cut-off)."""
    count = _check(support, count, L=L, E=E, G=G, I=I, A=A, rho=rho, ks=ks)
    om0 = scale(L, E, I, rho, A)
    r2, e = groups(L, E, G, I, A, ks)
    if support == "cantilever":
        om = determinant_roots(support, r2, e, count)
    else:
        pairs = [simply_supported(r2, e, n * math.pi) for n in range(1, count + 1)]
        om = np.sort([cutoff(r2, e)] + [w for pair in pairs for w in pair])[:count]
    return om * om0 / (2.0 * math.pi)


def section(E: float, nu: float, h: float, b: float) -> tuple[float, float, float]:
    """(I = b h^3 / 12, A = b h, G = E / (2 (1 + nu))) of a rectangular section."""
    return b * h**3 / 12.0, b * h, E / (2.0 * (1.0 + nu))


def check_section(E: float, nu: float, L: float, h: float, b: float, rho: float,
                  ks: float) -> None:
    """ValueError naming the field (h, b, ...) when a quantity the frequencies rest on
    leaves [1e-300, 1e300]: I, A, the frequency scale, the slenderness and E / (ks G)."""
    for k, v in dict(E=E, L=L, h=h, b=b, rho=rho, ks=ks).items():
        positive(k, v)
    magnitude("the second moment of area I = b h^3 / 12", {"h": (h, 3), "b": (b, 1)}, 1 / 12)
    magnitude("the area A = b h", {"h": (h, 1), "b": (b, 1)})
    magnitude("the frequency scale E h^2 / (12 rho L^4)",
              {"E": (E, 1), "h": (h, 2), "rho": (rho, -1), "L": (L, -4)}, 1 / 12)
    magnitude("the slenderness h^2 / (12 L^2)", {"h": (h, 2), "L": (L, -2)}, 1 / 12)
    magnitude("the ratio E / (ks G) = 2 (1 + nu) / ks", {"ks": (ks, -1)}, 2.0 * (1.0 + nu))
