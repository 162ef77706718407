"""The steady belt span with bending stiffness (analytic.belt_span_bending, solve_bvp on the
string's frame) against independent references:

* EI -> 0: the common tangent of the two circles, tilted by gamma = asin((r1 - r2) / D)
  from the centre line, and a uniform axial force N1.
* The linear boundary layer: a beam under tension P with end curvature 1 / r,
  EI w'''' = P w'', leaves the circle over the length lambda = sqrt(EI / P), so kappa =
  e^(-s / lambda) / r and the tangent turns by lambda / r: the departure shift
  delta -> sqrt(EI / P1) / r, the ratio of shifts at EI and EI / 4 -> 2.
* The exact elastica boundary layer (isolated: terms of e^(-l / lambda) neglected).  With
  phi the tangent angle from the straight part's direction and |F| the constant effective
  force, EI phi'' = |F| sin phi has the first integral EI phi'^2 / 2 = |F| (1 - cos phi),
  so at the pulley (phi' = 1 / r_i, |phi| = delta_i): sin(delta_i / 2) = lambda / (2 r_i),
  lambda^2 = EI / |F|, and P1 = |F| cos delta1 closes it: sin^2(delta1 / 2) = c / (1 + 2 c),
  c = EI / (4 r1^2 P1).  Across the layer the belt moves off the centre by
  int sin phi ds = int lambda cos(phi / 2) dphi = lambda^2 / r_i, so the straight part is
  the common tangent of circles of radii r_i + lambda^2 / (2 r_i); the span is longer than
  its chord by int (1 - cos phi) ds = 2 lambda (1 - cos(delta_i / 2)) per layer, and the
  axial force in the middle is |F| + G v, by eq. (3).
* Two-sided shooting: solve_ivp (DOP853) from the departure point forward and from the
  arrival point backward to the middle, scipy.optimize.root on (alpha1, Q1, alpha2, l).
"""
import math

import numpy as np
import pytest
from scipy.integrate import solve_ivp
from scipy.optimize import root

from analytic import belt_span_bending as bsb
from ancf.scenes.belt_common import R1, X_CENTRE, belt_params

_BELT = {p.name: p.default for p in belt_params()}
#: the thesis drive: pulleys (Table 3.1), rhoA = rho h b, v = 120 rad/s on R1; the brief's
#: departure force (N) and bending stiffness (N m^2)
THESIS = dict(c1=(-X_CENTRE, 0.0), r1=R1, c2=(X_CENTRE, 0.0), r2=R1, N1=100.0,
              rhoA=_BELT["rho"] * _BELT["h"] * _BELT["b"], v=120.0 * R1)
EI_BRIEF = 0.0208
#: unequal pulleys, tilted centre line, an extensible belt
TILTED = dict(THESIS, r2=0.5 * R1, c2=(X_CENTRE, 0.6 * R1), EA=1e4)
#: solve_bvp against the shooting method (the brief's 1e-6; we see up to 1.5e-10)
SAME = 1e-6


def _P1(g):
    """Effective tension at departure, N (independent of bsb.effective_tension)."""
    vo = g["v"] / (1 + g["N1"] / g.get("EA", math.inf))
    return g["N1"] - g["rhoA"] * vo * vo * (1 + g["N1"] / g.get("EA", math.inf))


def _axial(g, P):
    """Axial force N (N) at effective tension P: N1 plus the change of P over 1 - G v_o / EA."""
    vo = g["v"] / (1 + g["N1"] / g.get("EA", math.inf))
    return g["N1"] + (P - _P1(g)) / (1 - g["rhoA"] * vo * vo / g.get("EA", math.inf))


def _tangent_angle(c1, r1, c2, r2):
    """Direction (rad) of the common tangent leaving circle 1 with both circles on its left."""
    dx, dy = np.subtract(c2, c1)
    return math.atan2(dy, dx) + math.asin((r1 - r2) / math.hypot(dx, dy))


def _closed_form(g, EI):
    """Isolated elastica boundary layers (module doc): layer angles delta, contact angles,
    shifts from the string's tangent points, length, mean N, lambda, direction phi, |F|."""
    P1, (r1, r2) = _P1(g), (g["r1"], g["r2"])
    c = EI / (4 * r1 * r1 * P1)
    d1 = 2 * math.asin(math.sqrt(c / (1 + 2 * c)))
    F = P1 / math.cos(d1)
    lam = math.sqrt(EI / F)
    d2 = 2 * math.asin(lam / (2 * r2))
    phi = _tangent_angle(g["c1"], r1 + lam**2 / (2 * r1), g["c2"], r2 + lam**2 / (2 * r2))
    a1, a2 = phi - math.pi / 2 - d1, phi - math.pi / 2 + d2
    string = _tangent_angle(g["c1"], r1, g["c2"], r2) - math.pi / 2
    p1, p2 = (np.add(g[c], g[r] * np.array([math.cos(a), math.sin(a)]))
              for c, r, a in (("c1", "r1", a1), ("c2", "r2", a2)))
    ell = (p2 - p1) @ [math.cos(phi), math.sin(phi)] + 2 * lam * (
        2 - math.cos(d1 / 2) - math.cos(d2 / 2))
    return dict(delta=(d1, d2), angles=(a1, a2), shifts=(string - a1, a2 - string),
                length=ell, tension=_axial(g, F), lam=lam, phi=phi, F=F)


def test_string_limit_is_the_common_tangent_with_uniform_force():
    EI = 1e-9
    for g in (THESIS, TILTED):
        r = bsb.span(EI=EI, **g)
        phi = _tangent_angle(g["c1"], g["r1"], g["c2"], g["r2"])
        m = np.array([math.sin(phi), -math.cos(phi)])  # outward normal at the tangent points
        tol = 2 * math.sqrt(EI / _P1(g))  # twice the boundary layer's shift of the points
        for c, rad, a in (("c1", "r1", "departure"), ("c2", "r2", "arrival")):
            got = np.add(g[c], g[rad] * np.array([math.cos(r[f"{a}_angle_rad"]),
                                                   math.sin(r[f"{a}_angle_rad"])]))
            assert np.hypot(*(got - g[c] - g[rad] * m)) < tol
        assert np.max(np.abs(r["axial_force_N"] / g["N1"] - 1)) < 1e-6
        assert r["x_m"][[0, -1]] == pytest.approx([g["c1"][0] + g["r1"] * m[0],
                                                   g["c2"][0] + g["r2"] * m[0]], abs=tol)
    stiffer = bsb.span(EI=100 * EI, **THESIS)  # the check can fail: 10 times the shift
    assert R1 * stiffer["departure_shift_rad"] > 4 * math.sqrt(EI / _P1(THESIS))


def test_small_shifts_follow_the_linear_boundary_layer():
    """delta / (sqrt(EI / P1) / r) = 1 - 5 x^2 / 24 + O(x^4), x = sqrt(EI / P1) / r (the
    closed form's series): within x^2 / 4 of 1, the deviation shrinking like x^2."""
    x, dev, shift = [], [], []
    for k in range(3):
        EI = EI_BRIEF / 4**k
        r = bsb.span(EI=EI, **THESIS)
        x.append(math.sqrt(EI / _P1(THESIS)) / R1)
        shift.append(r["departure_shift_rad"])
        dev.append(shift[-1] / x[-1] - 1)
        assert abs(dev[-1]) < x[-1] ** 2 / 4
        assert r["arrival_shift_rad"] == pytest.approx(shift[-1], rel=1e-9)  # symmetric
    assert dev[0] / dev[1] == pytest.approx(4, rel=x[0] ** 2)
    assert shift[0] / shift[1] == pytest.approx(2, rel=x[0] ** 2 / 4)
    assert shift[0] / shift[1] != pytest.approx(math.sqrt(2), rel=x[0] ** 2 / 4)


@pytest.mark.parametrize("g", [THESIS, TILTED], ids=["thesis", "tilted-extensible"])
def test_the_exact_isolated_boundary_layers(g):
    """Nonlinear elastica layers: 1e-8 (e^(-l / lambda) < 1e-10 here; we see up to 5e-11)."""
    tol = 1e-8
    ref, r = _closed_form(g, EI_BRIEF), bsb.span(EI=EI_BRIEF, **g)
    assert math.exp(-r["length_m"] / ref["lam"]) < 1e-10
    assert [r["departure_shift_rad"], r["arrival_shift_rad"]] == pytest.approx(ref["shifts"],
                                                                               rel=tol)
    assert [r["departure_angle_rad"], r["arrival_angle_rad"]] == pytest.approx(ref["angles"],
                                                                               abs=tol)
    assert r["length_m"] == pytest.approx(ref["length"], rel=tol)
    assert r["tension_mean_N"] == pytest.approx(ref["tension"], rel=tol)
    assert np.hypot(*r["effective_force_N"]) == pytest.approx(ref["F"], rel=tol)
    assert r["axial_force_N"][0] == pytest.approx(g["N1"], rel=1e-12)
    mid = np.array([np.interp(r["length_m"] / 2, r["s_m"], r[k]) for k in ("x_m", "y_m")])
    m = np.array([math.sin(ref["phi"]), -math.cos(ref["phi"])])
    lam = ref["lam"]  # tails tan(phi / 4) = tan(delta / 4) e^(-s / lambda) pull it in
    tails = 4 * lam * sum(math.tan(d / 4) for d in ref["delta"]) * math.exp(
        -r["length_m"] / (2 * lam))
    assert (mid - g["c1"]) @ m == pytest.approx(g["r1"] + lam**2 / (2 * g["r1"]) - tails,
                                                rel=tol)
    linear = ref["phi"] - math.pi / 2 - lam / g["r1"]  # the check can fail: the linear
    assert r["departure_angle_rad"] != pytest.approx(linear, abs=100 * tol)  # layer's is off


def _rhs(F, EI):
    """Eqs. (1)-(2) with the effective force F (N): y = (x, y, theta, kappa)."""
    def f(s, y):
        return [math.cos(y[2]), math.sin(y[2]), y[3],
                (F[0] * math.sin(y[2]) - F[1] * math.cos(y[2])) / EI]
    return f


def _on_circle(c, r, a):
    """The belt's state where it touches the circle (c, r) at angle a, eq. (4)."""
    return [c[0] + r * math.cos(a), c[1] + r * math.sin(a), a + math.pi / 2, 1 / r]


def _shoot(g, EI, z):
    """Forward and backward solve_ivp halves for z = (alpha1, Q1 / P1, alpha2, l / l_s)."""
    P1, ls = _P1(g), math.dist(g["c1"], g["c2"])
    a1, q1, a2, ell = z[0], z[1] * P1, z[2], z[3] * ls
    t = (-math.sin(a1), math.cos(a1))
    F = (P1 * t[0] - q1 * t[1], P1 * t[1] + q1 * t[0])
    kw = dict(method="DOP853", rtol=1e-13, atol=1e-15, dense_output=True)
    fwd = solve_ivp(_rhs(F, EI), (0, ell / 2), _on_circle(g["c1"], g["r1"], a1), **kw)
    bwd = solve_ivp(_rhs(F, EI), (ell, ell / 2), _on_circle(g["c2"], g["r2"], a2), **kw)
    return fwd, bwd, F


def _mismatch(g, EI):
    """The two halves' mismatch at l / 2, scaled by l_s and r1."""
    ls = math.dist(g["c1"], g["c2"])

    def res(z):
        fwd, bwd, _ = _shoot(g, EI, z)
        d = fwd.y[:, -1] - bwd.y[:, -1]
        return [d[0] / ls, d[1] / ls, d[2], d[3] * g["r1"]]
    return res


@pytest.mark.parametrize("g,EI", [(THESIS, EI_BRIEF), (THESIS, 10 * EI_BRIEF),
                                  (TILTED, 10 * EI_BRIEF)],
                         ids=["thesis", "thesis-10x", "tilted-10x"])
def test_two_sided_shooting_gives_the_same_span(g, EI):
    """From the isolated layers' guess (Q1 = P1 tan delta1): 1e-6 (we see 1.5e-10)."""
    ls, guess = math.dist(g["c1"], g["c2"]), _closed_form(g, EI)
    z0 = [guess["angles"][0], math.tan(guess["delta"][0]), guess["angles"][1],
          guess["length"] / ls]
    sol = root(_mismatch(g, EI), z0, method="hybr", tol=1e-12)
    assert sol.success and np.max(np.abs(sol.fun)) < 1e-8
    fwd, bwd, F = _shoot(g, EI, sol.x)
    ell = sol.x[3] * ls
    gx, gw = np.polynomial.legendre.leggauss(16)
    th = [half.sol(ell / 2 + side * ell / 12 * (1 + gx))[2]  # the middle third's halves
          for half, side in ((fwd, -1), (bwd, 1))]
    mean = sum(gw @ _axial(g, F[0] * np.cos(t) + F[1] * np.sin(t)) for t in th) / 4
    r = bsb.span(EI=EI, **g)
    assert [r["departure_angle_rad"], r["arrival_angle_rad"]] == pytest.approx(
        [sol.x[0], sol.x[2]], abs=SAME)
    assert r["length_m"] == pytest.approx(ell, rel=SAME)
    assert r["tension_mean_N"] == pytest.approx(mean, rel=SAME)
    assert r["effective_force_N"] == pytest.approx(F, rel=SAME)
    other = bsb.span(EI=1.001 * EI, **g)  # the check can fail: EI 0.1 % off moves it
    assert other["tension_mean_N"] != pytest.approx(mean, rel=10 * SAME)
    assert other["departure_angle_rad"] != pytest.approx(sol.x[0], abs=10 * SAME)


def test_bad_input_names_the_field():
    vc = math.sqrt(THESIS["N1"] / THESIS["rhoA"])
    for v in (vc * (1 + 1e-9), -2 * vc):
        with pytest.raises(ValueError, match=r"^v = .* is out of range: allowed \|v\| < "):
            bsb.span(EI=EI_BRIEF, **{**THESIS, "v": v})
    for EI in (-EI_BRIEF, 0.0, math.nan):
        with pytest.raises(ValueError, match=r"^EI must be"):
            bsb.span(EI=EI, **THESIS)
    too_stiff = 10 * _P1(THESIS) * (2 * X_CENTRE) ** 2
    with pytest.raises(ValueError, match=r"^EI = .* is out of range for this span"):
        bsb.span(EI=too_stiff, **THESIS)
    with pytest.raises(ValueError, match=r"^c2 = .*: the pulleys overlap"):
        bsb.span(EI=EI_BRIEF, **{**THESIS, "c2": (R1 - X_CENTRE, 0.0)})
    for field, value in (("r1", -R1), ("N1", 0.0), ("rhoA", -1.0), ("EA", -1.0)):
        with pytest.raises(ValueError, match=rf"^{field} must be"):
            bsb.span(EI=EI_BRIEF, **{**THESIS, field: value})
    with pytest.raises(ValueError, match=r"^c1 must be a point"):
        bsb.span(EI=EI_BRIEF, **{**THESIS, "c1": 0.0})
