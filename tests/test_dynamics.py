"""Dynamics: equations of motion, constraint forms, integrators, dynamic scenes.

Acceptance checks of issue 3 (tolerances as stated there) plus unit checks of the
pieces.  Tolerances of the unit checks: gravity, mass and kinetic energy are
exact integrals, so 1e-12 relative (round-off); the Jacobian checks use central
differences with step h = 1e-6 on states of size ~1, whose truncation error is
~1e-12 |f'''|, hence 1e-6 relative to the largest entry, plus the round-off
10 eps |acc| / h.
"""
from __future__ import annotations

import math

import numpy as np
import pytest

from analytic.dynamics_refs import DYNAMIC_REFERENCES
from ancf.constraints import Elimination
from ancf.forces import Forces, Gravity
from ancf.scenes import beam_static as bs
from ancf.scenes import pendulum, spinning_beam
from ancf.scenes.base import InputError
from ancf.energy import energy_history
from ancf.solvers.dynamics import integrate

PEND, SPIN = pendulum.SCENE, spinning_beam.SCENE
L_PEND = 2.0
THESIS_ENERGY_DEVIATION = 0.62e-4  # J, thesis 2.4 (4 elements)
THESIS_EXTENSION = 1.09545e-4      # m, thesis 2.4 (Eq. 2.36)


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
    assert 3.0 < err[0] / err[1] < 5.0  # ~4 for second order


def test_generalized_alpha_steps_longer_than_the_sampling():
    """dt > output_dt: equal steps of dt over [0, t_end], samples by cubic Hermite."""
    fine = _tips(PEND.execute({"integrator": "generalized-alpha", "dt": 1e-3})[0])
    out, _ = PEND.execute({"integrator": "generalized-alpha", "dt": 0.05})
    assert out["converged"] and out["results"]["steps"] == 20
    assert len(out["results"]["times"]) == 101
    assert np.hypot(*(_tips(out) - fine)).max() < 0.05 * L_PEND  # first-order-ish at 0.05 s


# ---------------------------------------------------------------- acceptance (issue 3)

def test_pendulum_energy_deviation_below_thesis():
    out, _ = PEND.execute({})
    assert out["converged"]
    r = out["results"]
    assert r["energy_max_deviation_J"] < THESIS_ENERGY_DEVIATION
    assert len(r["times"]) == 101 and r["times"][-1] == pytest.approx(1.0)
    assert r["steps"] > 0 and r["nfev"] > 0


def test_pendulum_8_and_16_elements_agree_within_1_percent_of_L():
    """Each tip coordinate (Fig. 2.6 plots the vertical one) within 1 % of L.  The
    Euclidean tip distance is 1.03 % of L for the linear element (0.45 % for
    Omar-Shabana): the criterion holds per coordinate, not on the distance."""
    a, b = (PEND.execute({"n_elements": n})[0] for n in (8, 16))
    assert a["converged"] and b["converged"]
    d = np.abs(_tips(a) - _tips(b)).max(axis=1)
    assert d[1] < 0.01 * L_PEND and d[0] < 0.01 * L_PEND
    assert np.hypot(*(_tips(a) - _tips(b))).max() < 0.011 * L_PEND


def test_stiff_pendulum_follows_rigid_compound_pendulum():
    out, _ = PEND.execute({"E": 2.07e11, "integrator": "generalized-alpha", "dt": 1e-3,
                           "rho_inf": 0.8})
    ref = DYNAMIC_REFERENCES["rigid-pendulum"].execute({})[0]["results"]
    assert out["converged"]
    d = np.hypot(*(_tips(out) - np.array([ref["tip_x"], ref["tip_y"]]))).max()
    assert d < 0.005 * L_PEND


@pytest.mark.parametrize("integrator,tol", [("dop853", {"rtol": 1e-10, "atol": 1e-12}),
                                            ("generalized-alpha", {"dt": 1e-3})])
def test_elimination_and_multipliers_agree(integrator, tol):
    outs = {c: PEND.execute({"integrator": integrator, "constraints": c, **tol})[0]
            for c in ("elimination", "lagrange")}
    assert all(o["converged"] for o in outs.values())
    assert np.abs(_tips(outs["elimination"]) - _tips(outs["lagrange"])).max() < 1e-6
    assert outs["lagrange"]["results"]["constraint_violation_m"] < 1e-8


@pytest.mark.parametrize("constraints", ["elimination", "lagrange"])
@pytest.mark.parametrize("integrator", ["generalized-alpha", "radau"])
def test_dense_and_sparse_paths_agree(monkeypatch, constraints, integrator):
    """The model switches from dense to sparse algebra above DENSE_MAX coordinates;
    both paths solve the same equations, so the trajectories agree to round-off
    amplified by the Newton tolerance (1e-9 m over 0.1 s)."""
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
    for key in ("tip_dx", "tip_dy"):
        assert np.abs(np.subtract(a["results"][key], b["results"][key])).max() < 1e-6
    assert b["results"]["constraint_violation_m"] < 1e-8


def test_spinning_beam_axial_extension_within_2_percent():
    out, _ = SPIN.execute({})
    assert out["converged"]
    ext = out["results"]["axial_extension_m"]
    assert abs(ext / THESIS_EXTENSION - 1) < 0.02
    ref = DYNAMIC_REFERENCES["spinning-extension"].execute({})[0]["results"]
    assert ref["axial_extension_thesis_m"] == pytest.approx(THESIS_EXTENSION, rel=1e-5)
    assert abs(ext / ref["axial_extension_m"] - 1) < 0.02


def test_spinning_beam_tenfold_speed_stays_stable():
    out, _ = SPIN.execute({"omega_s": 40.0})
    r = out["results"]
    assert out["converged"], out["message"]
    assert np.all(np.isfinite(r["tip_dx"])) and max(np.abs(r["tip_lateral"])) < 8.0
    ref = DYNAMIC_REFERENCES["spinning-extension"].execute({"omega_s": 40.0})[0]["results"]
    assert abs(r["axial_extension_m"] / ref["axial_extension_m"] - 1) < 0.02


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
