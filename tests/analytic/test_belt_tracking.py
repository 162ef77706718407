"""The belt-tracking reference (analytic/belt_tracking.py): Eq. 3 against Eq. 2 integrated
in time under a speed ramp, the exact-angle rule against the first-order one, the free
span's classic rule, the settled offset, bad input.  Each check shows that a perturbed
input moves the answer beyond its tolerance."""
import math

import numpy as np
import pytest
from scipy.integrate import quad, solve_ivp

from analytic import belt_tracking as bt

L, TILT = 0.11, 1.0  # m, deg
#: Eq. 2 by RK45 at rtol 1e-10 against Eq. 3: we see 1e-10 relative
ODE = 1e-7
#: the exact angle rule tan(theta - atan(z / L)) against Eq. 2 at 1 deg: we see 5e-5
FIRST_ORDER = 1e-3


def _speed(t):
    """A belt speed ramped from 0 to 1 m/s over 20 ms, m/s."""
    return min(t / 0.02, 1.0)


def _ode(rate, t_end=0.3):
    """z (m) at 30 times up to ``t_end`` of dz/dt = v(t) rate(z), and the travel x(t)."""
    t = np.linspace(0.0, t_end, 30)
    sol = solve_ivp(lambda s, z: [_speed(s) * rate(z[0])], (0, t_end), [0.0], t_eval=t,
                    rtol=1e-10, atol=1e-14, max_step=1e-3)
    x = np.array([quad(_speed, 0, s, points=[0.02], limit=200)[0] for s in t])
    return sol.y[0], x


@pytest.mark.parametrize("tilt", [0.5, 1.0, -2.0])
def test_closed_form_solves_the_walk_equation(tilt):
    """Eq. 3 at the travel of a ramped speed against Eq. 2 integrated in time, Eq. 4
    against Eq. 2's right side there; a span 1 % longer misses by far more than ODE."""
    tan = math.tan(math.radians(tilt))
    z, x = _ode(lambda z: tan - z / L)
    scale = L * abs(tan)
    assert np.max(np.abs(bt.entry_offset(x, L, tilt) - z)) < ODE * scale
    assert np.max(np.abs(bt.entry_offset(x, 1.01 * L, tilt) - z)) > 100 * ODE * scale
    assert bt.entry_direction(x, L, tilt) == pytest.approx(tan - z / L, abs=ODE * abs(tan))


def test_first_order_against_the_exact_angle():
    """The rule with the span's angle subtracted exactly (tan(theta - atan(z / L))) agrees
    with Eq. 3 to FIRST_ORDER at 1 deg, not at 8 deg (the first-order model's limit)."""
    for tilt, within in ((TILT, True), (8.0, False)):
        a = math.radians(tilt)
        z, x = _ode(lambda z: math.tan(a - math.atan(z / L)))
        err = np.max(np.abs(bt.entry_offset(x, L, tilt) - z)) / (L * math.tan(a))
        assert bool(err < FIRST_ORDER) is within, (tilt, err)


def test_limits():
    """A free span (L = inf) walks at tan(theta) per metre of travel (Eq. 1), as Eq. 3's
    start does (to 5e-4 over 1e-3 L); after 20 span lengths the entry sits at L tan(theta)
    (to 1e-8), which a 1 % shorter travel also reaches but a 10 times shorter one not."""
    tan = math.tan(math.radians(TILT))
    x = np.array([1e-4, 0.05, 1.0])
    assert bt.entry_offset(x, math.inf, TILT) == pytest.approx(x * tan, rel=1e-15)
    assert bt.entry_offset(1e-3 * L, L, TILT) == pytest.approx(1e-3 * L * tan, rel=5e-4)
    assert bt.entry_offset(20 * L, L, TILT) == pytest.approx(L * tan, rel=1e-8)
    assert bt.entry_offset(2 * L, L, TILT) != pytest.approx(L * tan, rel=0.1)


@pytest.mark.parametrize("args, words", [
    ((-0.1, L, 1.0), "travel_m must be finite and >= 0"),
    (([0.0, math.nan], L, 1.0), "travel_m must be finite and >= 0"),
    ((0.1, 0.0, 1.0), "span_m must be > 0"),
    ((0.1, "x", 1.0), "span_m must be a real number"),
    ((0.1, L, 10.5), "tilt_deg = 10.5 is out of range; allowed: a number in [-10, 10]"),
    ((0.1, L, math.inf), "tilt_deg must be finite"),
])
def test_bad_input(args, words):
    for fn in (bt.entry_offset, bt.entry_direction):
        with pytest.raises(ValueError) as err:
            fn(*args)
        assert words in str(err.value)
