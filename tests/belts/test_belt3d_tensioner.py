"""Tensioner arms on the 3D plate belt (issue 36 item 1, :mod:`ancf.belts.arm3d`).

The three-pulley plate belt (examples/three_pulleys_3d.toml) with its idler put on an arm
by the drive-file keys: the arm's couplings in the march's iteration matrix are exact
(central differences), and leaving one out is seen; a short run settles the arm where its
spring and preload balance the belt's moment about the pivot (from the run's own span
tensions); bad input is one line (exit 2)."""
import json

import numpy as np
import pytest

from ancf.belts.arm2d import BETA0, COORD, LENGTH, PIVOT_X, PIVOT_Y
from ancf.belts.arm3d import Drive3DArms
from ancf.belts.drive_file import load
from ancf.belts.drive_model import build
from ancf.belts.forces import evaluate_record
from ancf.cli import main
from ancf.common.paths import REPO
from ancf.scenes import SCENES
from analytic.belt_layout import wrap

THREE3D = REPO / "examples" / "three_pulleys_3d.toml"
#: the idler on an arm 60 mm long, pivot to its left (beta0 = 0): the belt presses it up
#: (counter-clockwise), the preload turns it clockwise into the lower span
ARM = ["pulleys.idler.law=tensioner", "pulleys.idler.pivot=[0.0185, -0.08]",
       "pulleys.idler.arm_inertia=1e-5", "pulleys.idler.arm_stiffness=5.0",
       "pulleys.idler.arm_preload=-2.0", "pulleys.idler.arm_damping=0.03"]
FD_TOL = 1e-6  # of each column's (row's) largest entry


def _drive(n_elements=12, extra=()):
    return build(load(THREE3D, ARM + [f"belt.n_elements={n_elements}",
                                      "contact.gauss_points=25", *extra]))


def _state(drive):
    """Near the laid belt, the arm turned 0.12 mm into it, every coordinate moving:
    (kernel, laws, x, v)."""
    n, rng = drive.n, np.random.default_rng(0)
    x = drive.state(drive.q0)
    x[:n] += 2e-4 * rng.normal(size=n)
    x[-1] = -0.002
    v = 0.3 * rng.normal(size=drive.n + drive.k)
    v[n:] = [60.0, 20.0, 5.0]  # idler, driven pulley (rad/s), arm (rad/s)
    return drive.kernel(), drive.laws(np.array([0.4]))[:, 0].copy(), x, v


def _residual(kd, laws, x, v, n, k):
    out = np.zeros(n + k)
    evaluate_record(x, v, laws, kd, False, 0.0, 0.0, out, np.zeros((1, 1)), np.zeros((k, n)),
                    np.zeros((k, n)), np.zeros((k, k)))
    return out


def _jacobian(drive, kd, laws, x, v, bp, gp):
    n, k = drive.n, drive.k
    mat, col, row, corner = (drive.pattern.zeros_matrix(), np.zeros((k, n)), np.zeros((k, n)),
                             np.zeros((k, k)))
    evaluate_record(x, v, laws, kd, True, bp, gp, np.zeros(n + k), mat, col, row, corner)
    D = np.zeros((n + k, n + k))
    D[:n, :n] = drive.pattern.as_csr(mat).toarray()
    D[:n, n:], D[n:, :n], D[n:, n:] = col.T, row, corner
    return D


def _differences(kd, laws, x, v, n, k, by):
    FD = np.zeros((n + k, n + k))
    for c in range(n + k):
        h = 1e-7 if c < n else 1e-6
        plus, minus = (x.copy(), v.copy()), (x.copy(), v.copy())
        plus[by == "v"][c] += h
        minus[by == "v"][c] -= h
        FD[:, c] = (_residual(kd, laws, *plus, n, k) - _residual(kd, laws, *minus, n, k)) / (2 * h)
    return FD


def _errors(D, FD, n):
    """The largest error of the free coordinates' columns (the arm's: the contact forces by
    the pulley centre) and rows (the arm's by the belt), each relative to its own largest
    entry (the belt's own columns are contact3d's, tests/belts/test_contact3d.py)."""
    def worst(err, top):  # a column of zeros (a spin by positions) absolutely
        return np.max(err / np.where(top > 0, top, 1.0))

    E = np.abs(FD - D)
    return max(worst(E[:, n:].max(axis=0), np.abs(D[:, n:]).max(axis=0)),
               worst(E[n:].max(axis=1), np.abs(D[n:]).max(axis=1)))


@pytest.fixture(scope="module")
def jacobians():
    drive = _drive()
    kd, laws, x, v = _state(drive)
    n, k = drive.n, drive.k
    return drive, {by: (_jacobian(drive, kd, laws, x, v, *((1.0, 0.0) if by == "x" else (0.0, 1.0))),
                        _differences(kd, laws, x, v, n, k, by)) for by in ("x", "v")}


@pytest.mark.parametrize("by", ["x", "v"])
def test_arm_couplings_match_central_differences(jacobians, by):
    """The columns and rows of the free pulleys and of the arm in the iteration matrix by
    coordinates (bp, gp = 1, 0) and by velocities (0, 1) against central differences
    (h = 1e-7 m, 1e-6 rad): within 1e-6 of each column's (row's) largest entry.  The arm's
    column (dQ/dpsi through the moving centre) and its row by the belt are not zero."""
    drive, J = jacobians
    D, FD = J[by]
    n, ja = drive.n, drive.n + drive.k - 1
    assert isinstance(drive.kernel(), Drive3DArms)
    assert np.abs(D[:n, ja]).max() > 0 and np.abs(D[ja, :n]).max() > 0
    assert _errors(D, FD, n) <= FD_TOL


@pytest.mark.parametrize("left_out", ["column", "row", "corner"])
def test_leaving_a_coupling_out_fails(jacobians, left_out):
    """Without the contact forces' derivative by the pulley centre (the arm's column),
    the arm's row by the belt, or the tensioner pulley's moment by psi, the check above
    fails by far (its error is above 1e3 times its tolerance)."""
    drive, J = jacobians
    n, j, ja = drive.n, drive.n + int(drive.rig.free[1]), drive.n + drive.k - 1
    D, FD = (a.copy() for a in J["x"])
    cut = {"column": (slice(0, n), ja), "row": (ja, slice(0, n)), "corner": (j, ja)}[left_out]
    D[cut] = 0.0
    assert _errors(D, FD, n) > 1e3 * FD_TOL


def _span_moment(desc, arm, psi, tensions):
    """The belt's moment (N m, counter-clockwise) about the pivot on the arm's pulley at arm
    angle psi from the two spans' tensions (N; in, out): T_out d_out - T_in d_in at the
    pulley's centre, the span directions d of the wrapped path at that centre."""
    i = int(arm[0])
    pivot = arm[[PIVOT_X, PIVOT_Y]]
    b = arm[BETA0] + psi
    lever = arm[LENGTH] * np.array([np.cos(b), np.sin(b)])
    centres = [p.centre for p in desc.pulleys]
    centres[i] = tuple(pivot + lever)
    lay = wrap(centres, [p.radius for p in desc.pulleys], [p.side for p in desc.pulleys],
               [p.name for p in desc.pulleys], 1)
    force = tensions[1] * lay.d[i] - tensions[0] * lay.d[i - 1]
    return float(lever[0] * force[1] - lever[1] * force[0])


@pytest.fixture(scope="module")
def settled():
    """0.2 s of the drive (24 plates, 25 points each, dt = 2e-4 s), driver ramped to
    20 rad/s and the load to 0.05 N m within 10 ms, means over the last 50 ms."""
    sets = ARM + ["belt.n_elements=24", "contact.gauss_points=25", "pulleys.driver.t0=0",
                  "pulleys.driver.t1=0.01", "pulleys.driven.t0=0", "pulleys.driven.t1=0.01",
                  "pulleys.driver.omega_final=20", "pulleys.driven.load_torque=0.05"]
    out, res = SCENES["belt-drive"].execute({"file": str(THREE3D), "run.t_end": "0.2",
                                             "run.dt": "2e-4", "run.steady_window": "0.05",
                                             "set": "; ".join(sets)})
    return json.loads(json.dumps(out)), res.extra["description"], res.extra["drive"]


def test_arm_settles_where_the_span_tensions_balance_it(settled):
    """The arm's mean angle psi and the one its moment balance gives from the run's own
    span tensions, k psi = preload + M(psi), agree within 0.5 degree; a preload 0.1 N m
    off moves that balance by more (the check can fail)."""
    out, desc, drive = settled
    assert out["converged"]
    arm = drive.rig.arms[0]
    p = desc.pulleys[int(arm[0])].params
    psi = out["results"]["arms"][0]["angle_mean_rad"] - arm[BETA0]
    spans = out["results"]["spans"]
    tensions = [s["tension_mean_N"] for s in spans if s["to"] == "idler"] + \
        [s["tension_mean_N"] for s in spans if s["from"] == "idler"]
    moment = _span_moment(desc, arm, psi, tensions)
    balance = (p["arm_preload"] + moment) / p["arm_stiffness"]
    assert abs(balance - psi) < np.radians(0.5), (psi, balance)
    assert abs(balance - 0.1 / p["arm_stiffness"] - psi) > np.radians(0.5)


def _with(item):
    """ARM with the idler's key of ``item`` ("key=value") set to its value."""
    key = "pulleys.idler." + item.split("=")[0] + "="
    return [s for s in ARM if not s.startswith(key)] + ["pulleys.idler." + item]


@pytest.mark.parametrize("sets,message", [
    (ARM[:1], "pulleys.1.pivot: missing (law 'tensioner'"),
    (_with("pivot=[0.0785, -0.08]"), "pulleys.1.pivot = [0.0785, -0.08] is the pulley's "
     "centre; allowed: a point other than the centre"),
    (_with("arm_stiffness=0"), "pulleys.1.arm_stiffness = 0.0 is out of range"),
])
def test_bad_tensioner_input_is_one_line(sets, message, capsys):
    argv = ["run", "belt-drive", "--json", "--file", str(THREE3D)]
    for s in sets:
        argv += ["--set", s]
    assert main(argv) == 2
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1 and err.startswith("error: ") and message in err, err


def test_pulley_on_the_arm_is_sampled_where_it_is(settled):
    """The results sample the contact with the tensioner's pulley on its arm, not at its
    file centre: the idler's mean moment is its bearing's (seen 0.0017 N m where the file
    centre gave -0.78 N m) and its penetration the penalty's (a file centre gave 7.4 mm)."""
    out, desc, drive = settled
    row = next(p for p in out["results"]["pulleys"] if p["name"] == "idler")
    assert abs(row["torque_mean_Nm"]) < 0.02, row["torque_mean_Nm"]
    assert row["penetration_max_m"] < 1e-3, row["penetration_max_m"]
