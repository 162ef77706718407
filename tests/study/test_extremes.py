"""Stability at the extremes (issue 4, part 5): pinned behaviour.

* no shear locking of the thesis scheme at L/h = 1e4 (small-deflection cantilever,
  64 elements, error against Timoshenko < 1 %); exact integration locks there (> 50 %);
* every diverging case is reported (a row with a diagnosis), never raised or hung;
* every axis of the issue is declared, with the ones that need a missing scene saying so.
"""
import math

import pandas as pd
import pytest

from ancf.study import extremes
from ancf.reports.extremes import axis_map
from ancf.study.sweep import run_sweep

ISSUE_AXES = {"slenderness", "poisson", "elements", "load", "spinning", "penalty", "nu_s",
              "time-steps", "load-steps", "stiff-steps"}


def _run(workdir, name, grids, **kw):
    kw.setdefault("time_limit", 60.0)
    return run_sweep("cantilever", grids, out=workdir / f"{name}.parquet", workers=2,
                     progress=False, log=lambda m: None, **kw)


@pytest.fixture(scope="module")
def slender(workdir):
    sl = extremes.small_load(1e4)
    return _run(workdir, "slender", {"element": ["linear"], "integration": ["thesis", "exact"],
                                 "n_elements": [64], "nu": [0.3], "load_steps": [1], **{
                                     k: [v] for k, v in sl.items()}}, reference="timoshenko")


@pytest.mark.slow
def test_thesis_scheme_does_not_lock_at_slenderness_1e4(slender):
    """The issue asks < 1 %; today 6.21e-5 (the 64 elements' discretisation error), 1.25 x."""
    r = slender[slender["integration"] == "thesis"].iloc[0]
    assert r["h"] == pytest.approx(2e-4)
    assert r["status"] == "ok" and r["error"] < 0.01
    assert r["error"] < 1.25 * 6.21e-5


def test_exact_integration_locks_at_slenderness_1e4(slender):
    """The issue asks > 50 %; today the locked tip deflects 1.28e-4 of Timoshenko's value
    (error 1 - 1.28e-4); at most 1.25 x that."""
    r = slender[slender["integration"] == "exact"].iloc[0]
    assert r["status"] == "ok" and r["error"] > 0.5
    assert 1 - r["error"] < 1.25 * 1.28e-4


@pytest.mark.slow
def test_diverging_cases_are_reported_with_a_diagnosis(workdir):
    grids = [
        # Newton cannot converge with one iteration per step: diverged, with the load factor
        {"F": [-5e6], "n_elements": [16], "max_iterations": [1, 3]},
        # report's 1-point shear scheme, Model 2, 32 elements: unstable equilibrium
        {"integration": ["report-selective"], "h": [0.5], "nu": [0.0], "n_elements": [32]},
        # nearly incompressible, 10x load, many elements: converged or diagnosed
        {"element": ["omar-shabana"], "nu": [0.499], "F": [-5e6], "n_elements": [64]},
        # a run over its time limit
        {"element": ["omar-shabana"], "n_elements": [4096], "stability_check": ["off"]},
    ]
    df = _run(workdir, "diverging", grids, time_limit=0.5)
    df["diagnosis"] = [extremes.diagnosis(r) for _, r in df.iterrows()]
    assert len(df) == 5
    for _, r in df.iterrows():
        if r["status"] == "ok":
            assert math.isfinite(r["error"]) and math.isfinite(r["res_tip_y"])
        else:
            assert r["message"] and r["diagnosis"] != "ok" and math.isnan(r["error"])
    diag = set(df["diagnosis"])
    assert {"Newton diverged at load factor 0", "unstable equilibrium",
            "time limit exceeded"} <= diag
    slow = df[df["status"] == "timeout"].iloc[0]
    assert slow["message"] == "time limit exceeded (0.5 s)" and slow["wall_time_s"] < 30


@pytest.mark.slow
def test_stiff_pendulum_steps_end_in_a_result_or_a_diagnosis(workdir):
    """E = 2.07e11 pendulum: an explicit scheme runs out of its step budget (stable step
    ~1e-5 s), BDF at a loose tolerance blows up, generalised-alpha at 1000x the explicit
    step stays within 1 % of L of the rigid pendulum (today 7.62e-4; tolerance 1.25 x)."""
    stiff = {"E": [2.07e11], "n_elements": [4], "t_end": [0.05]}
    grids = [{"integrator": ["dop853"], "rtol": [1e-2], "max_steps": [200], **stiff},
             {"integrator": ["bdf"], "rtol": [1e-2], **stiff},
             {"integrator": ["generalized-alpha"], "dt": [0.01], **dict(stiff, t_end=[1.0])}]
    df = run_sweep("pendulum", grids, out=workdir / "stiff.parquet", workers=2, progress=False,
                   log=lambda m: None, reference="rigid-pendulum", time_limit=120.0)
    diag = {r["integrator"]: extremes.diagnosis(r) for _, r in df.iterrows()}
    assert diag == {"dop853": "step budget exceeded", "bdf": "energy blow-up",
                    "generalized-alpha": "ok"}
    ok = df[df["integrator"] == "generalized-alpha"].iloc[0]
    assert ok["error"] < 1e-2 and ok["error"] < 1.25 * 7.62e-4


def test_every_issue_axis_is_declared_and_missing_scenes_are_said():
    names = {a.name for a in extremes.AXES}
    assert ISSUE_AXES <= names
    for a in extremes.AXES:
        ok, why = a.applicable()
        if a.name in ("penalty", "nu_s"):
            assert ok and a.scene == "belt2d" and a.reference == "no-slip"
        elif not ok:
            assert why.startswith("not applicable yet")


def _belt_ends(workdir):
    """Both ends of the penalty and nu_s axes, as the axes run them (t_end = 0.6 s)."""
    ax = {a.name: a for a in extremes.AXES}
    grids = [dict(g, **{k: [v] for k, v in pin.items()})
             for name, values in (("penalty", (1e4, 1e10)), ("nu_s", (1e2, 1e7)))
             for g in ax[name].grids() for pin in ({ax[name].column: x} for x in values)]
    df = run_sweep("belt2d", grids, out=workdir / "belt_ends.parquet", workers=2, progress=False,
                   log=lambda m: None, reference="no-slip", time_limit=120.0)
    df["diagnosis"] = [extremes.diagnosis(r) for _, r in df.iterrows()]
    df["diagnosis"] = [(extremes.belt_warning(r) or d) if d == "ok" else d
                       for d, (_, r) in zip(df["diagnosis"], df.iterrows())]
    return df


@pytest.mark.slow
def test_belt_contact_extremes_end_in_a_result_or_a_diagnosis(workdir):
    """Soft penalty (k_p = 1e4): the belt sinks into the pulleys by more than its
    pre-stretch per wrap and slips (today 83 %); tiny nu_s (1e2): slip (today 85 %);
    k_p = 1e10 and nu_s = 1e7: Newton fails even at dt/16 (today at t = 0.257 s and
    0.0528 s, during the ramp)."""
    df = _belt_ends(workdir)
    soft, stiff = df[df["k_p"] == 1e4].iloc[0], df[df["k_p"] == 1e10].iloc[0]
    slow, sticky = df[df["nu_s"] == 1e2].iloc[0], df[df["nu_s"] == 1e7].iloc[0]
    pre = extremes.belt_prestretch(soft)
    assert pre == pytest.approx((1.27627 - 1.2727) / (2 * math.pi), rel=1e-3)
    assert soft["status"] == "ok" and soft["res_penetration_max_m"] > 0.5 * pre
    assert soft["diagnosis"].startswith("penetration") and soft["error"] > 0.5
    assert slow["status"] == "ok" and slow["diagnosis"].startswith("slip") and slow["error"] > 0.5
    for r in (stiff, sticky):
        assert r["status"] == "not-converged" and math.isnan(r["error"])
        assert r["diagnosis"].startswith("Newton failed at t = ")


@pytest.mark.parametrize("message,status,expected", [
    ("no convergence: Newton failed at t = 0.05275 s even with steps of dt/2^4", "not-converged",
     "Newton failed at t = 0.05275 s"),
    ("No convergence: singular tangent stiffness (x); load factor reached 0.5000", "not-converged",
     "singular tangent"),
    ("No convergence: no convergence in 25 iterations (|r| = 1e3); load factor reached 0.2500 "
     "(increment fell below 0.000244141)", "not-converged", "Newton diverged at load factor 0.25"),
    ("No convergence to a stable equilibrium: Newton converged to a point with 2 negative "
     "tangent eigenvalue(s)", "not-converged", "unstable equilibrium"),
    ("time limit exceeded (3 s)", "timeout", "time limit exceeded"),
    ("diverged at step 17: energy blow-up", "not-converged", "energy blow-up"),
    ("step size collapse at t = 0.1", "not-converged", "step size collapse"),
    ("converged", "ok", "ok"),
    ("Not trusted from t = 0.74 s on: element 1 of 4 is inverted (det of the deformation "
     "gradient -0.2 <= 0 at a quadrature point)", "not-converged", "element inverted at t = 0.74 s"),
    ("No convergence to a physical equilibrium: element 3 of 4 is inverted (det -1.19)",
     "not-converged", "inverted element"),
])
def test_diagnosis_labels(message, status, expected):
    assert extremes.diagnosis({"status": status, "message": message}) == expected


def test_axis_map_marks_cells():
    ax = next(a for a in extremes.AXES if a.name == "poisson")
    df = pd.DataFrame([
        {"element": "linear", "integration": "thesis", "n_elements": 8, "nu": 0.0,
         "status": "ok", "error": 1e-3, "message": "converged"},
        {"element": "linear", "integration": "thesis", "n_elements": 8, "nu": 0.499,
         "status": "not-converged", "error": float("nan"),
         "message": "No convergence: x; load factor reached 0.1000"}])
    df["diagnosis"] = [extremes.diagnosis(r) for _, r in df.iterrows()]
    m = axis_map(ax, df)
    assert m.iloc[0, 1] == "✓ 1.0e-03" and m.iloc[0, 2].startswith("⚠ Newton diverged")
