"""Dynamics: equations of motion, constraint forms, integrators, dynamic scenes.

Acceptance checks of issue 3 (tolerances as stated there) plus unit checks of the
pieces.  Tolerances of the unit checks: gravity, mass and kinetic energy are
exact integrals, so 1e-12 relative (round-off); the Jacobian checks use central
differences with step h = 1e-6 on states of size ~1, whose truncation error is
~1e-12 |f'''|, hence 1e-6 relative to the largest entry, plus the round-off
10 eps |acc| / h.  Acceptance checks: today's value (stated at each) with a margin of
1.25 where the value is deterministic (fixed steps, or far above the integrator
tolerance), and the published or issue-3 figure as a separate, looser assertion.
"""
from __future__ import annotations

import json
import math

import numpy as np
import pytest

from ancf.scenes.analytic import DYNAMIC_REFERENCES
from analytic.dynamics_refs import rigid_pendulum, spinning_extension
from ancf.core.constraints import Elimination
from ancf.core.forces import Forces, Gravity
from ancf.reports import published as pub
from ancf.scenes import beam_dynamic as bd
from ancf.scenes import beam_static as bs
from ancf.scenes import pendulum, spinning_beam
from ancf.common.params import InputError
from ancf.core.energy import energy_history
from ancf.solvers.dynamics import integrate

PEND, SPIN = pendulum.SCENE, spinning_beam.SCENE
L_PEND = pub.PENDULUM["L"]
MARGIN = 1.25


def _tips(out):
    r = out["results"]
    return np.array([r["tip_x"], r["tip_y"]])


# ---------------------------------------------------------------- pieces

@pytest.mark.parametrize("element", ["linear", "omar-shabana"])
def test_gravity_and_mass_are_exact_integrals(element):
    p = PEND.resolve({"element": element, "n_elements": 3})
    mesh, q0, asm = bs.build(p)
    m = p["rho"] * p["L"] * p["b"] * p["h"]
    grav = Gravity(asm, (0.0, -9.81))
    Q = grav.Q.reshape(-1, 2)
    pos = [mesh.dof(i, "r", 0) // 2 for i in range(mesh.n_nodes)]
    assert Q[:, 0].sum() == pytest.approx(0.0, abs=1e-9)
    assert Q[pos, 1].sum() == pytest.approx(-m * 9.81, rel=1e-12)
    # a rigid lift by dy changes the potential by m g dy
    lifted = q0.copy()
    lifted[[mesh.dof(i, "r", 1) for i in range(mesh.n_nodes)]] += 0.3
    dV = sum(v.sum() for v in grav.element_potential(lifted)) - sum(v.sum() for v in grav.element_potential(q0))
    assert dV == pytest.approx(m * 9.81 * 0.3, rel=1e-12)
    # rigid rotation about the origin at rate w: T = 1/2 I w^2, I = m (L^2/3 + h^2/12)
    w = 0.7
    v = np.zeros_like(q0)
    v[0::2], v[1::2] = -w * q0[1::2], w * q0[0::2]  # r' = w k x r for every slot
    en = energy_history(asm, Forces(asm.n_dofs, [grav]), [0.0], q0[None], v[None])
    I = m * (p["L"] ** 2 / 3 + p["h"] ** 2 / 12)
    assert en.kinetic.sum() == pytest.approx(0.5 * I * w * w, rel=1e-12)
    assert en.strain.sum() == pytest.approx(0.0, abs=1e-9)


def test_elimination_api_unchanged_and_rows_agree():
    T, g, free = Elimination(6).fix([0, 1], [2.0, 3.0]).tie(5, 4).tie(3, 0).build()
    assert free.tolist() == [2, 4]
    z = np.array([7.0, 9.0])
    assert (T @ z + g).tolist() == [2.0, 3.0, 7.0, 2.0, 9.0, 9.0]
    motion = lambda t: (np.array([math.sin(t)]), np.array([math.cos(t)]),  # noqa: E731
                        np.array([-math.sin(t)]))
    el = Elimination(6).fix([0], [1.0]).tie(5, 4).prescribe([2], motion).tie(3, 2)
    rh = el.rheonomic()
    B, c = el.rows()
    for t in (0.0, 0.4):
        for order in range(3):
            q = rh.T @ (z if order == 0 else 0 * z) + rh.g(t, order)
            assert np.allclose(B @ q, c(t)[order])
    T0, g0, _ = el.build()
    assert np.allclose(g0, rh.g(0.0))


def _models(scene, overrides):
    """The elimination and multiplier models of one scene: {form: (model, q0)}."""
    setup = pendulum.setup if scene is PEND else spinning_beam.setup
    p = scene.resolve(overrides)
    mods = {}
    for form in ("elimination", "lagrange"):
        _, q0, _, mdl, _ = setup(dict(p, constraints=form))
        mods[form] = (mdl, q0)
    return mods


@pytest.mark.parametrize("scene,overrides", [(PEND, {"element": "linear"}),
                                             (PEND, {"element": "omar-shabana", "n_elements": 2}),
                                             (SPIN, {"element": "linear"})])
def test_acceleration_jacobian_matches_finite_differences(scene, overrides):
    mods, rng = _models(scene, overrides), np.random.default_rng(1)
    for form, (mdl, q0) in mods.items():
        x0, _ = mdl.initial(q0, q0 * 0)
        x = x0 + 1e-2 * rng.standard_normal(x0.size)
        v = 1e-1 * rng.standard_normal(x0.size)
        t = 3.0
        Jq, Jv = mdl.acc_jacobian(x, v, t)
        h = 1e-6
        fq = np.array([(mdl.acc(x + h * e, v, t) - mdl.acc(x - h * e, v, t)) / (2 * h)
                       for e in np.eye(x.size)]).T
        fv = np.array([(mdl.acc(x, v + h * e, t) - mdl.acc(x, v - h * e, t)) / (2 * h)
                       for e in np.eye(x.size)]).T
        noise = 10 * np.finfo(float).eps * np.max(np.abs(mdl.acc(x, v, t))) / h  # round-off
        assert np.max(np.abs(Jq - fq)) <= 1e-6 * np.max(np.abs(fq)) + noise, form
        assert np.max(np.abs(Jv - fv)) <= 1e-6 * np.max(np.abs(fv)) + noise, form


def test_hub_angle_law_is_smooth_and_consistent():
    w, Ts = 4.0, 15.0
    for t in (0.0, 3.0, 14.0, 16.0):
        th, dth, ddth = spinning_beam.hub_angle(t, w, Ts)
        h = 1e-5
        assert dth == pytest.approx((spinning_beam.hub_angle(t + h, w, Ts)[0]
                                     - spinning_beam.hub_angle(t - h, w, Ts)[0]) / (2 * h), abs=1e-8)
        assert ddth == pytest.approx((spinning_beam.hub_angle(t + h, w, Ts)[1]
                                      - spinning_beam.hub_angle(t - h, w, Ts)[1]) / (2 * h), abs=1e-6)
    a, b = spinning_beam.hub_angle(Ts - 1e-12, w, Ts), spinning_beam.hub_angle(Ts, w, Ts)
    assert np.allclose(a, b, atol=1e-9)


class _Unstable:
    """x'' = +1e4 x: grows like exp(100 t); must end as a flagged blow-up."""

    form, constraints, n, dense = "elimination", None, 1, True

    def __init__(self):
        self.M = np.eye(1)

    def initial(self, q0, v0):
        return np.asarray(q0, float), np.asarray(v0, float)

    def full(self, x, v, t):
        return x, v

    def acc(self, x, v, t):
        return 1e4 * x

    def acc_jacobian(self, x, v, t):
        return np.array([[1e4]]), np.zeros((1, 1))

    def tangent(self, x, v, t):
        return 1e4 * x, np.array([[-1e4]]), None


@pytest.mark.parametrize("integrator", ["rk45", "radau", "generalized-alpha"])
def test_blow_up_is_a_flag_not_an_exception(integrator):
    res = integrate(_Unstable(), [1.0], [0.0], np.linspace(0, 1, 11), integrator, dt=1e-3,
                    rho_inf=1.0)
    assert not res.converged
    assert "blow-up" in res.message
    assert np.all(np.isfinite(res.q))


def test_a_singular_mass_solve_is_a_failed_run_not_a_traceback(cli):
    """rho = 1e-30 makes the mass matrix numerically singular against the stiffness (issue
    33: a ``Singular`` traceback, exit 1, no JSON): the run stops with a non-finite
    solution named, exit 3, and its JSON whole on stdout."""
    out, _ = PEND.execute({"rho": 1e-30, "integrator": "dop853"})
    assert out["converged"] is False
    assert "singular or ill-conditioned" in out["message"]
    rc, stdout, err = cli("run", "pendulum", "--set", "rho=1e-30", "--set", "integrator=dop853",
                          "--json")
    assert rc == 3 and "Traceback" not in err
    assert json.loads(stdout)["message"] == out["message"]


@pytest.mark.parametrize("overrides", [
    {"E": 2.07e11, "integrator": "dop853", "max_steps": 300, "t_end": 0.1},
    {"integrator": "generalized-alpha", "dt": 1e-3, "max_steps": 30, "t_end": 0.1}])
def test_step_budget_is_a_flag(overrides):
    out, _ = PEND.execute(overrides)
    assert out["converged"] is False and "budget" in out["message"]
    assert all(math.isfinite(v) for v in out["results"]["tip_y"])
    assert out["results"]["t_reached"] < 0.1


def test_generalized_alpha_is_second_order():
    ref = _tips(PEND.execute({"t_end": 0.3, "rtol": 1e-11, "atol": 1e-13})[0])
    err = [np.abs(_tips(PEND.execute({"t_end": 0.3, "integrator": "generalized-alpha", "dt": dt,
                                      "rho_inf": 0.9})[0]) - ref).max() for dt in (2e-3, 1e-3)]
    assert err[0] / err[1] == pytest.approx(4.0, abs=MARGIN * 0.055)  # today 3.945


def test_generalized_alpha_steps_longer_than_the_sampling():
    """dt > output_dt: equal steps of dt over [0, t_end] (the samples at the step times are
    those of a run sampled at dt), samples in between by cubic Hermite."""
    ga = {"integrator": "generalized-alpha", "dt": 0.05}
    fine = _tips(PEND.execute({"integrator": "generalized-alpha", "dt": 1e-3})[0])
    out, _ = PEND.execute(ga)
    at_steps = _tips(PEND.execute(dict(ga, output_dt=0.05))[0])
    assert out["converged"] and len(out["results"]["times"]) == 101
    np.testing.assert_allclose(_tips(out)[:, ::5], at_steps, rtol=0, atol=1e-12)
    # today 4.01 % of L off the dt = 1e-3 run; tolerance 5 % (1.25 x)
    assert np.hypot(*(_tips(out) - fine)).max() < MARGIN * 0.0401 * L_PEND


# ---------------------------------------------------------------- acceptance (issue 3)

def test_pendulum_energy_deviation_below_thesis():
    out, _ = PEND.execute({})
    assert out["converged"]
    r = out["results"]
    assert r["energy_max_deviation_J"] < pub.PENDULUM_ENERGY_DEVIATION_J  # the thesis's
    # today 3.6e-9 J, at DOP853's rtol 1e-8: a platform may step differently, so 3 x
    assert r["energy_max_deviation_J"] < 3 * 3.6e-9
    assert len(r["times"]) == 101 and r["times"][-1] == pytest.approx(1.0)
    assert r["steps"] > 0 and r["nfev"] > 0


@pytest.mark.slow
def test_pendulum_8_and_16_elements_agree_within_1_percent_of_L():
    """Each tip coordinate (Fig. 2.6 plots the vertical one) within 1 % of L (issue 3).  The
    Euclidean tip distance is 1.03 % of L for the linear element (0.45 % for
    Omar-Shabana): the criterion holds per coordinate, not on the distance.  Today
    (x, y) differ by (0.876, 0.612) % of L; tolerance 1.25 x."""
    a, b = (PEND.execute({"n_elements": n})[0] for n in (8, 16))
    assert a["converged"] and b["converged"]
    d = np.abs(_tips(a) - _tips(b)).max(axis=1)
    assert np.all(d < 0.01 * L_PEND)
    assert np.all(d < MARGIN * np.array([0.00876, 0.00612]) * L_PEND)
    assert np.hypot(*(_tips(a) - _tips(b))).max() < MARGIN * 0.0103 * L_PEND


def test_stiff_pendulum_follows_rigid_compound_pendulum():
    """E = 2.07e11: the rigid compound pendulum of the thesis's data (g, L, h, rho).  Issue 3:
    within 0.5 % of L of the slender rod (today 0.093 %).  With the section's rotary inertia
    h^2/12 the tip is today 1.89e-5 L off and the kinetic energy, against
    1/2 I theta'^2 = -m g L/2 sin(theta), 9.0e-6 of its largest value; tolerance 1.25 x."""
    out, _ = PEND.execute({"E": 2.07e11, "integrator": "generalized-alpha", "dt": 1e-3,
                           "rho_inf": 0.8})
    rod = DYNAMIC_REFERENCES["rigid-pendulum"].execute({})[0]["results"]
    assert out["converged"]
    assert np.hypot(*(_tips(out) - np.array([rod["tip_x"], rod["tip_y"]]))).max() < 0.005 * L_PEND
    P = pub.PENDULUM
    r = out["results"]
    theta, x, y = rigid_pendulum(P["L"], P["g"], r["times"], P["h"])
    assert np.hypot(*(_tips(out) - np.array([x, y]))).max() < MARGIN * 1.89e-5 * P["L"]
    kinetic = -P["rho"] * P["b"] * P["h"] * P["L"] * P["g"] * P["L"] / 2 * np.sin(theta)
    assert np.abs(r["energy_kinetic"] - kinetic).max() < MARGIN * 9.0e-6 * kinetic.max()


@pytest.mark.slow
@pytest.mark.parametrize("integrator,tol", [("dop853", {"rtol": 1e-10, "atol": 1e-12}),
                                            ("generalized-alpha", {"dt": 1e-3})])
def test_elimination_and_multipliers_agree(integrator, tol):
    outs = {c: PEND.execute({"integrator": integrator, "constraints": c, **tol})[0]
            for c in ("elimination", "lagrange")}
    assert all(o["converged"] for o in outs.values())
    # today <= 1.1e-14 m and a violation <= 1.3e-16 m: round-off; the bounds allow the two
    # forms to step differently elsewhere (10 x rtol x L) and 1e-12 m of round-off
    assert np.abs(_tips(outs["elimination"]) - _tips(outs["lagrange"])).max() < 1e-9 * L_PEND
    assert outs["lagrange"]["results"]["constraint_violation_m"] < 1e-12


@pytest.mark.slow
@pytest.mark.parametrize("constraints", ["elimination", "lagrange"])
@pytest.mark.parametrize("integrator", ["generalized-alpha", "radau"])
def test_dense_and_sparse_paths_agree(monkeypatch, constraints, integrator):
    """The model switches from dense to sparse algebra above DENSE_MAX coordinates;
    both paths solve the same equations, so the trajectories agree to round-off
    amplified by the Newton tolerance (1e-9 m over 0.1 s; today <= 6.6e-15 m)."""
    from ancf.solvers import dynamics
    run = {"t_end": 0.1, "n_elements": 4, "integrator": integrator, "constraints": constraints}
    tips = {}
    for dense_max in (10**9, 0):
        monkeypatch.setattr(dynamics, "DENSE_MAX", dense_max)
        out = PEND.execute(run)[0]
        assert out["converged"], out["message"]
        tips[dense_max] = _tips(out)
    assert np.abs(tips[10**9] - tips[0]).max() < 1e-9


def test_rheonomic_constraint_both_forms_agree():
    """Driven hub slope: elimination vs Baumgarte-stabilised multipliers (Radau), 2 s."""
    common = {"t_end": 2.0, "mean_window": 1.0, "integrator": "radau", "rtol": 1e-6, "atol": 1e-9}
    a = SPIN.execute(dict(common, constraints="elimination"))[0]
    b = SPIN.execute(dict(common, constraints="lagrange"))[0]
    assert a["converged"] and b["converged"]
    # today 3.1e-10 m and a violation of 1.7e-11 m; Radau's Newton iterations may differ
    # with round-off on another platform: 3 x
    for key in ("tip_dx", "tip_dy"):
        assert np.abs(np.subtract(a["results"][key], b["results"][key])).max() < 3 * 3.1e-10
    assert b["results"]["constraint_violation_m"] < 3 * 1.7e-11


@pytest.mark.slow
@pytest.mark.parametrize("integrator", ["dop853", "rk45"])
def test_baumgarte_restores_a_violated_pin_critically_damped(integrator):
    """Multipliers from a pin violated by d (the beam shifted rigidly): the stabilised
    constraint acceleration C'' = -2 alpha C' - beta^2 C holds exactly (constant C_e), so with
    alpha = beta (the scenes' choice) C(t) = d (1 + beta t) exp(-beta t).  Today within
    1.7e-17 m (dop853) and 1.4e-17 m (rk45) of it for |d| = 2e-3 m, i.e. round-off (the steps
    the beam needs make beta h ~ 1e-2); tolerance 1e-12 x |d|.  Without the position term C
    stays at d; without the velocity term it oscillates."""
    p = PEND.resolve({"constraints": "lagrange", "integrator": integrator, "t_end": 0.25,
                      "rtol": 1e-10, "atol": 1e-12})
    mesh, q0, _, mdl, _ = pendulum.setup(p)
    d = np.array([1e-3, -2e-3])
    q = q0.copy()
    for node in range(mesh.n_nodes):
        q[[mesh.dof(node, "r", 0), mesh.dof(node, "r", 1)]] += d
    res = bd.simulate(p, mdl, q, np.zeros_like(q))
    assert res.converged, res.message
    C = np.array([mdl.constraints.value(qt, t) for qt, t in zip(res.q, res.t)])
    beta = p["baumgarte"]
    expected = np.outer((1 + beta * res.t) * np.exp(-beta * res.t), d)
    assert np.abs(C - expected).max() < 1e-12 * np.abs(d).max()


def _spin(omega_factor):
    """(steady extension, Eq. 2.36 with the thesis's data, largest |lateral tip offset| over
    the last mean_window) of the spinning beam at omega_factor x the thesis's omega_s."""
    P = pub.SPINNING_BEAM
    out, _ = SPIN.execute({"omega_s": omega_factor * P["omega_s"]})
    assert out["converged"], out["message"]
    r, p = out["results"], out["params"]
    exact = spinning_extension(P["L"], P["E"], P["rho"], omega_factor * P["omega_s"])
    steady = np.array(r["times"]) >= p["t_end"] - p["mean_window"]
    return r["axial_extension_m"], exact, np.abs(np.array(r["tip_lateral"])[steady]).max()


def test_spinning_beam_axial_extension_against_eq_2_36():
    """Issue 3: within 2 % of the thesis's 1.09545e-4 m, which Eq. 2.36 gives with Wu & Haug's
    tabulated area in rho A (today 5.5e-6 apart).  Today -0.0105 % off Eq. 2.36 with the
    thesis's data and a steady lateral vibration of 8.56 mm; tolerance 1.25 x."""
    ext, exact, lateral = _spin(1)
    assert abs(ext / pub.SPINNING_EXTENSION_M - 1) < 0.02
    ref = DYNAMIC_REFERENCES["spinning-extension"].execute({})[0]["results"]
    assert ref["axial_extension_thesis_m"] == pytest.approx(pub.SPINNING_EXTENSION_M,
                                                            rel=MARGIN * 5.5e-6)
    assert abs(ext / exact - 1) < MARGIN * 1.055e-4
    assert lateral < MARGIN * 8.56e-3


def test_spinning_beam_tenfold_speed_stays_stable():
    """omega_s x 10: today +0.465 % off Eq. 2.36 and a steady lateral vibration of 38.3 mm
    (no blow-up); tolerance 1.25 x."""
    ext, exact, lateral = _spin(10)
    assert abs(ext / exact - 1) < MARGIN * 4.65e-3
    assert lateral < MARGIN * 3.83e-2


@pytest.mark.parametrize("scene,data", [
    (PEND, pub.PENDULUM), (SPIN, pub.SPINNING_BEAM),
    (DYNAMIC_REFERENCES["rigid-pendulum"], {k: pub.PENDULUM[k] for k in ("L", "g")}),
    (DYNAMIC_REFERENCES["spinning-extension"],
     {k: pub.SPINNING_BEAM[k] for k in ("L", "b", "h", "E", "rho", "omega_s")})],
    ids=["pendulum", "spinning-beam", "rigid-pendulum", "spinning-extension"])
def test_defaults_are_the_thesis_problem(scene, data):
    """The defaults are the problem data the thesis states (the checks above compare
    results with references built from these data; this one also covers the constants whose
    effect no reference resolves, e.g. the flexible pendulum's E)."""
    p = scene.resolve({})
    assert {k: p[k] for k in data} == data


@pytest.mark.parametrize("scene", [PEND, SPIN], ids=["pendulum", "spinning-beam"])
@pytest.mark.parametrize("field,value", [("t_end", -1.0), ("n_elements", 0),
                                         ("integrator", "euler"), ("nu", 0.5),
                                         ("constraints", "penalty"), ("dt", 0.0)])
def test_bad_input_names_the_field(scene, field, value):
    with pytest.raises(InputError, match=field):
        scene.execute({field: value})


def test_analytic_reference_inputs():
    with pytest.raises(InputError, match="t_end"):
        DYNAMIC_REFERENCES["rigid-pendulum"].execute({"t_end": -1})
    out, _ = DYNAMIC_REFERENCES["spinning-extension"].execute({"omega_s": 1e4})
    assert out["converged"] is False and "resonance" in out["message"]


def test_pendulum_model_is_built_once_per_structure():
    """setup shares the model between runs of one structure (a new one for another g),
    and the gravity it holds is the parameter's: the sum of its gravity loads is the
    weight rho L h b g (N)."""
    p = PEND.resolve({})
    first, again = pendulum.setup(p), pendulum.setup(dict(p))
    other = pendulum.setup({**p, "g": 2.0 * p["g"]})
    assert again[3] is first[3] and other[3] is not first[3]
    first[1][:] = np.nan  # q0 is the caller's own copy
    assert np.all(np.isfinite(pendulum.setup(p)[1]))
    for (_, q0, asm, _, forces), g in ((first, p["g"]), (other, 2.0 * p["g"])):
        load = forces.value(q0, np.zeros_like(q0), 0.0)
        mass = p["rho"] * p["L"] * p["h"] * p["b"]
        assert -load.sum() == pytest.approx(mass * g, rel=1e-12)
