"""References and scene defaults pinned by numbers that do not come from the package.

Every other check compares the code with a reference the same code computes from the same
constants: a constant changed consistently in a scene and its reference (g = 9.81 m/s^2,
steel's 7850 kg/m^3, ...) leaves them green.  Here each published constant is written
down as the paper prints it (thesis = Kerkkänen 2006, shared/papers/000_*.txt beside the project, line
numbers of that file), and each analytic reference at its defaults is held against a
second method written out in the test: the rigid pendulum's fall time by the complete
elliptic integral, beam and plate frequencies by their closed forms, Navier's plate by
Timoshenko's tabulated coefficient, the spinning beam by the thesis' printed extension.
tests/mutations.py changes g and the density everywhere in the package; these fail.
"""
from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.optimize import brentq
from scipy.special import ellipk

from ancf.scenes import SCENES
from ancf.scenes.analytic import DYNAMIC_REFERENCES, REFERENCES

G = 9.81          # m/s^2, thesis l. 654 (pendulum: "gravity, which is equal to 9.81 m/s^2")
STEEL = 7850.0    # kg/m^3, thesis l. 576 and l. 654 ("the mass density 7850 kg/m^3")
E_STATIC = 2.07e11  # Pa, thesis l. 576 (static problems)


def _run(scene, **overrides) -> dict:
    out, _ = scene.execute(overrides)
    assert out["converged"], out.get("message")
    return out["results"]


def test_pendulum_defaults_are_the_thesis_problem_as_printed():
    """Thesis l. 654: 0.1-m-sided square, 2.0 m, E = 2.07e7 N/m^2, nu = 0, rho = 7850, g = 9.81."""
    p = SCENES["pendulum"].resolve({})
    assert {k: p[k] for k in ("L", "b", "h", "E", "nu", "rho", "g")} == dict(
        L=2.0, b=0.1, h=0.1, E=2.07e7, nu=0.0, rho=STEEL, g=G)


def test_spinning_beam_defaults_are_wu_and_haugs_as_printed():
    """Thesis l. 684: 8 m, width 1.986e-3 m, height 3.675e-2 m, E = 6.895e10, rho = 2766.67;
    Eq. 2.35's omega_s = 4 rad/s."""
    want = dict(L=8.0, b=1.986e-3, h=3.675e-2, E=6.895e10, rho=2766.67, omega_s=4.0)
    p = SCENES["spinning-beam"].resolve({})
    assert {k: p[k] for k in want} == want
    q = DYNAMIC_REFERENCES["spinning-extension"].resolve({})
    assert {k: q[k] for k in want} == want
    # the printed extension 1.09545e-4 m (thesis l. 704), from the reference at its
    # defaults with Wu & Haug's tabulated area (today 5.5e-6 apart; rho 1 % off: 1 %)
    r = _run(DYNAMIC_REFERENCES["spinning-extension"])
    assert r["axial_extension_thesis_m"] == pytest.approx(1.09545e-4, rel=1e-5)


def test_rigid_pendulum_reaches_the_vertical_at_the_elliptic_integral_time():
    """The slender rod released horizontally: theta'' = -(3 g / 2 L) cos(theta) is the simple
    pendulum of omega0^2 = 3 g / (2 L) swinging through +-90 degrees about the vertical, so
    it first hangs vertically at a quarter period, K(m = sin^2 45 deg) / omega0 (0.68355 s
    for L = 2 m, g = 9.81).  The reference (DOP853 at rtol 1e-12) at its defaults crosses
    theta = -pi/2 there to 1e-7 s (cubic interpolation of the 1 ms samples); g off by 1 %
    moves it 3.4 ms."""
    L = 2.0
    quarter = ellipk(0.5) / math.sqrt(3.0 * G / (2.0 * L))
    r = _run(DYNAMIC_REFERENCES["rigid-pendulum"], output_dt=1e-3)
    t, th = np.asarray(r["times"]), np.asarray(r["theta"])
    i = int(np.argmax(th < -math.pi / 2))
    sl = slice(i - 2, i + 2)
    t_cross = np.polynomial.Polynomial.fit(th[sl], t[sl], 3)(-math.pi / 2)
    assert t_cross == pytest.approx(quarter, abs=1e-7)


def test_beam_modes_reference_defaults_are_the_thesis_steel_beam():
    """The beam-modes reference at its defaults (thesis l. 576: L = 2 m, 0.1 m square,
    E = 2.07e11, rho = 7850; nu = 0.3): its Euler-Bernoulli cantilever frequencies are
    (beta_k L)^2 / (2 pi L^2) sqrt(E I / (rho A)) with beta_k L the roots of
    1 + cos x cosh x = 0 (1.8751041, 4.6940911, 7.8547574), to 1e-7."""
    p = REFERENCES["beam-modes"].resolve({})
    assert {k: p[k] for k in ("L", "h", "b", "E", "rho", "support")} == dict(
        L=2.0, h=0.1, b=0.1, E=E_STATIC, rho=STEEL, support="cantilever")
    r = _run(REFERENCES["beam-modes"])
    EI, rhoA = E_STATIC * 0.1**4 / 12.0, STEEL * 0.1 * 0.1
    roots = np.array([1.87510407, 4.69409113, 7.85475744])
    want = roots**2 / (2.0 * math.pi * 2.0**2) * math.sqrt(EI / rhoA)
    assert np.asarray(r["euler_bernoulli_hz"]) == pytest.approx(want, rel=1e-7)
    # Timoshenko's lies below, by the shear and rotary inertia of L/h = 20 (0.2-3.2 %)
    ratio = np.asarray(r["frequencies_hz"]) / want
    assert np.all((ratio < 1.0) & (ratio > 0.96))


def test_plate_modes_reference_defaults_against_the_closed_form():
    """plate-modes at its defaults (1 m square steel plate, h = 0.01 m, E = 2.1e11, nu = 0.3,
    rho = 7850): omega_11 = 2 pi^2 sqrt(D / (rho h)), D = E h^3 / (12 (1 - nu^2)), and the
    square's (1, 2) and (2, 1) at 5/2 of it (Leissa, NASA SP-160, ch. 4), to 1e-12."""
    D = 2.1e11 * 0.01**3 / (12.0 * (1.0 - 0.3**2))
    w11 = 2.0 * math.pi**2 * math.sqrt(D / (STEEL * 0.01))
    f = np.asarray(_run(REFERENCES["plate-modes"])["frequencies_hz"])
    assert f[:3] == pytest.approx(np.array([1.0, 2.5, 2.5]) * w11 / (2.0 * math.pi), rel=1e-12)


def test_navier_plate_reference_defaults_against_timoshenkos_coefficient():
    """navier-plate at its defaults (1 m square, h = 0.01 m, E = 2.1e11, nu = 0.3, p = 1 kPa):
    w_c = 0.00406235 p a^4 / D (Timoshenko & Woinowsky-Krieger, Table 8, b/a = 1), 1e-6."""
    D = 2.1e11 * 0.01**3 / (12.0 * (1.0 - 0.3**2))
    w = _run(REFERENCES["navier-plate"])["center_deflection_m"]
    assert w == pytest.approx(0.00406235 * 1e3 / D, rel=1e-6)


def test_modes_scenes_default_density_is_steel():
    """``ancf modes`` of the static beams and plates: rho defaults to steel's 7850 kg/m^3
    (thesis l. 576); the frequencies themselves are checked against Timoshenko's beam with
    the test's own data in tests/scenes/test_modes.py."""
    for name in ("simply-supported", "cantilever", "axial-bar", "plate-strip", "beam3d-cantilever"):
        rho = {p.name: p.default for p in SCENES[name].modal_params}["rho"]
        assert rho == STEEL, name


def test_bechtel_reference_is_model_2_and_its_stiff_limit_the_closed_form():
    """Bechtel's steady belt at its defaults is the thesis' Model 2 (Table 4.1, l. 1073-1089:
    R = 0.05 m, w = 0.04 m, h = 0.003 m, rho = 166.667, mu = 0.6, omega0 = 500 rad/s;
    T_i = 50 N, l. 1324; T_a = 2 N m, Eq. 4.47; k = 0.2 kN, Fig. 4.11).  Made stiff
    (k = 1e9 N), its span tensions are the inextensible closed form written out here: a
    slip arc phi on the driven pulley with n_t / n_s = e^(mu phi), n = T - rhoA v^2,
    n_t - n_s = T_a / R, and the mean tension T_i: 4 pi R T_i = (2 pi R - R phi)(T_t + T_s)
    + 2 (rhoA v^2 R phi + T_a / mu); to 1e-6 (the strains T/k ~ 1e-7)."""
    R, mu, omega, T_i, T_a = 0.05, 0.6, 500.0, 50.0, 2.0
    rhoA = 166.667 * 0.04 * 0.003
    p = REFERENCES["bechtel"].resolve({})
    assert {k: p[k] for k in ("k", "R", "omega", "mu", "T_i", "T_a")} == dict(
        k=200.0, R=R, omega=omega, mu=mu, T_i=T_i, T_a=T_a)
    assert p["rhoA"] == pytest.approx(rhoA, rel=1e-15)
    m = rhoA * (omega * R) ** 2

    def mean_tension_gap(n_s):
        n_t = n_s + T_a / R
        phi = math.log(n_t / n_s) / mu
        return ((2 * math.pi * R - R * phi) * (n_t + n_s + 2 * m) + 2 * (m * R * phi + T_a / mu)
                - 4 * math.pi * R * T_i)

    n_s = brentq(mean_tension_gap, T_a / (R * math.expm1(mu * math.pi)), 10 * T_i, xtol=1e-13)
    r = _run(REFERENCES["bechtel"], k=1e9)
    assert (r["T_tight_N"], r["T_slack_N"]) == pytest.approx((n_s + T_a / R + m, n_s + m),
                                                             rel=1e-6)


def test_moving_string_defaults_are_the_table_3_1_belt():
    """The moving-string reference's defaults: Table 3.1's belt (rho 1036 kg/m^3, 0.01 m
    square: rho A = 0.1036 kg/m), the span between the centres (2 x 0.191441 m) and the
    rim speed of 120 rad/s on R = 0.08125 m."""
    p = REFERENCES["moving-string"].resolve({})
    assert (p["rho_A"], p["L"], p["v"]) == pytest.approx((1036.0 * 0.01 * 0.01, 0.382882,
                                                          120.0 * 0.08125), rel=1e-14)
