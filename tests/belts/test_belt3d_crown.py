"""Crowned pulleys of the plate belt (issue 36 item 4; ancf.belts.contact3d_state, crowned
rims): the drive-file keys ``crown_m`` and ``face_offset_m`` with their bad input, the
crowned kernel's exact derivatives against central differences, and ``crown_m = 0`` bit for
bit the drive without the key."""
import json

import numpy as np
import pytest

from ancf.belts import friction
from ancf.belts.contact3d import contact_points3d
from ancf.belts.contact3d_state import contact_forces3d_crown
from ancf.cli import main
from ancf.common.paths import REPO
from ancf.scenes import SCENES

THREE3D = REPO / "examples" / "three_pulleys_3d.toml"
THREE2D, SERPENTINE3D = REPO / "examples" / "three_pulleys.toml", REPO / "examples" / \
    "serpentine_3d.toml"


def _one_error_line(args, capsys) -> str:
    """The CLI's stderr for ``args``: exactly one ``error:`` line and exit 2."""
    assert main(args) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and err[0].startswith("error: "), err
    return err[0]


@pytest.mark.parametrize("path, item, words", [
    (THREE2D, "pulleys.0.crown_m=0.001", "pulleys.0.crown_m = 0.001 is out of range for "
     "belt.element = 'dufva2d'; allowed: 0.0"),
    (THREE3D, "pulleys.driven.crown_m=-0.001", "pulleys.2.crown_m = -0.001 is out of range; "
     "allowed: a number in [0, 1]"),
    (THREE3D, "pulleys.driven.crown_m=0.05", "pulleys.2.crown_m = 0.05 is out of range: not "
     "below the pulley's radius 0.05 m; allowed: a number in [0, 0.05) m"),
    (THREE3D, "pulleys.driven.crown_m=0.2", "pulleys.2.crown_m = 0.2 is out of range: not "
     "below the pulley's radius 0.05 m; allowed: a number in [0, 0.05) m"),
    (SERPENTINE3D, "pulleys.tensioner.crown_m=0.001", "pulleys.1.crown_m = 0.001 is out of "
     "range for law = 'tensioner'; allowed: 0"),
    (THREE3D, "pulleys.driven.crown_m=0.002", "pulleys.2.crown_m = 0.002 is out of range: its "
     "slope at the face's ends 4 c / W = 0.182 is above 0.1 (W = 0.044 m the face width); "
     "allowed: a number in [0, 0.0011] m"),
    (THREE3D, "pulleys.driven.face_offset_m=0.5", "pulleys.2.face_offset_m = 0.5 is out of "
     "range: the belt's mid-line would be off the face (face width 0.044 m, belt.b = 0.04 m); "
     "allowed: a number in [-0.022, 0.022] m"),
    (THREE3D, "pulleys.driven.flanges=true; pulleys.driven.face_offset_m=-0.003",
     "pulleys.2.face_offset_m = -0.003 is out of range: a flange would be inside the belt "
     "(face width 0.044 m, belt.b = 0.04 m); allowed: a number in [-0.002, 0.002] m"),
])
def test_bad_crowns_are_one_error_line(path, item, words, capsys):
    """A crown on the 2D belt, negative, not below the radius, steeper at the face's ends
    than tracking3d.MAX_CROWN_SLOPE, or on a tensioner; a face offset that takes the belt's
    mid-line off the face or puts a flange inside the belt: one ``error:`` line naming the
    key and its allowed range, exit 2."""
    sets = [a for s in item.split("; ") for a in ("--set", s)]
    line = _one_error_line(["run", "belt-drive", "--file", str(path), *sets], capsys)
    assert words in line, line


def test_crown_with_a_friction_state_is_one_line(tmp_path, capsys):
    """A crowned pulley with the bristle law (a state per contact point, which the crowned
    kernel does not carry): one ``error:`` line naming friction.law and the laws allowed."""
    import re
    text = re.sub(r"\[friction\][^\[]*", "[friction]\nlaw = 'bristle'\nmu = 0.6\n"
                  "stiffness = 1e8\ndamping = 1e3\n\n", THREE3D.read_text())
    path = tmp_path / "bristle.toml"
    path.write_text(text)
    line = _one_error_line(["run", "belt-drive", "--file", str(path), "--set",
                            "pulleys.driven.crown_m=0.001"], capsys)
    assert line.startswith("error: friction.law = 'bristle' is out of range with a crowned "
                           "pulley") and "allowed: one of " + ", ".join(friction.LAWS) in line


# ------------------------------------------------------------ the crowned kernel's derivatives
C, HALF = 1e-3, 0.03  # crown (m) and half face (m) of the checks: R' up to 2 C / HALF = 0.07
FD_CASES = {  # strip radius above R0 (m), creep coefficient nu_s (kg/(m^2 s)), pulley speed
    "linear": dict(gap=0.5e-3, nu=1e2, omega=5.0),
    "saturated": dict(gap=0.5e-3, nu=1e8, omega=2.0),
}


def _crown_case(case: dict) -> tuple:
    """4 plates wrapped over 1.6 rad at R0 + gap on a crowned pulley (axis AXIS; the strip
    along it from 0.01 to 0.06 m, the mid-face at 0.03 m, so the crown's slope changes sign
    on it and its edge lies past the face's end, on the continued parabola), perturbed at
    random; pulley 1 far away.  Returns (E, V, S0, w, pulleys, omegas, prm, crowns)."""
    from tests.belts.test_contact3d import AXIS, R0, _frame, _pulleys, _wrap
    rng = np.random.default_rng(3)
    p = _frame(AXIS)[2]
    pul = _pulleys([[0.02, -0.01, 0.03], [0.6, 0.3, -0.2]], [AXIS, [1.0, 0.0, 0.0]], [R0, 0.05],
                   odot=[[0.3, -0.2, 0.1], [0.0, 0.5, 0.0]])
    E, V, S0, w, _ = _wrap(4, R0 + case["gap"], pul["centres"][0] + 0.01 * p, AXIS, arc=1.6,
                           theta0=-0.3, width=0.05, omega_b=5.0, axial=0.2, drift=pul["odot"][0])
    E = E + 1e-4 * rng.standard_normal(E.shape)
    V = V + 0.05 * rng.standard_normal(V.shape)
    zm = pul["centres"][0, 2] + 0.03 / p[2]  # s = (r - o) . p - (z_m - o_z) p_z
    crowns = np.array([[C, zm, HALF], [0.0, 0.0, HALF]])
    prm = friction.contact_record(1e7, 2000.0, "creep-rate", 0.3, case["nu"])
    return E, V, S0, w, pul, np.array([case["omega"], 3.0]), prm, crowns


def _crown_forces(E, V, S0, w, pul, omegas, prm, crowns, want_J=True) -> dict:
    from tests.belts.test_contact3d import _outputs
    out = _outputs(E.shape[0], pul["radii"].size)
    contact_forces3d_crown(E, V, S0, w, pul["centres"], pul["axes"], pul["radii"], omegas,
                           pul["odot"], prm, crowns, want_J, *out.values())
    return out


def _labels(E, V, S0, pul, omegas, prm, crowns) -> np.ndarray:
    from ancf.belts.contact3d_state import contact_state3d_crown
    return contact_state3d_crown(E, V, S0, pul["centres"], pul["axes"], pul["radii"], omegas,
                                 pul["odot"], prm, crowns)[5]


@pytest.mark.parametrize("name", list(FD_CASES))
def test_crowned_jacobians_match_central_differences(name):
    """Every derivative of contact_forces3d_crown (dQ/de, dQ/dedot, dQ/domega, dT/de,
    dT/dedot, dT/domega) against central differences with test_contact3d's step and
    column tolerance (RTOL of the column's norm plus round-off); no stencil point changes
    any point's branch; some points in contact, some out, on the stated friction branch."""
    from tests.belts.test_contact3d import H, R0, _check
    E, V, S0, w, pul, omegas, prm, crowns = _crown_case(FD_CASES[name])
    base = _crown_forces(E, V, S0, w, pul, omegas, prm, crowns)
    labels = _labels(E, V, S0, pul, omegas, prm, crowns)
    nel, npul = E.shape[0], 2
    fd = {k: np.zeros_like(v) for k, v in base.items()}

    def diff(Ep, Vp, om):
        res = []
        for sgn in (1.0, -1.0):
            args = [x.copy() for x in (Ep(sgn * H), Vp(sgn * H), om(sgn * H))]
            assert np.array_equal(_labels(args[0], args[1], S0, pul, args[2], prm, crowns),
                                  labels), "a kink within one step"
            o = _crown_forces(args[0], args[1], S0, w, pul, args[2], prm, crowns, False)
            res.append((o["Q"], o["T"]))
        return (res[0][0] - res[1][0]) / (2 * H), (res[0][1] - res[1][1]) / (2 * H)

    def bump(X, e, k, c):
        def at(h):
            Xp = X.copy()
            Xp[e, k, c] += h
            return Xp
        return at

    same = (lambda X: (lambda h: X))
    for e in range(nel):
        for j in range(36):
            k, c = divmod(j, 3)
            dQ, dT = diff(bump(E, e, k, c), same(V), same(omegas))
            fd["Kq"][e, :, j], fd["dTq"][:, e, j] = dQ[e], dT
            dQ, dT = diff(same(E), bump(V, e, k, c), same(omegas))
            fd["Cv"][e, :, j], fd["dTv"][:, e, j] = dQ[e], dT
    for p in range(npul):
        dQ, dT = diff(same(E), same(V), lambda h, p=p: omegas + h * (np.arange(npul) == p))
        fd["Qw"][:, p, :], fd["dTw"][p] = dQ, dT[p]
    sQ = np.abs(base["Q"]).max()
    sT = max(np.abs(base["T"]).max(), R0 * sQ)
    for key in ("Kq", "Cv", "Qw"):
        _check(fd[key], base[key], sQ, key)
    for key in ("dTq", "dTv"):
        _check(fd[key], base[key], sT, key)
    _check(fd["dTw"][:, None], base["dTw"][:, None], sT, "dTw")
    on = labels[:, :, 0]
    assert np.any(on == 0) and np.any(on >= 2), on
    assert not labels[:, :, 1].any()
    assert np.all(on[on >= 2] == (2 if name == "linear" else 3)), on


# ------------------------------------------------------------------ crown_m = 0 is no crown
def _coarse(sets: list, t_end: float = 0.05) -> tuple:
    """(results, the scene's result) of examples/three_pulleys_3d.toml coarsened (20
    plates, 5 x 5 contact points, the driver ramped to 20 rad/s in 20 ms, laid on its
    path) to ``t_end`` s, with the extra ``sets``."""
    base = ["pulleys.driver.t0=0", "pulleys.driver.t1=0.02", "pulleys.driven.t0=0",
            "pulleys.driven.t1=0.02", "pulleys.driver.omega_final=20",
            "pulleys.driven.load_torque=0.05", "belt.n_elements=20",
            "contact.gauss_points=25", "run.start=laid"]
    out, res = SCENES["belt-drive"].execute({
        "file": str(THREE3D), "run.t_end": str(t_end), "run.steady_window": "0.005",
        "run.output_dt": "0.0025", "set": "; ".join(base + sets)})
    assert out["converged"], out["message"]
    return json.loads(json.dumps(out))["results"], res


def test_crown_zero_is_the_drive_without_the_key():
    """``crown_m = 0`` (and ``face_offset_m = 0``) runs bit for bit the drive that does not
    name the keys, on a 1 deg tilted driven pulley (contact3d's kernel, the Drive3DArms
    record without arms: the crowned kernel is not called)."""
    (a, ra), (b, rb) = (_coarse(["pulleys.driven.axis_tilt_deg=1"] + extra) for extra in (
        ["pulleys.driven.crown_m=0", "pulleys.driven.face_offset_m=0"], []))
    assert type(ra.extra["drive"].kernel()).__name__ == "Drive3DArms"
    assert a["times"] == b["times"] and a["pulleys"] == b["pulleys"]
    assert np.array_equal(ra.extra["result"].q, rb.extra["result"].q)
    assert np.array_equal(ra.extra["result"].v, rb.extra["result"].v)


# ------------------------------------------------------------------ centring (ancf.checks.crown3d)
def test_crowned_example_runs_from_the_cli(capsys):
    """``ancf run belt-drive --file examples/crowned.toml`` (cut to 0.05 s) converges; the
    driven pulley's lateral position, measured from its displaced face's mid-plane, is the
    belt's start off the crown's top, -face_offset_m, within 5 % (the contact points' mean)."""
    from ancf.belts.drive_file import load
    path = REPO / "examples" / "crowned.toml"
    assert main(["run", "belt-drive", "--json", "--file", str(path), "--set", "run.t_end=0.05",
                 "--set", "run.steady_window=0.01"]) == 0
    out = json.loads(capsys.readouterr().out)
    y0 = load(path).pulleys[2].params["face_offset_m"]
    lateral = out["results"]["pulleys"][2]["lateral_position_m"]
    assert out["converged"] and y0 > 0
    assert lateral[-1] == pytest.approx(-y0, rel=0.05), lateral


@pytest.fixture(scope="module")
def centring() -> list:
    from ancf.checks import crown3d
    return crown3d.rows()


@pytest.mark.slow
@pytest.mark.xfail(strict=True, reason="documented miss (ancf/checks/crown3d.py): the soft "
                   "benchmark belt stretches to follow the crown instead of steering")
def test_benchmark_belt_comes_back_in_the_rules_time(centring):
    """The acceptance: the belt 3 mm off a 0.5 mm crown is back within 10 % of its offset
    within 10 % of the classic rule's time t* (crown3d Eq. 2).  It is not (strict xfail):
    the row stays a failed check until the model or the rule changes."""
    from ancf.checks import crown3d
    assert crown3d.checks(centring)[0].passed, centring[0]


@pytest.mark.slow
def test_the_miss_is_the_belts_stretch(centring):
    """The evidence for the miss.  The rule's t* falls within the runs (before 60 % of
    T_END).  The benchmark belt, whose 19 % strain is over 20 times the 0.5 % edge strain
    difference the crown asks for, moves its entry less than 1 % of y0; the stiff belt,
    whose 0.19 % strain is below that difference (its low edge would go slack), moves
    toward the crown's top by over 4 % of y0 and over 5 times the benchmark belt's move;
    neither is back within 10 % by T_END (the rule: by t*)."""
    from ancf.checks import crown3d
    soft, stiff = centring
    y0 = -soft["entry_start_m"]
    assert soft["predicted_s"] < 0.6 * crown3d.T_END
    assert soft["belt_strain"] > 20 * soft["edge_strain_difference"]
    assert stiff["belt_strain"] < stiff["edge_strain_difference"]
    moved = [r["entry_end_m"] - r["entry_start_m"] for r in (soft, stiff)]
    assert abs(moved[0]) < 0.01 * y0, moved
    assert moved[1] > 0.04 * y0 and moved[1] > 5 * abs(moved[0]), moved
    assert all(np.isnan(r["simulated_s"]) for r in centring)


@pytest.mark.slow
def test_a_centred_belt_stays_on_the_crowns_top():
    """The example with face_offset_m = 0 (the belt centred on the crown; 0.2 s): by
    symmetry every pulley's lateral position and the crowned pulley's axial force stay
    at round-off, below 1e-3 of the example's offset (m) and of its load torque over its
    radius (N)."""
    from ancf.checks import crown3d
    out, res = crown3d.run(("pulleys.driven.face_offset_m=0",), 0.2)
    desc = crown3d.run(())[1].extra["description"]
    y0, q = desc.pulleys[2].params["face_offset_m"], desc.pulleys[2]
    lateral = np.array([p["lateral_position_m"] for p in out["results"]["pulleys"]], float)
    axial = np.array(out["results"]["pulleys"][2]["axial_force_N"])
    assert np.nanmax(np.abs(lateral)) < 1e-3 * y0
    assert np.max(np.abs(axial)) < 1e-3 * q.params["load_torque"] / q.radius


# ------------------------------------------------------------------ post-processing on the crown
@pytest.mark.slow
def test_reported_moments_and_depths_are_the_crowned_rims():
    """The results a crowned drive reports at t_end (the pulleys' moments, the largest
    penetration, ancf.belts.post3d) are the crowned rims' (contact_forces3d_crown,
    contact_state3d_crown at the same state), not the cylinders': on 1 mm crowns the
    cylinders' penetration of the crowned pulleys is below the crowned one by over a third
    of the crown, and their moments differ from the crowned ones by over 1 %."""
    from ancf.belts import post3d
    from ancf.belts.contact3d import contact_state3d
    from ancf.belts.contact3d_state import contact_state3d_crown
    c = 0.001
    out, res = _coarse([f"pulleys.driver.crown_m={c}", f"pulleys.driven.crown_m={c}"])
    drive, run = res.extra["drive"], res.extra["result"]
    x, v, t = run.q[-1], run.v[-1], float(run.t[-1])
    E, V, o, om, odot = post3d._contact_args(drive, x, v, t)
    args = (E, V, drive.S0, o, drive.axes, drive.radii, om, odot, drive.prm)
    crowned = contact_state3d_crown(*args, drive.flanges.crowns)[1].max(axis=(0, 1))
    cylinder = contact_state3d(*args)[1].max(axis=(0, 1))
    assert out["penetration_max_m"] == pytest.approx(crowned.max(), rel=1e-12)
    assert np.all(cylinder[[0, 2]] < crowned[[0, 2]] - c / 3), (cylinder, crowned)
    T = np.array([p["torque_Nm"][-1] for p in out["pulleys"]])
    assert np.allclose(T, post3d.pulley_moments(drive, x, v, t), rtol=1e-12, atol=0)
    drive.flanges = drive.flanges._replace(crowns=np.zeros((0, 3)))
    T_cyl = post3d.pulley_moments(drive, x, v, t)
    assert np.max(np.abs(T_cyl / T - 1)[[0, 2]]) > 0.01, (T, T_cyl)
