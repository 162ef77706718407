"""Moving-string span frequencies (analytic.moving_string, issue 24 item 2) against a
Galerkin discretisation of rho_A (w_tt + 2 v w_xt + v^2 w_xx) - T w_xx = 0 on N sine modes:
the gyroscopic system M q'' + G q' + K q = 0 (M, G, K by Gauss-Legendre quadrature), its
frequencies the eigenvalues of the first-order form (scipy.linalg.eigvals).  The exact
modes are sines modulated by travelling waves, so the sine basis converges algebraically,
like N^-3 (v/c = 0.79: 6e-6 at N = 40, 7e-7 at N = 80), and Richardson's extrapolation
(8 f_80 - f_40) / 7 reaches 5e-8."""
import json
import math

import numpy as np
import pytest
import scipy.linalg as sl

from analytic import moving_string as ms

STRING = dict(T=1000.0, rho_A=1.0, L=1.0)  # c = 31.6 m/s
N, TOL = 80, 1e-7


def _galerkin(T, rho_A, v, L, modes, count):
    x, w = np.polynomial.legendre.leggauss(2 * modes + 2)
    x, w = (x + 1) * L / 2, w * L / 2
    j = np.arange(1, modes + 1)[:, None]
    phi, dphi = np.sin(j * np.pi * x / L), j * np.pi / L * np.cos(j * np.pi * x / L)
    M = rho_A * (phi * w) @ phi.T
    G = 2 * rho_A * v * (phi * w) @ dphi.T  # int phi_i phi_j' (skew)
    K = (T - rho_A * v**2) * (dphi * w) @ dphi.T  # -int phi_i phi_j'' by parts
    Z, Id = np.zeros((modes, modes)), np.eye(modes)
    ev = sl.eigvals(np.block([[Z, Id], [-np.linalg.solve(M, K), -np.linalg.solve(M, G)]]))
    return np.sort(ev.imag[ev.imag > 0])[:count] / (2.0 * math.pi)


@pytest.mark.parametrize("v", [0.0, 10.0, -25.0])
def test_span_frequencies_equal_the_galerkin_gyroscopic_eigenproblem(v):
    f = ms.span_frequencies(v=v, count=3, **STRING)
    coarse, fine = (_galerkin(v=v, modes=n, count=3, **STRING) for n in (N // 2, N))
    extrapolated = (8 * fine - coarse) / 7
    assert extrapolated == pytest.approx(f, rel=TOL)
    if v:  # the error falls like N^-3: halving N costs a factor 8 (7 to 9)
        assert fine != pytest.approx(f, rel=TOL)
        assert np.all((7 < (coarse - f) / (fine - f)) & ((coarse - f) / (fine - f) < 9))
    heavier = ms.span_frequencies(v=v, count=3, **{**STRING, "rho_A": 1.01})
    assert extrapolated != pytest.approx(heavier, rel=TOL)


def test_at_or_above_the_wave_speed_there_is_no_free_vibration():
    c = math.sqrt(STRING["T"] / STRING["rho_A"])
    assert ms.span_frequencies(v=0.999 * c, **STRING)[0] > 0
    for v in (c, -1.5 * c):
        with pytest.raises(ValueError, match=rf"^v = .* is out of range: allowed \|v\| < c = "
                                             rf"sqrt\(T / rho_A\) = {c:.6g} m/s .*upstream"):
            ms.span_frequencies(v=v, **STRING)
    with pytest.raises(ValueError, match=r"^T must be > 0"):
        ms.span_frequencies(v=0.0, **{**STRING, "T": -1.0})


def test_cli_moving_string(capsys):
    from ancf.cli import main
    assert main(["analytic", "moving-string", "--set", "count=4", "--json"]) == 0
    out = json.loads(capsys.readouterr().out)
    p, res = out["params"], out["results"]
    assert res["frequencies_hz"] == ms.span_frequencies(p["T"], p["rho_A"], p["v"], p["L"],
                                                        count=4).tolist()
    assert main(["analytic", "moving-string", "--set", "v=-40"]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and err[0].startswith("error: v = -40.0 is out of range: allowed |v| < c")


def test_cli_defaults_are_the_thesis_belt():
    """The defaults typed in ancf.scenes.analytic are belt_common's Table 3.1 values."""
    from ancf.scenes.analytic import REFERENCES
    from ancf.scenes.belt_common import R1, X_CENTRE, belt_params
    belt = {p.name: p.default for p in belt_params()}
    p = REFERENCES["moving-string"].resolve({})
    assert (p["rho_A"], p["v"], p["L"]) == (belt["rho"] * belt["h"] * belt["b"], 120.0 * R1,
                                            2.0 * X_CENTRE)
