"""The ALE march of a 2D drive (ancf.belts.ale_march2d, ``belt.formulation = "ale"``):
its window means against the steady solve (ancf.belts.steady2d, a different method: one
Newton solve, no march) on THREAD's two pulleys and on the serpentine with its tensioner
arm, the iteration matrix against central differences, the key choosing the march, the
formulations it refuses."""
from __future__ import annotations

import numpy as np
import pytest

from ancf.belts.ale_march2d import AleSystem, _laws
from ancf.belts.arm2d import COORD
from ancf.belts.drive_file import load
from ancf.belts.drive_model import build
from ancf.belts.pretension import settle
from ancf.common.params import InputError
from ancf.common.paths import REPO
from ancf.scenes import belt_drive, belt_steady

THREAD = str(REPO / "examples" / "thread_creep_rate.toml")
SERPENTINE = str(REPO / "examples" / "serpentine.toml")
#: THREAD's creep-rate drive made quick: 30 elements, the driver's ramp over 0.1 s, the load
#: over 0.1-0.2 s, the driven pulley light (0.01 kg m^2: its torsional mode damped in a few
#: periods by its 2 N m s), the window 0.3-0.4 s
SMALL = ["belt.n_elements=30", "pulleys.driver.t0=0.0", "pulleys.driver.t1=0.1",
         "pulleys.driven.t0=0.1", "pulleys.driven.t1=0.2", "pulleys.driven.inertia=0.01",
         "run.t_end=0.4", "run.output_dt=0.01", "run.steady_window=0.1", "run.dt=1e-3"]
#: relative tolerances of the march's window means against the steady state
SPEED_TOL, TENSION_TOL = 2e-4, 5e-4


#: the serpentine made quick: 30 elements, the crank's ramp over 0.1 s, the loads over
#: 0.1-0.2 s, steps of 2 ms, the window 0.3-0.4 s
SERP = ["belt.n_elements=30", "pulleys.crank.t0=0.0", "pulleys.crank.t1=0.1",
        "pulleys.alternator.t0=0.1", "pulleys.alternator.t1=0.2", "pulleys.pump.t0=0.1",
        "pulleys.pump.t1=0.2", "run.t_end=0.4", "run.output_dt=0.01",
        "run.steady_window=0.1", "run.dt=2e-3"]
#: the serpentine's tolerances: free pulleys' speeds (relative) and arm angle (rad)
SERP_SPEED_TOL, ARM_TOL = 5e-5, 1e-4
#: the iteration matrix against central differences, relative to a column's (row's) largest
FD_TOL = 1e-6


def _params(extra=(), base=None, file=THREAD) -> dict:
    base = SMALL if base is None else base
    return {"file": file, "set": "; ".join(base + list(extra)), "n_elements": None,
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


def _serpentine_steady(extra=()) -> tuple:
    """(the free pulleys' omegas rad/s, the arm's angle rad) of the serpentine's steady
    solve."""
    r = belt_steady.run(_params(extra, SERP, SERPENTINE), max_loads=False)
    assert r.converged, r.message
    free = [q["omega"] for q in r.results["pulleys"][1:]]
    return np.array(free), r.results["arms"][0]["angle_rad"]


def test_serpentine_with_its_tensioner_reaches_the_steady_state():
    """The serpentine marched in ALE (tensioner arm, alternator, idler, pump free): its
    free pulleys' window-mean speeds within SERP_SPEED_TOL of the steady solve's (seen
    2e-5), the arm's mean angle within ARM_TOL rad (seen 5e-5 rad); 5 % more alternator
    load and 2 % more arm preload move the steady state beyond both (the test can fail)."""
    r = belt_drive.run(_params(["belt.formulation=ale"], SERP, SERPENTINE))
    assert r.converged, r.message
    got = r.results
    omega = np.array([q["omega_mean"] for q in got["pulleys"][1:]])
    angle = got["arms"][0]["angle_mean_rad"]
    want, arm = _serpentine_steady()
    assert _rel(omega, want) <= SERP_SPEED_TOL
    assert abs(angle - arm) <= ARM_TOL
    want2, arm2 = _serpentine_steady(["pulleys.alternator.load_torque=2.1",
                                      "pulleys.tensioner.arm_preload=-6.987"])
    assert _rel(omega, want2) > 3 * SERP_SPEED_TOL
    assert abs(angle - arm2) > 3 * ARM_TOL


@pytest.fixture(scope="module")
def serpentine_system():
    """(AleSystem of the quick serpentine at its settled belt, a state y, yd, ydd in the
    full layout: running at vb = 5 m/s, the mesh, pulleys and arm with rates, loads on);
    the tensioner pulley's bearing damping 0.01 N m s, so its coupling with the arm shows."""
    drive = build(load(SERPENTINE, SERP + ["belt.formulation=ale",
                                           "pulleys.tensioner.damping=0.01"]))
    x0, pre = settle(drive)
    assert pre.converged
    s = AleSystem(drive, x0)
    rng = np.random.default_rng(3)
    y = s.full(np.delete(np.concatenate([x0[: s.n], [0.0], x0[s.n:]]), s.gauge), x0[s.gauge])
    yd = np.concatenate([1e-3 * rng.standard_normal(s.n), [5.0], 10 * rng.standard_normal(s.k)])
    yd[s.n + 1 + int(drive.rig.arms[0, COORD])] = 0.3
    return s, y, yd, rng.standard_normal(y.size), _laws(drive, 0.6)


def test_iteration_matrix_matches_central_differences(serpentine_system):
    """S = dR/d(acc) with positions and rates moved by beta' and gamma' (the step's
    kinematics; beta', gamma' large enough that stiffness and damping outweigh the mass)
    against central differences of R (step 1e-3 m/s^2 in the accelerations), every 7th
    belt column and every column past the belt (vb, pulleys, arm): within FD_TOL of each
    column's largest entry (seen 1.7e-7) and, in the rows past the belt, of each row's
    (seen 6.5e-8).  The arm's couplings with the belt (its row's and its column's belt
    entries) exceed 100 FD_TOL of those scales, so leaving them out fails (as does
    leaving out c_j's coupling of pulley and arm, checked by hand)."""
    s, y, yd, ydd, laws = serpentine_system
    bp, gp, h = 1e-5, 3e-3, 1e-3
    S = s.evaluate(y, yd, ydd, laws, (bp, gp))[4].toarray()
    cols = list(range(0, s.n - 1, 7)) + list(range(s.n - 1, s.keep.size))
    fd = np.zeros((S.shape[0], len(cols)))
    for i, c in enumerate(cols):
        d = np.zeros(y.size)
        d[s.keep[c]] = h
        Rp, Rm = (s.evaluate(y + k * bp * d, yd + k * gp * d, ydd + k * d, laws)[0]
                  for k in (1.0, -1.0))
        fd[:, i] = (Rp - Rm)[s.eq] / (2 * h)
    Sc = S[:, cols]
    assert np.all(np.abs(fd - Sc).max(axis=0) <= FD_TOL * np.abs(Sc).max(axis=0))
    rows = np.abs(Sc[s.n - 1:]).max(axis=1)  # the gauge's, the pulleys' and the arm's rows
    assert np.all(np.abs(fd - Sc)[s.n - 1:].max(axis=1) <= FD_TOL * rows)
    arm = int(np.flatnonzero(s.keep == s.n + 1 + int(s.kern.arms[0, COORD]))[0])
    row = np.abs(Sc[arm]).max()
    belt = [i for i, c in enumerate(cols) if c < s.n - 1]
    assert np.abs(Sc[arm, belt]).max() > 100 * FD_TOL * row
    assert np.abs(S[: s.n - 1, arm]).max() > 100 * FD_TOL * np.abs(S[:, arm]).max()


@pytest.mark.parametrize("example, extra, message", [
    ("thesis_table_3_1", ["belt.formulation=eulerian"], "belt.formulation = 'eulerian' is out "
     "of range; allowed: one of lagrangian, ale"),
    ("three_pulleys_3d", ["belt.formulation=ale"], "belt.formulation = 'ale' is out of range "
     "for belt.element = 'plate36'; allowed: one of lagrangian"),
    ("thread_benchmark", ["belt.formulation=ale"], "belt.formulation = 'ale' with "
     "friction.law = 'bristle'.*allowed: friction.law one of creep-rate, coulomb"),
])
def test_what_the_ale_march_cannot_carry_is_one_line(example, extra, message):
    with pytest.raises(InputError, match=message) as exc:
        load(str(REPO / "examples" / f"{example}.toml"), extra)
    assert "\n" not in str(exc.value)
    load(str(REPO / "examples" / f"{example}.toml"), [])  # without the key: fine


def test_a_tensioner_is_carried():
    """The serpentine's tensioner arm is no longer refused under the ALE march."""
    desc = load(SERPENTINE, ["belt.formulation=ale"])
    assert desc.belt["formulation"] == "ale"
