"""Kong & Parker's bending belt (analytic/belt_bending_steady.py): the EI -> 0 limit against
the string (analytic/belt_steady.py), the span against the linear tensioned beam's closed
form, EI's effect, bad input."""
import math

import numpy as np
import pytest

from analytic import belt_bending_steady as bb

# The thesis drive at 120 rad/s (examples/thesis_table_3_1.toml, ancf.checks.belt2d.CASE_120)
E, ALPHA2, B, H, RHO = 1e9, 1e-3, 0.01, 0.01, 1036.0
EI = E * ALPHA2 * B * H ** 3 / 12                   # N m^2
R, X = 0.08125, 0.191441
PULLEYS = [{"name": "driver", "centre": [-X, 0.0], "radius": R, "side": 1,
            "law": "prescribed", "omega": 120.0},
           {"name": "driven", "centre": [X, 0.0], "radius": R, "side": 1, "law": "driven",
            "torque": 45.0}]
BELT = dict(EA=E * B * H, rhoA=RHO * B * H, L0=1.24437, mu=1.2)
LIMIT_RTOL = 1e-6


def drive(factor):
    return bb.solve(PULLEYS, EI=factor * EI, **BELT)


def limit_errors(out):
    """Largest relative error of the span tensions (mean, ends) and of the contact points
    (distance / R) against the string's."""
    t = max(abs(v / s["tension_N"] - 1) for s in out["spans"]
            for v in [s["tension_mean_N"], *s["tension_ends_N"]])
    p = max(np.hypot(*np.subtract(s[a], s[b])) / R for s in out["spans"]
            for a, b in (("departure_point_m", "string_departure_m"),
                         ("arrival_point_m", "string_arrival_m")))
    return t, p


def test_zero_bending_limit_is_the_string():
    t, p = limit_errors(drive(1e-9))
    assert t < LIMIT_RTOL and p < LIMIT_RTOL


def test_ten_times_ei_moves_the_contact_points():
    """(c) the key matters: 10x the thesis EI moves the points far beyond the limit's tolerance
    (so the limit test can fail), each by about eps / R (eps = sqrt(EI / n))."""
    out = drive(10.0)
    _, p = limit_errors(out)
    assert p > 1e3 * LIMIT_RTOL
    for s in out["spans"]:
        assert s["departure_shift_rad"] < -0.5 * s["eps_m"] / R


def linear_shift(eps, ell):
    """The linear tensioned beam EI w'''' = n w'' between two equal pulleys (span ell):
    w = A + C cosh((x - ell / 2) / eps) meeting the rim -x^2 / (2R) at x = -a with w, w', w''
    continuous gives a = eps tanh((ell / 2 + a) / eps) and the mid-span offset
    eps^2 / R (1 - 1 / cosh(h / eps)) - a^2 / (2 R), h = ell / 2 + a (fixed point)."""
    a = eps
    for _ in range(200):
        a = eps * math.tanh((ell / 2 + a) / eps)
    h = ell / 2 + a
    return a, eps ** 2 / R * (1 - 1 / math.cosh(h / eps)) - a ** 2 / (2 * R)


@pytest.mark.parametrize("ell, n, ei", [(0.2, 50.0, 4e-4), (0.4, 1500.0, 10 * EI)])
def test_span_against_the_linear_beam(ell, n, ei):
    """(b) the departure shift and mid-span offset against the linear closed form, within
    (eps / R)^2 relative (the rim's and the elastica's nonlinearity); a short stiff span
    (eps / (ell / 2) = 0.028, eps / R = 0.035) and the thesis span at 10 EI; 1.2 EI misses."""
    def measure(e):
        sp = bb.span([0.0, 0.0], R, 1, [ell, 0.0], R, 1, n, e)
        mid = np.interp(sp.L / 2, sp.s, sp.xy[:, 1]) + R   # above the string line y = -R
        return -sp.departure_shift * R, -mid, sp.eps
    a, off, eps = measure(ei)
    a_ref, off_ref = linear_shift(eps, ell)
    tol = (eps / R) ** 2
    assert abs(a / a_ref - 1) < tol and abs(off / off_ref - 1) < 10 * tol
    assert abs(measure(1.2 * ei)[0] / a_ref - 1) > 10 * tol


def test_torques_and_creep_are_the_strings():
    """The tension along a span follows P . t: at 10 EI its ends equal the wrap's n."""
    out = drive(10.0)
    for s in out["spans"]:
        assert abs(s["tension_ends_N"][0] / s["tension_N"] - 1) < 1e-9


@pytest.mark.parametrize("ei, match", [(-1.0, "belt.EI must be > 0"),
                                        (float("nan"), "belt.EI must be finite"),
                                        ("x", "belt.EI must be a real number"),
                                        (1e3, "belt.EI = 1000.0 is out of range"),
                                        (1e-30, "belt.EI = 1e-30 is out of range")])
def test_bad_input(ei, match):
    with pytest.raises(ValueError, match=match):
        bb.solve(PULLEYS, EI=ei, **BELT)
