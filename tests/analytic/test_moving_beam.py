"""Moving-beam span frequencies (analytic.moving_beam) against independent references:

* Galerkin discretisations of rho_A (w_tt + 2 v w_xt + v^2 w_xx) - T w_xx + EI w_xxxx = 0,
  the gyroscopic system M q'' + G q' + K q = 0 (Gauss-Legendre quadrature), frequencies the
  eigenvalues of its first-order form (scipy.linalg.eigvals).  Sine modes (pinned): the
  exact modes have w'''' = -2 rho_A v w_xt / EI != 0 at the ends, so the odd extension jumps
  in its 4th derivative and the error falls like N^-5 (1e-7 at N = 64).  Polynomials
  x (L - x) P_j or x^2 (L - x)^2 P_j (P_j Legendre; pinned, clamped): spectral, 1e-13 at
  N = 24.
* v = 0, pinned: w = sin(n pi x / L), omega_n = (n pi / L) sqrt((T + EI (n pi / L)^2) / rho_A).
* EI -> 0: the moving string (analytic.moving_string).  Pinned ends differ by O(EI / (T L^2))
  (v = 0: n^2 pi^2 EI / (2 T L^2)); clamped ends by O(sqrt(EI)): a boundary layer of width
  delta = sqrt(EI / (T - rho_A v^2)) at each end shortens the span to L - 2 delta, so
  f / f_string - 1 -> 2 delta / L (v = 9.75 m/s, EI = 1e-10 T L^2: 2.10654 sqrt(EI / (T L^2))
  seen, 2 delta / L = 2.10640 sqrt(EI / (T L^2)) predicted).
* The critical speed: the smallest rho_A v^2 making the Galerkin stiffness K singular, and
  f_1 ~ sqrt(v_c - v) as v -> v_c.
"""
import math

import numpy as np
import pytest
import scipy.linalg as sl
from numpy.polynomial import legendre as leg

from analytic import moving_beam as mb
from analytic import moving_string as ms

BELT = dict(T=100.0, rho_A=0.1036, L=0.382882, EI=0.0208)  # v_c = 31.3 m/s (pinned)
SPEEDS = [0.0, 9.75, 25.0, -30.0]


def _sines(xi, modes):
    """phi_j = sin(j pi xi) and its first two xi-derivatives, shape (modes, len(xi))."""
    q = np.arange(1, modes + 1)[:, None] * np.pi
    return np.sin(q * xi), q * np.cos(q * xi), -q * q * np.sin(q * xi)


def _bubbles(power):
    """phi_j = (xi (1 - xi))^power P_j(2 xi - 1) and two xi-derivatives (product rule)."""
    def basis(xi, modes):
        b = [np.polynomial.Polynomial([0, 1, -1]) ** power]
        b += [b[0].deriv(), b[0].deriv(2)]
        b = [p(xi) for p in b]
        c = np.eye(modes)
        p = [np.array([2.0 ** m * leg.legval(2 * xi - 1, leg.legder(ci, m)) for ci in c])
             for m in range(3)]
        return b[0] * p[0], b[1] * p[0] + b[0] * p[1], b[2] * p[0] + 2 * b[1] * p[1] + b[0] * p[2]
    return basis


def _matrices(T, rho_A, L, EI, basis, modes):
    """String stiffness S = int phi' phi', bending B = int phi'' phi'', mass M, and
    C = int phi phi' (1/m-scaled, x = L xi)."""
    xi, w = leg.leggauss(2 * modes + 10)
    xi, w = (xi + 1) / 2, w * L / 2
    phi, d1, d2 = basis(xi, modes)
    d1, d2 = d1 / L, d2 / L**2
    return (phi * w) @ phi.T, (phi * w) @ d1.T, (d1 * w) @ d1.T, (d2 * w) @ d2.T


def _galerkin(T, rho_A, v, L, EI, basis, modes, count=3):
    M, C, S, B = _matrices(T, rho_A, L, EI, basis, modes)
    K = (T - rho_A * v**2) * S + EI * B
    Z, Id = np.zeros((modes, modes)), np.eye(modes)
    ev = sl.eigvals(np.block([[Z, Id], [-K, -2 * rho_A * v * C]]),
                    np.block([[Id, Z], [Z, rho_A * M]]))
    return np.sort(ev.imag[ev.imag > 0])[:count] / (2.0 * math.pi)


@pytest.mark.parametrize("v", SPEEDS)
def test_pinned_frequencies_equal_the_sine_galerkin_eigenproblem(v):
    f = mb.span_frequencies(v=v, **BELT)
    err = {n: _galerkin(v=v, basis=_sines, modes=n, **BELT) / f - 1 for n in (16, 32, 64)}
    assert np.max(np.abs(err[64])) < 1e-6
    if v:  # N^-5: halving N multiplies the error by about 32 (seen 25 to 30)
        assert np.all((16 < err[16] / err[32]) & (err[16] / err[32] < 64))
    heavier = mb.span_frequencies(v=v, **{**BELT, "rho_A": 1.00001 * BELT["rho_A"]})
    assert np.max(np.abs(f / heavier - 1)) > 1e-6


@pytest.mark.parametrize("ends, power", [("pinned", 1), ("clamped", 2)])
@pytest.mark.parametrize("v", SPEEDS)
def test_frequencies_equal_the_polynomial_galerkin_eigenproblem(ends, power, v):
    f = mb.span_frequencies(v=v, count=3, ends=ends, **BELT)
    g = _galerkin(v=v, basis=_bubbles(power), modes=24, **BELT)
    assert g == pytest.approx(f, rel=1e-10)
    stiffer = mb.span_frequencies(v=v, ends=ends, **{**BELT, "EI": 1.000001 * BELT["EI"]})
    assert g != pytest.approx(stiffer, rel=1e-10)


def test_at_rest_pinned_frequencies_are_the_closed_form():
    T, rho_A, L, EI = BELT.values()
    q = np.arange(1, 7) * np.pi / L
    closed = q * np.sqrt((T + EI * q * q) / rho_A) / (2 * math.pi)
    assert mb.span_frequencies(v=0.0, count=6, **BELT) == pytest.approx(closed, rel=1e-12)
    stiffer = mb.span_frequencies(v=0.0, count=6, **{**BELT, "EI": 1.000001 * EI})
    assert stiffer != pytest.approx(closed, rel=1e-12)


@pytest.mark.parametrize("v", SPEEDS[:3])
def test_without_bending_stiffness_the_span_is_the_moving_string(v):
    T, rho_A, L, _ = BELT.values()
    EI = 1e-10 * T * L * L
    string = ms.span_frequencies(T, rho_A, v, L, count=3)
    pinned, clamped = (mb.span_frequencies(T, rho_A, v, L, EI, ends=e) for e in mb.ENDS)
    assert pinned == pytest.approx(string, rel=1e-6)
    shortening = 2 * math.sqrt(EI / (T - rho_A * v * v)) / L  # 2 delta / L, 2.1e-5 at v = 0
    # next order O(EI / (T L^2)) relative to the shortening: seen up to 2e-3 (v = 25, n = 3)
    assert clamped / string - 1 == pytest.approx(np.full(3, shortening), rel=5e-3)
    assert clamped != pytest.approx(string, rel=1e-6)


@pytest.mark.parametrize("ends, power", [("pinned", 1), ("clamped", 2)])
def test_first_frequency_vanishes_at_the_critical_speed(ends, power):
    T, rho_A, L, EI = BELT.values()
    v_c = mb.critical_speed(T, rho_A, L, EI, ends)
    _, _, S, B = _matrices(T, rho_A, L, EI, _bubbles(power), 24)
    buckling = sl.eigh(T * S + EI * B, S, eigvals_only=True)[0]  # K = 0 at rho_A v^2 = this
    assert rho_A * v_c**2 == pytest.approx(buckling, rel=1e-12)
    f1 = [mb.span_frequencies(v=v, count=1, ends=ends, **BELT)[0]
          for v in v_c * np.array([0, 0.3, 0.6, 0.9, 0.99, 0.999, 1 - 1e-5, 1 - 1e-7])]
    assert np.all(np.diff(f1) < 0) and f1[5] < 0.02 * f1[0]  # seen 0.011 at 0.999 v_c
    # f_1 ~ sqrt(v_c - v): seen 0.09998; a v_c off by 1e-6 relative would give 0.32
    assert f1[-1] / f1[-2] == pytest.approx(0.1, rel=1e-3)
    with pytest.raises(ValueError, match=rf"^v = .* is out of range: allowed \|v\| < v_c = "
                                         rf"{v_c:.6g} m/s"):
        mb.span_frequencies(v=-v_c, ends=ends, **BELT)


@pytest.mark.parametrize("field, value, message", [
    ("v", math.nan, r"^v must be finite"),
    ("v", 40.0, r"^v = 40.0 is out of range: allowed \|v\| < v_c"),
    ("ends", "free", r"^ends = 'free' is out of range: allowed 'pinned' or 'clamped'"),
    ("T", 0.0, r"^T must be > 0"),
    ("rho_A", -1.0, r"^rho_A must be > 0"),
    ("L", "x", r"^L must be a real number"),
    ("EI", 0.0, r"^EI must be > 0"),
    ("EI", 1e-12, r"^EI = 1e-12 is out of range: T L\^2 / EI = .* allowed EI >= "),
    ("count", 0, r"^count must be an integer >= 1"),
])
def test_bad_inputs_raise_naming_the_field(field, value, message):
    args = {**BELT, "v": 9.75, "count": 3, "ends": "pinned", field: value}
    with pytest.raises(ValueError, match=message):
        mb.span_frequencies(**args)
