"""The ALE march of a 2D drive (ancf.belts.ale_march2d, ``belt.formulation = "ale"``):
its window means against the steady solve (ancf.belts.steady2d, a different method: one
Newton solve, no march), the key choosing the march, the formulations it refuses."""
from __future__ import annotations

import numpy as np
import pytest

from ancf.belts.drive_file import load
from ancf.common.params import InputError
from ancf.common.paths import REPO
from ancf.scenes import belt_drive, belt_steady

THREAD = str(REPO / "examples" / "thread_creep_rate.toml")
#: THREAD's creep-rate drive made quick: 30 elements, the driver's ramp over 0.1 s, the load
#: over 0.1-0.2 s, the driven pulley light (0.01 kg m^2: its torsional mode damped in a few
#: periods by its 2 N m s), the window 0.3-0.4 s
SMALL = ["belt.n_elements=30", "pulleys.driver.t0=0.0", "pulleys.driver.t1=0.1",
         "pulleys.driven.t0=0.1", "pulleys.driven.t1=0.2", "pulleys.driven.inertia=0.01",
         "run.t_end=0.4", "run.output_dt=0.01", "run.steady_window=0.1", "run.dt=1e-3"]
#: relative tolerances of the march's window means against the steady state
SPEED_TOL, TENSION_TOL = 2e-4, 5e-4


def _params(extra=()) -> dict:
    return {"file": THREAD, "set": "; ".join(SMALL + list(extra)), "n_elements": None,
            "dt": None, "gauss_points": None}


def _steady(extra=()) -> tuple:
    """(driven pulley's omega rad/s, span tensions N) of the steady solve."""
    r = belt_steady.run(_params(extra), max_loads=False)
    assert r.converged, r.message
    return r.results["pulleys"][1]["omega"], [s["tension_mean_N"] for s in r.results["spans"]]


def _rel(a, b) -> float:
    return float(np.max(np.abs(np.subtract(a, b)) / np.abs(b)))


@pytest.fixture(scope="module")
def ale():
    r = belt_drive.run(_params(["belt.formulation=ale"]))
    assert r.converged, r.message
    return r.results


def test_ale_march_reaches_the_steady_state(ale):
    """The ALE march's window means (driven pulley's speed, both span tensions) are the
    steady solve's within SPEED_TOL and TENSION_TOL; 2 % more load moves the steady
    state beyond them (the comparison can fail)."""
    omega, spans = _steady()
    assert _rel(ale["pulleys"][1]["omega_mean"], omega) <= SPEED_TOL
    assert _rel([s["tension_mean_N"] for s in ale["spans"]], spans) <= TENSION_TOL
    assert ale["integrator"] == "generalized-alpha (ALE)"
    omega2, spans2 = _steady(["pulleys.driven.load_torque=25.5"])
    assert _rel([s["tension_mean_N"] for s in ale["spans"]], spans2) > 10 * TENSION_TOL
    assert _rel(ale["pulleys"][1]["omega_mean"], omega2) > SPEED_TOL


def test_the_key_chooses_the_march_lagrangian_by_default(ale):
    """A file without belt.formulation is Lagrangian; over the first 0.05 s (the belt
    pulled up to speed) the two marches agree to 1 % in the driven pulley's speed and the
    belt's, but are not the same computation."""
    assert load(THREAD, []).belt["formulation"] == "lagrangian"
    short = ["run.t_end=0.05", "run.steady_window=0.01", "run.dt=2.5e-4"]
    lag = belt_drive.run(_params(short))
    fast = belt_drive.run(_params(short + ["belt.formulation=ale"]))
    assert lag.converged and fast.converged
    assert lag.results["integrator"] == "generalized-alpha"
    a, b = (np.array(r.results["pulleys"][1]["omega"][-3:]) for r in (fast, lag))
    assert _rel(a, b) <= 0.01
    assert _rel(a, b) > 1e-9
    sa, sb = (np.mean(r.results["speed_m_s"]) for r in (fast, lag))
    assert abs(sa - sb) <= 0.01 * sb


@pytest.mark.parametrize("example, extra, message", [
    ("thesis_table_3_1", ["belt.formulation=eulerian"], "belt.formulation = 'eulerian' is out "
     "of range; allowed: one of lagrangian, ale"),
    ("three_pulleys_3d", ["belt.formulation=ale"], "belt.formulation = 'ale' is out of range "
     "for belt.element = 'plate36'; allowed: one of lagrangian"),
    ("thread_benchmark", ["belt.formulation=ale"], "belt.formulation = 'ale' with "
     "friction.law = 'bristle'.*allowed: friction.law one of creep-rate, coulomb"),
    ("serpentine", ["belt.formulation=ale"], r"belt.formulation = 'ale' with a tensioner "
     r"\(pulleys.1\).*allowed: belt.formulation = 'lagrangian'"),
])
def test_what_the_ale_march_cannot_carry_is_one_line(example, extra, message):
    with pytest.raises(InputError, match=message) as exc:
        load(str(REPO / "examples" / f"{example}.toml"), extra)
    assert "\n" not in str(exc.value)
    load(str(REPO / "examples" / f"{example}.toml"), [])  # without the key: fine
