"""The 2D belt drive against thesis section 3.3 (Figs 3.5-3.21, Table 3.1, Eqs 3.29-3.30):
one test per acceptance check of :mod:`ancf.checks.belt2d` (the report's table uses the
same functions), the path geometry, the pulley laws and bad input."""
import math

import numpy as np
import pytest

from ancf.checks import belt2d as bc
from ancf.belts.path import TwoPulleyPath
from ancf.cli import main
from ancf.belts.pulleys import driver_omega, opposing_torque
from ancf.scenes import SCENES
from ancf.scenes import belt_common as common
from ancf.common.params import InputError

TABLE = TwoPulleyPath((-0.191441, 0.0), 0.08125, (0.191441, 0.0), 0.08125)


# ------------------------------------------------------------------ acceptance checks

def test_free_belt_is_a_circle_of_its_length():
    mean, dev = bc.free_belt()
    assert mean.passed and dev.passed, (mean, dev)


@pytest.mark.slow
def test_20_25_30_elements_agree_at_1_s():
    c = bc.element_convergence()
    assert c.passed, c
    assert bc.steady_ratio() == pytest.approx(1.0, abs=1e-2)  # equal radii, no load


@pytest.mark.slow
def test_stiffer_belt_oscillates_less():
    c = bc.stiffness_trend()
    assert c.passed, c


@pytest.mark.slow
def test_smaller_creep_rate_factor_lags_during_the_ramp():
    c = bc.creep_lag_trend()
    assert c.passed, c


@pytest.mark.slow
def test_smaller_creep_rate_factor_slips_more_at_120_rad_s():
    c = bc.creep_slip_trend()
    assert c.passed, c


@pytest.mark.slow
def test_span_tensions_carry_the_driven_torque():
    c = bc.torque_balance()
    assert c.passed, c


def test_normal_force_against_T_over_R_and_the_exact_relation():
    """F_n per unit belt length is T/R within 5 % (the rest: penetration and centripetal
    terms); per unit reference length the exact relation of a stretched belt on a circle
    holds to 1 %."""
    thin, exact = bc.normal_force()
    assert exact.passed, exact
    assert thin.passed, thin
    assert bc.normal_force_status(thin, exact) == "PASS"


@pytest.mark.slow
def test_the_slack_span_moves_more_than_the_tight_one_at_120_rad_s():
    """Figs 3.10-3.11 say the tight span moves more; here the slack span, at its lower
    tension, moves more during the ramp (an acceptance row: DIFFERS (explained))."""
    m = bc.span_motion(**dict(bc.CASE_120, nu_s=1e5))
    assert m["slack"] > 1.1 * m["tight"] > 0
    assert bc.span_status(m) == "DIFFERS (explained)"
    assert bc.span_status({"tight": 2.0, "slack": 1.0}) == "PASS"


@pytest.mark.slow
def test_5_7_11_contact_points_give_the_same_driven_speed():
    c = bc.gauss_point_agreement()
    assert c.passed, c


def test_larger_driven_pulley_turns_at_the_radius_ratio():
    c = bc.radius_ratio()
    assert c.passed, c


def test_belt_length_follows_the_path_with_table_shortening():
    drive = bc.run(R2=bc.R2_LARGE)[1].extra["drive"]
    assert drive.spec.belt_length == pytest.approx(drive.spec.path.length * 1.2727 / TABLE.length,
                                                   rel=1e-12)
    assert bc.run()[1].extra["drive"].spec.belt_length == pytest.approx(1.2727, rel=1e-12)


def test_a_wrong_reference_fails_the_check():
    c = bc.Check("x", 1.0, 1.0, 0.02, 0.01, "-", "m")
    assert not c.passed
    assert bc.normal_force_status(c, c) == "FAIL"


# ------------------------------------------------------------------ geometry

def test_table_3_1_span_and_path_length():
    defaults = SCENES["belt2d"].resolve({})
    scene_path = common.path_of(defaults)
    assert (scene_path.O1, scene_path.R1, scene_path.O2, scene_path.R2) == (
        TABLE.O1, TABLE.R1, TABLE.O2, TABLE.R2)  # the scene's defaults are Table 3.1
    assert round(TABLE.span, 6) == 0.382882
    assert TABLE.length == pytest.approx(2 * 0.382882 + 2 * math.pi * 0.08125, abs=1e-6)
    s = np.linspace(0.0, TABLE.length, 20001)
    r, _ = TABLE(s)
    assert np.sum(np.linalg.norm(np.diff(r, axis=0), axis=1)) == pytest.approx(TABLE.length,
                                                                                rel=1e-7)  # chords of 6e-5 m


@pytest.mark.parametrize("R2", [0.08125, 0.1218, 0.05])
def test_path_is_tangent_continuous_and_closed(R2):
    path = TwoPulleyPath((-0.191441, 0.0), 0.08125, (0.191441, 0.0), R2)
    ends = np.array([p[2] for p in path.pieces()])
    r_a, t_a = path(ends - 1e-9)
    r_b, t_b = path(ends + 1e-9)
    assert np.abs(r_a - r_b).max() < 1e-8 and np.abs(t_a - t_b).max() < 1e-6
    _, t = path(np.linspace(0.0, path.length, 5001))
    assert np.allclose(np.linalg.norm(t, axis=1), 1.0)


@pytest.mark.parametrize("R2", [0.05, 0.1218])
def test_wrap_angles_of_unequal_pulleys_sum_to_two_pi(R2):
    path = TwoPulleyPath((-0.191441, 0.0), 0.08125, (0.191441, 0.0), R2)
    t1, t2 = path.wrap
    assert t1 + t2 == pytest.approx(2 * math.pi, abs=1e-14)
    assert (t1 > math.pi) == (R2 < 0.08125)  # the larger pulley wraps more
    c = (0.08125 - R2) / path.centre_distance
    assert t2 == pytest.approx(math.pi - 2 * math.asin(c), abs=1e-14)  # textbook form


# ------------------------------------------------------------------ pulley laws

def test_eq_3_29_at_its_breakpoints():
    """Eq. 3.29 as printed: 0 up to 0.05 s, linear to 12 rad/s at 0.6 s."""
    t = np.array([0.0, 0.05, 0.325, 0.6, 1.0])
    assert driver_omega(t, 12.0) == pytest.approx([0.0, 0.0, 6.0, 12.0, 12.0], abs=1e-14)


def test_eq_3_30_at_its_breakpoints():
    """Eq. 3.30 as printed: 0 up to 0.05 s, 45/2 (1 - cos(pi t / 0.6)) up to 0.6 s, 45."""
    T0, T1 = 0.05, 0.6
    t = np.array([0.0, T0, T0 + 1e-12, 0.3, T1, 1.0])
    want = [0.0, 0.0, 22.5 * (1 - math.cos(math.pi * T0 / 0.6)), 22.5, 45.0, 45.0]
    assert opposing_torque(t, 45.0) == pytest.approx(want, abs=1e-9)


# ------------------------------------------------------------------ bad input

@pytest.mark.parametrize("setting,field", [
    ({"R1": 0.2, "R2": 0.2}, "R1 + R2"),
    ({"belt_length": 0.6}, "belt_length"),
    ({"k_p": -1.0}, "k_p"),
    ({"mu": -0.1}, "mu"),
    ({"gauss_points": 6}, "gauss_points"),
])
def test_bad_input_names_the_field(setting, field, capsys):
    with pytest.raises(InputError, match=field.replace("+", r"\+")):
        SCENES["belt2d"].execute(setting)
    argv = ["run", "belt2d"] + [a for k, v in setting.items() for a in ("--set", f"{k}={v}")]
    assert main(argv) == 2
    err = capsys.readouterr().err.strip()
    assert "\n" not in err and field in err


def test_belt_of_half_the_path_is_the_shortest_allowed():
    half = 0.5 * common.path_of({"R1": common.R1, "R2": common.R2}).length
    with pytest.raises(InputError, match="belt_length"):
        SCENES["belt2d"].resolve({"belt_length": half * (1 - 1e-9)})
    SCENES["belt2d"].resolve({"belt_length": half})
