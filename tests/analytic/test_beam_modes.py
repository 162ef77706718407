"""Beam frequencies (analytic.beam_modes, issue 24 item 2) against a second, independent
method: Chebyshev collocation of the Euler-Bernoulli and Timoshenko eigenproblems
(scipy.linalg.eig of K v = Omega^2 M v, boundary conditions in place of the ODE's rows at
the two ends), the simply supported closed form against the frequency determinant, and the
Timoshenko beam tending to Euler-Bernoulli as L/h grows.  Steel, 0.1 x 0.1 m section."""
import json
import math

import numpy as np
import pytest
import scipy.linalg as sl

from analytic import beam_modes as bm

E, NU, RHO, KS = 2.07e11, 0.3, 7850.0, 5.0 / 6.0
#: collocation points and the agreement they reach (largest relative difference seen:
#: Euler-Bernoulli 9e-9 with 30 points, the fourth derivative's round-off growing beyond;
#: Timoshenko 6e-10 at L/h = 20 and 7e-12 at L/h = 2 with 40 points)
N_EB, TOL_EB = 30, 2e-8
N_TIMO, TOL_TIMO = 40, 2e-9


def _beam(L):
    I, A, G = bm.section(E, NU, 0.1, 0.1)
    return dict(L=L, E=E, I=I, rho=RHO, A=A), G


def _cheb(N):
    """Chebyshev points mapped to xi in [0, 1] (xi[0] = 0) and d/dxi (Trefethen, Spectral
    Methods in MATLAB, cheb.m)."""
    x = np.cos(np.pi * np.arange(N + 1) / N)
    c = np.r_[2.0, np.ones(N - 1), 2.0] * (-1.0) ** np.arange(N + 1)
    X = np.tile(x, (N + 1, 1)).T
    D = np.outer(c, 1 / c) / (X - X.T + np.eye(N + 1))
    D -= np.diag(D.sum(axis=1))
    return (1 - x) / 2, -2 * D


def _finite_omegas(K, M, count):
    lam = sl.eig(K, M, right=False)
    lam = lam[np.isfinite(lam)].real
    return np.sort(np.sqrt(lam[lam > 0]))[:count]


def _collocation_eb(support, count, N=N_EB):
    """Omega = omega / omega_0 of w'''' = Omega^2 w on xi in [0, 1]."""
    _, D = _cheb(N)
    Id, D2 = np.eye(N + 1), D @ D
    K, M = D2 @ D2, Id.copy()
    rows = {"cantilever": [(0, Id[0]), (1, D[0]), (N - 1, D2[N]), (N, (D2 @ D)[N])],
            "simply-supported": [(0, Id[0]), (1, D2[0]), (N - 1, D2[N]), (N, Id[N])]}[support]
    for i, r in rows:
        K[i], M[i] = r, 0.0
    return _finite_omegas(K, M, count)


def _collocation_timoshenko(support, r2, e, count, N=N_TIMO):
    """Omega of w'' - P' = -Omega^2 r2 e w, r2 e P'' + w' - P = -Omega^2 r2^2 e P (P = L psi;
    the Timoshenko equations over k_s G A / L^2 and E I / L^3, r2 = I / (A L^2),
    e = E / (k_s G), Omega = omega / sqrt(E I / (rho A L^4)))."""
    _, D = _cheb(N)
    Id, Z, n = np.eye(N + 1), np.zeros((N + 1, N + 1)), N + 1
    K = -np.block([[D @ D, -D], [D, r2 * e * D @ D - Id]])
    M = np.block([[r2 * e * Id, Z], [Z, r2**2 * e * Id]])
    w, P = (lambda row: np.r_[row, Z[0]]), (lambda row: np.r_[Z[0], row])
    rows = {"cantilever": [(0, w(Id[0])), (n, P(Id[0])), (2 * n - 1, P(D[N])),
                           (N, np.r_[D[N], -Id[N]])],  # w = psi = 0; psi' = 0, w' = psi
            "simply-supported": [(0, w(Id[0])), (n, P(D[0])), (N, w(Id[N])),
                                 (2 * n - 1, P(D[N]))]}[support]
    for i, r in rows:
        K[i], M[i] = r, 0.0
    return _finite_omegas(K, M, count)


@pytest.mark.parametrize("support", bm.SUPPORTS)
def test_euler_bernoulli_equals_collocation(support):
    beam, _ = _beam(2.0)
    om0 = bm.scale(**beam)
    f = bm.euler_bernoulli(support, **beam, count=6)
    ref = _collocation_eb(support, 6) * om0 / (2 * math.pi)
    assert np.all(np.diff(f) > 0)
    assert f == pytest.approx(ref, rel=TOL_EB)
    heavier = bm.euler_bernoulli(support, **{**beam, "rho": 1.01 * RHO}, count=6)
    assert heavier != pytest.approx(ref, rel=TOL_EB)  # the check can fail


@pytest.mark.parametrize("L, count", [(2.0, 6), (0.2, 8)])  # L/h = 20; L/h = 2 (second spectrum)
@pytest.mark.parametrize("support", bm.SUPPORTS)
def test_timoshenko_equals_collocation(support, L, count):
    beam, G = _beam(L)
    om0 = bm.scale(**beam)
    r2, e = bm.groups(L, E, G, beam["I"], beam["A"], KS)
    f = bm.timoshenko(support, L, E, G, beam["I"], beam["A"], RHO, KS, count=count)
    ref = _collocation_timoshenko(support, r2, e, count) * om0 / (2 * math.pi)
    assert f == pytest.approx(ref, rel=TOL_TIMO)
    cut = bm.cutoff(r2, e) * om0 / (2 * math.pi)
    assert bool(f[-1] > cut) is (L == 0.2)  # the thick beam's list reaches the second spectrum
    heavier = bm.timoshenko(support, L, E, G, beam["I"], beam["A"], 1.01 * RHO, KS, count=count)
    assert heavier != pytest.approx(ref, rel=TOL_TIMO)


def test_simply_supported_closed_form_equals_its_determinant():
    """Both methods on the thick beam (L/h = 2), 8 modes on both sides of the cut-off; the
    closed form's shear mode exactly at the cut-off (w = 0) is the one the determinant,
    whose basis degenerates there, leaves out."""
    beam, G = _beam(0.2)
    r2, e = bm.groups(0.2, E, G, beam["I"], beam["A"], KS)
    pairs = [bm.simply_supported(r2, e, n * math.pi) for n in range(1, 9)]
    closed = np.sort([w for p in pairs for w in p])[:8]
    det = bm.determinant_roots("simply-supported", r2, e, 8)
    assert det == pytest.approx(closed, rel=1e-12)
    assert closed[0] < bm.cutoff(r2, e) < closed[-1]
    om0 = bm.scale(**beam)
    f = bm.timoshenko("simply-supported", 0.2, E, G, beam["I"], beam["A"], RHO, KS, count=9)
    assert bm.cutoff(r2, e) * om0 / (2 * math.pi) in f


def test_timoshenko_tends_to_euler_bernoulli_as_the_beam_grows_slender():
    """1 - f_T / f_EB shrinks like (h / L)^2: simply supported, it equals the first-order
    correction (n pi)^2 r^2 (1 + E / (k_s G)) / 2 (rotary inertia and shear) to 5e-5 at
    L/h = 1000; the cantilever's (1 - f_T / f_EB) (L/h)^2 is the same at L/h = 1000 and
    10 000 to 5e-5 (seen: 3e-5 and 2.3e-5, mode 3)."""
    scaled = {}
    for Lh in (1000, 10000):
        beam, G = _beam(0.1 * Lh)
        r2, e = bm.groups(beam["L"], E, G, beam["I"], beam["A"], KS)
        for support in bm.SUPPORTS:
            ratio = (bm.timoshenko(support, beam["L"], E, G, beam["I"], beam["A"], RHO, KS)
                     / bm.euler_bernoulli(support, **beam))
            scaled[support, Lh] = (1 - ratio) * Lh**2
            if support == "simply-supported" and Lh == 1000:
                first_order = (np.arange(1, 4) * math.pi) ** 2 * r2 * (1 + e) / 2
                assert 1 - ratio == pytest.approx(first_order, rel=5e-5)
    assert scaled["cantilever", 1000] == pytest.approx(scaled["cantilever", 10000], rel=5e-5)


def test_bad_input_names_the_field():
    beam, G = _beam(2.0)
    with pytest.raises(ValueError, match="^support must be one of cantilever, simply-supported"):
        bm.euler_bernoulli("clamped", **beam)
    with pytest.raises(ValueError, match=r"^count must be an integer >= 1 \(got 0\)"):
        bm.timoshenko("cantilever", 2.0, E, G, beam["I"], beam["A"], RHO, KS, count=0)
    with pytest.raises(ValueError, match=r"^rho must be > 0"):
        bm.euler_bernoulli("cantilever", **{**beam, "rho": 0.0})
    with pytest.raises(ValueError, match=r"^L = 1e-80 is out of range: the frequency scale"):
        bm.euler_bernoulli("cantilever", **{**beam, "L": 1e-80})


def test_cli_beam_modes(capsys):
    """`ancf analytic beam-modes --json`: the functions' values at the defaults (steel
    cantilever, 2 m, 0.1 x 0.1 m); bad input is one error line naming the field."""
    from ancf.cli import main
    assert main(["analytic", "beam-modes", "--set", "support=simply-supported", "--json"]) == 0
    out = json.loads(capsys.readouterr().out)
    p, res = out["params"], out["results"]
    beam, G = _beam(2.0)
    assert (p["E"], p["nu"], p["rho"], p["L"], p["count"]) == (E, NU, RHO, 2.0, 3)
    assert res["frequencies_hz"] == bm.timoshenko("simply-supported", 2.0, E, G, beam["I"],
                                                  beam["A"], RHO, KS).tolist()
    assert res["euler_bernoulli_hz"] == bm.euler_bernoulli("simply-supported", **beam).tolist()
    assert main(["analytic", "beam-modes", "--set", "h=1e-200"]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and err[0].startswith("error: h = 1e-200 is out of range")
