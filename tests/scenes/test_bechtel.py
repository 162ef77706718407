"""Bechtel et al.'s steady belt (analytic/bechtel.py, thesis 4.1): a second solution by
integrating the belt ODEs along s, the capstan (rhoA -> 0) and stiff (k -> infinity)
limits against closed forms, Model 2 next to the thesis, bad input, the CLI."""
import json
import math

import numpy as np
import pytest
from scipy.integrate import solve_ivp
from scipy.optimize import brentq

from analytic import bechtel
from ancf.scenes.analytic import REFERENCES
from ancf.cli import main
from ancf.common.params import InputError
from ancf.study.schemas import schema, validate

DEFAULTS = REFERENCES["bechtel"].resolve({})
#: DOP853 tolerance of the second solution, and what it must reproduce (relative)
ODE_RTOL, ODE_MATCH = 1e-12, 1e-9


def _slip(b, v_in, sign):
    """Integrate Eq. 4.2 with Eq. 4.1 over one slip arc from speed v_in (m/s): returns
    (exit speed m/s, unstretched length m, int |friction| ds N)."""
    G = b.rhoA * b.v_o

    def rhs(_, y):
        n = b.k * (y[0] / b.v_o - 1.0) - G * y[0]        # T - G v, N
        return [sign * b.mu * n / (b.R * (b.k / b.v_o - G)), b.v_o / y[0], b.mu * n / b.R]

    sol = solve_ivp(rhs, (0.0, b.R * b.slip_arc), [v_in, 0.0, 0.0], method="DOP853",
                    rtol=ODE_RTOL, atol=1e-14)
    assert sol.success
    return sol.y[:, -1]


def _loop(b):
    """Round the belt from the driver's entry at the driver's rim speed (Eq. 4.48)."""
    stick, l_s = b.R * (math.pi - b.slip_arc), math.pi * b.R
    v1 = b.omega * b.R
    v2, u_driver, _ = _slip(b, v1, -1.0)
    v3, u_driven, friction = _slip(b, v2, 1.0)
    unstretched = (stick + l_s) * b.v_o * (1 / v1 + 1 / v2) + u_driver + u_driven
    return {"v_driver_exit": v2, "v_driven_exit": v3, "unstretched_m": unstretched,
            "torque_Nm": b.R * friction}


@pytest.mark.parametrize("k", [200.0, 25e3])
@pytest.mark.parametrize("capstan", [False, True])
def test_belt_odes_close_the_loop(k, capstan):
    p = dict(DEFAULTS, k=k)
    b, _ = bechtel.steady(p, capstan)
    loop = _loop(b)
    assert loop["v_driven_exit"] == pytest.approx(p["omega"] * p["R"], rel=ODE_MATCH)
    assert loop["v_driver_exit"] == pytest.approx(b.v_slack, rel=ODE_MATCH)
    assert loop["torque_Nm"] == pytest.approx(p["T_a"], rel=ODE_MATCH)
    L = 4 * math.pi * p["R"]  # Table 4.1: l_belt = 4 pi R
    assert loop["unstretched_m"] == pytest.approx(L / (1 + p["T_i"] / k), rel=ODE_MATCH)


def test_the_root_meets_its_tolerance():
    b, _ = bechtel.steady(DEFAULTS)
    step = bechtel._state(DEFAULTS, b.n_slack + 10 * bechtel.XTOL_N, DEFAULTS["T_a"])
    assert abs(bechtel.mass_residual(b, DEFAULTS["T_i"])) <= abs(
        bechtel.mass_residual(step, DEFAULTS["T_i"]))


def _inextensible(p, T_a):
    """k -> infinity: T = n + m, m = rhoA (omega R)^2, n_t / n_s = e^(mu phi), and the
    mean tension is T_i: 4 pi R T_i = (2 pi R - R phi)(T_t + T_s) + 2 (m R phi + T_a / mu)."""
    m, R, mu = p["rhoA"] * (p["omega"] * p["R"]) ** 2, p["R"], p["mu"]

    def f(n_s):
        n_t = n_s + T_a / R
        phi = math.log(n_t / n_s) / mu
        return (2 * math.pi * R - R * phi) * (n_t + n_s + 2 * m) + 2 * (m * R * phi + T_a / mu) \
            - 4 * math.pi * R * p["T_i"]

    n_s = brentq(f, T_a / (R * math.expm1(mu * math.pi)), 10 * p["T_i"], xtol=1e-13)
    return n_s + T_a / R + m, n_s + m, math.log1p(T_a / (R * n_s)) / mu


def _max_torque_inextensible(p):
    """Slip over the whole wrap: T_a = 4 pi R (T_i - m) / (pi coth(mu pi / 2) + 2 / mu)."""
    m, R, mu = p["rhoA"] * (p["omega"] * p["R"]) ** 2, p["R"], p["mu"]
    return 4 * math.pi * R * (p["T_i"] - m) / (math.pi / math.tanh(mu * math.pi / 2) + 2 / mu)


@pytest.mark.parametrize("rhoA", [DEFAULTS["rhoA"], 0.0])
def test_stiff_limit_is_the_inextensible_solution(rhoA):
    p = dict(DEFAULTS, k=1e9, rhoA=rhoA)
    r = bechtel.summary(*bechtel.steady(p))
    T_t, T_s, phi = _inextensible(p, p["T_a"])
    assert (r["T_tight_N"], r["T_slack_N"], r["slip_arc_driven_rad"]) == pytest.approx(
        (T_t, T_s, phi), rel=1e-6)
    assert r["omega_ratio"] == pytest.approx(1.0, abs=1e-6)  # no creep: ratio -> 1
    assert r["max_torque_Nm"] == pytest.approx(_max_torque_inextensible(p), rel=1e-6)


def test_model2_stiff_belt_is_close_to_inextensible():
    """Figs 4.4-4.5 (k = 25 kN) print no numbers; the strains T/k ~ 0.3 % bound the
    difference from the k -> infinity solution."""
    p = dict(DEFAULTS, k=25e3)
    r = bechtel.results(p)
    T_t, T_s, _ = _inextensible(p, p["T_a"])
    strain = T_t / p["k"]
    assert r["T_tight_N"] == pytest.approx(T_t, rel=strain)
    assert r["T_slack_N"] == pytest.approx(T_s, rel=strain)
    assert 1 - r["omega_ratio"] == pytest.approx((T_t - T_s) / (p["k"] + T_t), rel=strain)


def test_capstan_limit_rhoA_to_zero():
    full = bechtel.results(dict(DEFAULTS, rhoA=1e-9))
    for key, val in full["capstan"].items():
        assert full[key] == pytest.approx(val, rel=1e-6), key


def test_inertia_as_bechtel_et_al_state():
    """Their abstract: neglecting inertia over-predicts the largest moment and
    under-predicts the slip angles."""
    r = bechtel.results(DEFAULTS)
    assert r["capstan"]["max_torque_Nm"] > r["max_torque_Nm"]
    assert r["capstan"]["slip_arc_driver_rad"] < r["slip_arc_driver_rad"]


#: thesis, after Eq. 4.48, k = 0.2 kN (Fig. 4.14): omega_driven "approximately 14.6 %" lower
THESIS_SLIP = 0.146
#: the thesis reads it off a figure ("approximately"): we hold it to one percentage point
THESIS_SLIP_TOL = 0.01


def test_model2_compliant_slip_next_to_the_thesis():
    """We get 15.16 % (capstan 14.71 %), not 14.6 %.  1 - ratio = (T_t - T_s) / (k + T_t)
    (v is proportional to the stretch), so 14.6 % needs T_t - T_s = 40 N with T_t = 74 N;
    the readings tried (mass, mean tension or T_t + T_s = 2 T_i as the installation
    condition; torque with or without the momentum flux) all give 14.70-15.30 %."""
    r = bechtel.results(DEFAULTS)
    for slip in (1 - r["omega_ratio"], 1 - r["capstan"]["omega_ratio"]):
        assert abs(slip - THESIS_SLIP) <= THESIS_SLIP_TOL
        assert slip > THESIS_SLIP + 0.0005  # not reproduced to the printed digit


def test_distributions_integrate_to_the_torque():
    d = bechtel.distributions(DEFAULTS, n=4000)
    driven = (d["s"] > 2 * math.pi * DEFAULTS["R"]) & (d["s"] < 3 * math.pi * DEFAULTS["R"])
    s, f = d["s"][driven], d["friction"][driven]
    torque = -DEFAULTS["R"] * np.sum(0.5 * (f[1:] + f[:-1]) * np.diff(s))
    assert torque == pytest.approx(DEFAULTS["T_a"], rel=1e-3)
    assert np.all(d["normal"] >= 0) and np.all(np.diff(d["s"]) >= 0)
    assert d["s"][-1] == pytest.approx(4 * math.pi * DEFAULTS["R"], rel=1e-12)
    b, _ = bechtel.steady(DEFAULTS)
    assert (d["T"].max(), d["T"].min()) == pytest.approx((b.T_tight, b.T_slack), rel=1e-12)


@pytest.mark.parametrize("field,value,says", [
    ("mu", 0.0, "mu = 0.0 is out of range; allowed: a number in [1e-06, 10]"),
    ("mu", -0.6, "mu = -0.6 is out of range"),
    ("k", 0.0, "k = 0.0 is out of range; allowed: a number in [1e-06, 1e+12]"),
    ("T_a", 10.0, "T_a = 10.0 N m is out of range; allowed: [0, "),
    ("omega", 5000.0, "omega = 5000.0 is out of range: the belt leaves the pulleys")])
def test_bad_input_names_the_field(field, value, says):
    with pytest.raises(InputError) as exc:
        bechtel.results(dict(DEFAULTS, **{field: value}))
    assert says in str(exc.value)


def test_too_large_torque_states_the_maximum():
    top = bechtel.results(DEFAULTS)["max_torque_Nm"]
    bechtel.results(dict(DEFAULTS, T_a=top))  # the largest is transmitted
    with pytest.raises(InputError, match=rf"allowed: \[0, {top:.6g}\] N m"):
        bechtel.results(dict(DEFAULTS, T_a=1.001 * top))


def test_cli_bad_torque_is_one_error_line(capsys):
    assert main(["analytic", "bechtel", "--set", "T_a=1e3", "--json"]) == 2
    out, err = capsys.readouterr()
    assert out == "" and err.count("\n") == 1 and err.startswith("error: T_a = 1000.0 N m")


def test_cli_json_has_the_capstan_object(capsys):
    assert main(["analytic", "bechtel", "--set", "k=25e3", "--json"]) == 0
    out = json.loads(capsys.readouterr()[0])
    assert set(out["results"]["capstan"]) == set(out["results"]) - {"capstan"}
    assert validate(out, schema("bechtel")) == []
    del out["results"]["capstan"]["omega_ratio"]
    assert validate(out, schema("bechtel")) == ["$.results.capstan: missing key 'omega_ratio'"]
