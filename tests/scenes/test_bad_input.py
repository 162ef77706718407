"""One test per class of issue 15 items 1-10 and 12 (the CLI fuzz replays the
examples: tests/interface/test_fuzz_cli.py)."""
import json
import math
import tomllib
import warnings
from pathlib import Path

import numpy as np
import pytest

from ancf.scenes.analytic import REFERENCES
from ancf.scenes import accuracy
from ancf.common.diagnostics import numerical_warnings
from ancf.common.inputs import MAX_INTERVALS, MAX_STEPS
from ancf.scenes import SCENES
from ancf.scenes import beam_dynamic as bd
from ancf.scenes import beam_static as bs
from ancf.scenes import pendulum
from ancf.common.params import InputError
from ancf.scenes.base import SceneResult
from ancf.common.strict_json import dumps
from ancf.core.validity import AREA_FACTOR, check_dynamic, check_static, deformation_dets, min_det

ROOT = Path(__file__).resolve().parents[2]


# ------------------------------------------------------------- 1. inverted elements
def _model(element):
    p = SCENES["axial-bar"].resolve({"element": element, "n_elements": 3})
    return bs.build(p)


def _scaled_x(mesh, q0, s):
    """q0 with every x coordinate of r and r_x scaled by s: F = diag(s, 1), det F = s."""
    q = q0.reshape(mesh.n_nodes, len(mesh.slots), 2).copy()
    for k, slot in enumerate(mesh.slots):
        if slot in ("r", "r_x"):
            q[:, k, 0] *= s
    return q.ravel()


@pytest.mark.parametrize("element", ["linear", "omar-shabana"])
@pytest.mark.parametrize("s", [2.0, 0.5, -0.5])
def test_min_det_is_the_stretch_of_a_uniform_deformation(element, s):
    mesh, q0, asm = _model(element)
    det, _ = min_det(asm.groups, _scaled_x(mesh, q0, s), q0)
    assert det == pytest.approx(s, rel=1e-12)


def test_min_det_of_a_rigid_rotation_is_one():
    mesh, q0, asm = _model("omar-shabana")
    c, s = math.cos(2.0), math.sin(2.0)
    R = np.array([[c, -s], [s, c]])
    q = (q0.reshape(-1, 2) @ R.T).ravel()
    assert np.allclose(deformation_dets(asm.groups, q, q0), 1.0, rtol=1e-12)


def test_det_follows_a_changed_reference_of_the_same_element():
    """det J0 is kept per element for its last reference: another reference of the same
    element (q0 stretched along x by 2, the state q0 itself: det F = 1/2) is not served
    the kept one (which would give 1)."""
    mesh, q0, asm = _model("linear")
    assert min_det(asm.groups, q0, q0)[0] == pytest.approx(1.0, rel=1e-12)
    assert min_det(asm.groups, q0, _scaled_x(mesh, q0, 2.0))[0] == pytest.approx(0.5, rel=1e-12)
    assert min_det(asm.groups, q0, q0)[0] == pytest.approx(1.0, rel=1e-12)


def test_min_det_names_the_inverted_element():
    mesh, q0, asm = _model("linear")
    q = q0.copy()
    q[mesh.dof(2, "r", 0)] = q0[mesh.dof(0, "r", 0)] - 0.1  # node 2 behind node 0
    det, element = min_det(asm.groups, q, q0)
    assert det < 0 and element == 1  # the second element goes backwards


def test_static_inverted_equilibrium_is_not_converged():
    out, res = SCENES["axial-bar"].execute({"F": "-5e8"})
    p = out["params"]
    mesh, q0, asm = bs.build(p)
    det, element = min_det(asm.groups, res.extra["q"], q0)
    assert det <= 0 and out["converged"] is False
    assert f"element {element + 1} of {p['n_elements']} is inverted" in out["message"]
    assert f"{det:.3g}" in out["message"]
    assert out["results"]["elongation_m"] < -p["L"]  # kept, flagged: the bar passed through itself


@pytest.mark.parametrize("s,warned", [(0.75 * AREA_FACTOR, False), (1.5 * AREA_FACTOR, True),
                                      (1 / (1.5 * AREA_FACTOR), True)])
def test_static_area_change_beyond_the_material_range_warns(s, warned):
    mesh, q0, asm = _model("linear")
    res = check_static(SceneResult(True, "converged", {}, extra={"q": _scaled_x(mesh, q0, s)}), asm, q0)
    assert res.converged and bool(res.warnings) is warned
    assert all(f"changes its area by a factor {max(s, 1 / s):.3g}:" in w for w in res.warnings)


def test_dynamic_history_is_trusted_up_to_the_first_inverted_sample():
    mesh, q0, asm = _model("linear")
    t = np.array([0.0, 0.1, 0.2, 0.3])
    Q = np.stack([q0, _scaled_x(mesh, q0, 0.5), _scaled_x(mesh, q0, -0.5), q0])
    res = check_dynamic(SceneResult(True, "reached t_end", {}), asm, q0, t, Q)
    assert res.converged is False and res.message.startswith(f"Not trusted from t = {t[2]:g} s")


# ---------------------------------------------------------------------- 2. warnings
def test_default_runs_have_no_warnings():
    for name in ("simply-supported", "cantilever", "axial-bar"):
        assert SCENES[name].execute({})[0]["warnings"] == []
    for ref in REFERENCES.values():
        assert ref.execute({})[0]["warnings"] == []


def test_pendulum_energy_drift_warns_against_m_g_L():
    ga = {"integrator": "generalized-alpha"}
    coarse, _ = SCENES["pendulum"].execute({**ga, "dt": "0.05"})
    fine, _ = SCENES["pendulum"].execute({**ga, "t_end": "0.2"})
    p = coarse["params"]
    scale = p["rho"] * p["b"] * p["h"] * p["L"] ** 2 * p["g"]
    dev = coarse["results"]["energy_max_deviation_J"]
    assert dev > pendulum.ENERGY_DRIFT_REL * scale
    assert any(w.startswith(f"energy drift {dev:.3g} J") for w in coarse["warnings"])
    assert fine["results"]["energy_max_deviation_J"] < pendulum.ENERGY_DRIFT_REL * scale
    assert fine["warnings"] == []


def test_step_warning_follows_the_first_bending_period():
    p = SCENES["pendulum"].resolve({"integrator": "generalized-alpha"})
    period = accuracy.bending_period(p, accuracy.PINNED_FREE)
    ok = dict(p, dt=period / accuracy.STEPS_PER_PERIOD)
    coarse = dict(p, dt=1.01 * period / accuracy.STEPS_PER_PERIOD)
    assert accuracy.step(ok, period, "mode") == []
    assert len(accuracy.step(coarse, period, "mode")) == 1
    assert math.tan(accuracy.PINNED_FREE) == pytest.approx(math.tanh(accuracy.PINNED_FREE))
    assert math.cos(accuracy.CLAMPED_FREE) * math.cosh(accuracy.CLAMPED_FREE) == pytest.approx(-1.0)


def test_newton_at_the_round_off_floor_warns():
    out, res = SCENES["cantilever"].execute({"rtol": "1e-300"})
    final = res.extra["residuals"][-1][-1]
    assert out["converged"] and final > 1e-300 * abs(out["params"]["F"])
    assert any(w.startswith(f"Newton stopped at the round-off floor: final residual {final:.3g} N")
               for w in out["warnings"])


# ---------------------------------------------------------------- 3. sample cap
@pytest.mark.parametrize("name,registry", [("pendulum", SCENES), ("spinning-beam", SCENES),
                                           ("rigid-pendulum", REFERENCES)])
def test_output_samples_are_capped(name, registry):
    sc = registry[name]
    t_end = sc.resolve({})["t_end"]
    p = sc.resolve({"output_dt": repr(t_end / MAX_INTERVALS)})
    assert bd.times(p).size == MAX_INTERVALS + 1
    with pytest.raises(InputError, match=rf"^output_dt = .* \(at most {MAX_INTERVALS + 1} samples\)"):
        sc.resolve({"output_dt": repr(0.999 * t_end / MAX_INTERVALS)})


@pytest.mark.parametrize("name", ["pendulum", "spinning-beam"])
def test_fixed_steps_are_capped(name):
    sc = SCENES[name]
    ga = {"integrator": "generalized-alpha", "t_end": "1"}
    assert sc.resolve({**ga, "dt": repr(1.0 / MAX_STEPS)})["dt"] == 1.0 / MAX_STEPS
    with pytest.raises(InputError, match=rf"^dt = .* \(at most {MAX_STEPS} steps\)"):
        sc.resolve({**ga, "dt": repr(0.999 / MAX_STEPS)})
    assert sc.resolve({"integrator": "bdf", "t_end": "1", "dt": repr(0.999 / MAX_STEPS)})  # unused


# ---------------------------------------------------------------- 4. strict JSON
def test_non_finite_values_are_null():
    text = dumps({"a": float("nan"), "b": [1.0, float("inf"), {"c": -float("inf")}], "d": np.float64("nan")})
    assert json.loads(text) == {"a": None, "b": [1.0, None, {"c": None}], "d": None}
    with pytest.raises(ValueError):
        json.dumps(float("nan"), allow_nan=False)


def test_spinning_extension_at_rest_is_zero():
    assert REFERENCES["spinning-extension"].execute({"omega_s": "0"})[0]["results"]["axial_extension_m"] == 0.0


def test_a_converged_run_with_a_non_finite_result_is_not_converged():
    from ancf.common.params import Param
    from ancf.scenes.base import Scene
    sc = Scene("overflowing", "a run claiming convergence with an overflowed result",
               (Param("x", 1e300, float, "-", "a value"),),
               lambda p: SceneResult(True, "closed form", {"mid_deflection_m": p["x"] * 1e10}))
    with np.errstate(over="ignore"):
        out, _ = sc.execute({})
    assert out["converged"] is False and "mid_deflection_m" in out["message"]
    # the inputs that used to get there in `ancf analytic timoshenko` are now refused up
    # front, naming the field (issue 22)
    with pytest.raises(InputError, match=r"^E = 1e-300 is out of range: the shear modulus"):
        REFERENCES["timoshenko"].execute({"E": "1e-300", "F": "-1e300"})


# ---------------------------------------------------------- 8. dependent defaults
def test_sampling_and_window_defaults_follow_t_end():
    sp = SCENES["spinning-beam"].resolve({"t_end": "1"})
    assert sp["mean_window"] == sp["t_end"] and sp["output_dt"] <= sp["t_end"]
    pe = SCENES["pendulum"].resolve({"t_end": "0.005"})
    assert pe["output_dt"] == pe["t_end"]
    long = REFERENCES["rigid-pendulum"].resolve({"t_end": "10000"})
    assert long["output_dt"] == long["t_end"] / MAX_INTERVALS
    assert SCENES["pendulum"].resolve({}) == SCENES["pendulum"].resolve({"output_dt": "0.01"})


# ---------------------------------------------------------------- 9. rtol floor
def test_dynamic_rtol_below_scipys_floor_is_rejected():
    floor = float(100 * np.finfo(float).eps)
    p = SCENES["pendulum"].resolve({"rtol": repr(floor)})
    assert p["rtol"] == floor
    with pytest.raises(InputError, match=r"^rtol = 1e-300 is out of range; allowed: a number in \["):
        SCENES["pendulum"].resolve({"rtol": "1e-300"})
    with warnings.catch_warnings():
        warnings.simplefilter("error")  # scipy warns when it raises rtol itself
        out, _ = SCENES["pendulum"].execute({"rtol": repr(floor), "t_end": "0.01"})
    assert out["params"]["rtol"] == floor and out["warnings"] == []


# ------------------------------------------------------- 10. numerical warnings
def test_numerical_warnings_become_one_line():
    with numerical_warnings() as noted:
        for _ in range(3):
            np.float64(1e308) * 10.0
        np.float64(0.0) / 0.0
    assert noted == [noted[0]] and noted[0].startswith("numerical: 4 floating-point warning(s)")
    assert "and 1 other kind(s)" in noted[0]


def test_a_scene_at_the_floating_point_limit_reports_one_line(capsys):
    """At E = 1e-300 the compiled Newton raises no numpy warning at all; the run says why it
    stopped, and at most one numerical line is added, never printed as noise."""
    out, _ = SCENES["axial-bar"].execute({"E": "1e-300"})
    assert not out["converged"] and "not finite" in out["message"]
    assert [w for w in out["warnings"] if w.startswith("numerical: ")] == out["warnings"]
    assert len(out["warnings"]) <= 1 and capsys.readouterr().err == ""


# --------------------------------------------------------------- 12. description
def test_package_metadata_describes_what_exists():
    meta = tomllib.loads((ROOT / "pyproject.toml").read_text())["project"]
    assert meta["license"] == "MIT"
    assert "planned" not in meta["description"] and "belt drives (2D and 3D)" in meta["description"]
    readme = (ROOT / "README.md").read_text()
    assert "the 3D\nbelt drive of thin plates" in readme and "planned" not in readme.split("##")[0]
