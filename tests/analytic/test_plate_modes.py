"""Simply supported plate frequencies (analytic.plate_modes, issue 24 item 2) against two
independent methods: the finite-difference biharmonic eigenproblem (the 5-point Laplacian
with w = 0 on the edges, squared: simple support), Richardson-extrapolated from 40 and 80
intervals along a; and the Rayleigh quotient of each listed (m, n) sine mode, the plate's
full bending energy (with the nu terms) integrated by Gauss-Legendre quadrature."""
import json
import math

import numpy as np
import pytest
import scipy.sparse as sp
import scipy.sparse.linalg as spl

from analytic import plate_modes as pm

STEEL = dict(h=0.01, E=2.07e11, nu=0.3, rho=7850.0)
#: the extrapolated differences reach 2e-6 (6 modes, both plates)
TOL_FD = 3e-6


def _rigidity(E, nu, h):
    return E * h**3 / (12.0 * (1.0 - nu**2))


def _finite_differences(a, b, h, E, nu, rho, n, count):
    """The lowest ``count`` frequencies (Hz) of D (Lap_h)^2 w = rho h omega^2 w, n intervals
    along a and the nearest whole number along b."""
    nb = int(round(n * b / a))
    dx, dy = a / n, b / nb

    def second(m, d):
        return sp.diags([np.ones(m - 2), -2.0 * np.ones(m - 1), np.ones(m - 2)], [-1, 0, 1]) / d**2

    lap = sp.kronsum(second(n, dx), second(nb, dy), format="csc")
    lam = spl.eigsh((lap @ lap).tocsc(), k=count, sigma=0, return_eigenvectors=False)
    return np.sort(np.sqrt(lam * _rigidity(E, nu, h) / (rho * h))) / (2.0 * math.pi)


def _rayleigh(a, b, h, E, nu, rho, m, n, points=64):
    """Frequency (Hz) of the Rayleigh quotient of w = sin(m pi x / a) sin(n pi y / b):
    D int (w_xx + w_yy)^2 - 2 (1 - nu) (w_xx w_yy - w_xy^2) / (rho h int w^2)."""
    g, wt = np.polynomial.legendre.leggauss(points)
    x, y = np.meshgrid(a * (g + 1) / 2, b * (g + 1) / 2, indexing="ij")
    W = np.outer(wt, wt) * a * b / 4
    kx, ky = m * math.pi / a, n * math.pi / b
    w = np.sin(kx * x) * np.sin(ky * y)
    wxx, wyy = -kx**2 * w, -ky**2 * w
    wxy = kx * ky * np.cos(kx * x) * np.cos(ky * y)
    strain = (wxx + wyy) ** 2 - 2 * (1 - nu) * (wxx * wyy - wxy**2)
    omega2 = _rigidity(E, nu, h) * np.sum(W * strain) / (rho * h * np.sum(W * w**2))
    return math.sqrt(omega2) / (2.0 * math.pi)


@pytest.mark.parametrize("a, b", [(1.0, 1.0), (1.0, 0.7)])
def test_navier_equals_the_extrapolated_finite_differences(a, b):
    f, _ = pm.navier_frequencies(a, b, count=6, **STEEL)
    coarse, fine = (_finite_differences(a, b, n=n, count=6, **STEEL) for n in (40, 80))
    assert np.all(np.diff(f) >= 0)
    assert (4 * fine - coarse) / 3 == pytest.approx(f, rel=TOL_FD)
    assert fine != pytest.approx(f, rel=TOL_FD)  # the extrapolation is what gets there
    heavier, _ = pm.navier_frequencies(a, b, count=6, **{**STEEL, "rho": 1.01 * STEEL["rho"]})
    assert (4 * fine - coarse) / 3 != pytest.approx(heavier, rel=TOL_FD)


@pytest.mark.parametrize("a, b", [(1.0, 1.0), (1.0, 0.7), (0.3, 2.0)])
def test_each_listed_mode_is_its_rayleigh_quotient(a, b):
    f, mn = pm.navier_frequencies(a, b, count=8, **STEEL)
    assert [_rayleigh(a, b, m=m, n=n, **STEEL) for m, n in mn] == pytest.approx(f, rel=1e-12)
    assert len(set(mn)) == 8
    if a == b:  # equal frequencies ordered by m
        assert mn[:4] == [(1, 1), (1, 2), (2, 1), (2, 2)] and f[1] == f[2]


def test_bad_input_names_the_field():
    with pytest.raises(ValueError, match=r"^nu must be in \(-1, 0.5\)"):
        pm.navier_frequencies(1.0, 1.0, **{**STEEL, "nu": 0.5})
    with pytest.raises(ValueError, match=r"^count must be an integer >= 1"):
        pm.navier_frequencies(1.0, 1.0, count=2.5, **STEEL)
    with pytest.raises(ValueError, match=r"^b = 1e-200 is out of range: the frequency scale"):
        pm.navier_frequencies(1.0, 1e-200, **STEEL)


def test_cli_plate_modes(capsys):
    from ancf.cli import main
    assert main(["analytic", "plate-modes", "--set", "b=0.7", "--set", "count=5", "--json"]) == 0
    out = json.loads(capsys.readouterr().out)
    p, res = out["params"], out["results"]
    f, mn = pm.navier_frequencies(p["a"], p["b"], p["h"], p["E"], p["nu"], p["rho"], count=5)
    assert res["frequencies_hz"] == f.tolist() and list(zip(res["m"], res["n"])) == mn
    assert main(["analytic", "plate-modes", "--set", "rho=0"]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and err[0].startswith("error: rho = 0")


def test_free_plate_ritz_series_converges_from_above_to_exudyns_published_ratios():
    """The free square plate (nu = 0.3) by the Ritz series: each ratio falls as the
    Legendre degree grows from 8 to 12 to 16 (a Ritz space grows: values from above, to
    1e-9); from 16 to 24 the ratios agree to 1e-7, where degree 24's round-off (its mass
    matrix is ill-conditioned) moves them by up to 1.2e-8 either way, depending on the BLAS
    build; and they equal the ratios Exudyn's TestModels/ANCFThinPlateTests.py prints
    (1.364614, 1.985504, 2.459086) within one unit of their last digit."""
    series = np.array([pm.free_ratios(0.3, 3, d) for d in (8, 12, 16, 24)])
    assert np.all(np.diff(series[:3], axis=0) <= 1e-9)
    assert np.abs(series[-1] / series[-2] - 1.0).max() < 1e-7
    assert np.abs(series[-1] - np.array([1.364614, 1.985504, 2.459086])).max() < 1e-6


def test_free_plate_ritz_ratios_follow_the_aspect_and_nu():
    """A 1 x 2 free plate with b = 2 a is the 2 x 1 plate with the axes swapped: its
    ratios, scaled by (a / b)^2 = 1/4 to the other side, agree; nu = 0 raises the first
    (twisting) mode, whose energy is mostly the twist term 2 (1 - nu) w_xy^2."""
    long = pm.free_ratios(0.3, 3, 16, aspect=2.0)
    wide = pm.free_ratios(0.3, 3, 16, aspect=0.5)
    assert long == pytest.approx(wide / 4.0, rel=1e-8)  # round-off: 1.4e-9
    assert pm.free_ratios(0.0, 1, 16)[0] > 1.1 * pm.free_ratios(0.3, 1, 16)[0]
