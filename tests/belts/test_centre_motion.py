"""Moving pulley centres as a drive-file law (issue 36 item 3): any pulley's
``centre_shift`` [dx, dy] (m) reached at ``centre_shift_time`` (s) by the
``centre_motion`` law (``ramp``: Eq. 4.46, u = u0 t / t0 up to t0), on the planar belt and
on the plate belt (a tensioner's pivot carried alike).

Model 1 of Table 4.1 from a drive file (examples/thesis_table_4_1_model_1.toml) is
``ancf run belt3d --set model=1`` key for key and bit for bit; the key moves the centre
in the contact (2D and 3D answers change), its absence is no motion (bit for bit the run
with a zero shift); the centre's velocity is the rate of its position; bad input is one
line naming the key."""
from __future__ import annotations

import json

import numpy as np
import pytest

from ancf.belts import drive_data as dd
from ancf.belts.drive3d import laid_plate_belt
from ancf.belts.drive_file import describe, load, override, read
from ancf.belts.drive_model import build
from ancf.belts.forces import moved_centres
from ancf.cli import main
from ancf.common.params import InputError
from ancf.common.paths import REPO
from ancf.scenes import SCENES
from ancf.scenes import belt3d as b3
from tests.belts.plate_runs import assert_file_run_is_belt3d

EXAMPLES = REPO / "examples"
MODEL1 = EXAMPLES / "thesis_table_4_1_model_1.toml"
THREE, SERPENTINE = EXAMPLES / "three_pulleys.toml", EXAMPLES / "serpentine.toml"
SHORT = "0.02"  # s: 200 steps of 1e-4 s
IDLER_SHIFT = ["pulleys.idler.centre_shift=[0.0, -0.004]",
               "pulleys.idler.centre_shift_time=0.01"]
ARM_SHIFT = ["pulleys.tensioner.centre_shift=[0.003, 0.002]",
             "pulleys.tensioner.centre_shift_time=0.02"]


def _run(path, sets, t_end=SHORT):
    """belt-drive's JSON output and march result for the file with overrides ``sets``."""
    out, res = SCENES["belt-drive"].execute({"file": str(path), "run.t_end": t_end,
                                             "run.steady_window": t_end,
                                             "set": "; ".join(sets)})
    assert out["converged"], out.get("message")
    return json.loads(json.dumps(out))["results"], res.extra["result"]


# ------------------------------------------------------------------ the law, fast

@pytest.mark.parametrize("path, sets, pulley", [(THREE, IDLER_SHIFT, 1),
                                                (SERPENTINE, ARM_SHIFT, 1),
                                                (MODEL1, [], 0)])
def test_centre_velocity_is_the_rate_of_its_position(path, sets, pulley):
    """At times within and after the ramp: the centre's velocity is the central difference
    of its position (a sign error in the rate fails), the compiled centres equal the
    model's, and after the ramp the centre sits at centre + centre_shift (a tensioner's:
    on its arm at rest, its pivot carried by the shift)."""
    desc = load(path, sets)
    drive, p = build(desc), desc.pulleys[pulley]
    shift, t0 = np.array(p.params["centre_shift"]), p.params["centre_shift_time"]
    x = drive.state(drive.q0)
    v = np.zeros_like(x)
    h = 1e-6
    for t in (0.3 * t0, 0.7 * t0, 2.0 * t0):
        o, odot = drive.moved(x, v, t)
        fd = (drive.moved(x, v, t + h)[0] - drive.moved(x, v, t - h)[0]) / (2 * h)
        assert odot[pulley] == pytest.approx(fd[pulley], rel=1e-6, abs=1e-12)
        assert np.dot(odot[pulley, :2], shift) == pytest.approx(
            np.dot(shift, shift) / t0 if t < t0 else 0.0, rel=1e-12, abs=1e-15)
        got = moved_centres(drive.kernel(), drive.laws(np.array([t]))[:, 0])
        c, cdot = drive.centre_motion(t)
        assert np.array_equal(got[0], c) and np.array_equal(got[1], cdot)
    rest = drive.moved(x, v, 2.0 * t0)[0][pulley, :2]
    assert rest == pytest.approx(np.array(p.centre) + shift, abs=1e-15)


def test_a_missing_key_is_no_motion():
    """Without the keys every pulley stays: defaults [0, 0], Eq. 4.46's 0.05 s, ``ramp``;
    no motion in the rig, only the pulley rows in the march's laws."""
    for path in (THREE, SERPENTINE, EXAMPLES / "three_pulleys_3d.toml"):
        desc = load(path)
        for p in desc.pulleys:
            assert (p.params["centre_shift"], p.params["centre_shift_time"],
                    p.params["centre_motion"]) == ((0.0, 0.0), 0.05, "ramp")
        drive = build(desc)
        assert drive.rig.motions == ()
        assert drive.laws(np.array([0.0, 0.1])).shape == (len(desc.pulleys), 2)
        assert drive.kernel().moving.size == 0


def test_model_1_file_is_belt3d_model_1_key_for_key():
    """Every parameter of ``ancf run belt3d --set model=1`` that defines the drive is in
    the file, the driver's shift is u0 along -x reached at t0, and the belt laid on the
    file's path is belt3d's, bit for bit."""
    d, p = load(MODEL1), SCENES["belt3d"].resolve({"model": 1})
    driver, driven = d.pulleys
    b = d.belt
    got = dict(n_elements=b["n_elements"], E=b["E"], nu=b["nu"], rho=b["rho"], h=b["h"],
               width=b["b"], bending=b["bending"], R=driver.radius,
               k_p=d.contact["k_p"], c_p=d.contact["c_p"],
               contact_points=d.contact["gauss_points"], mu=d.friction["mu"],
               nu_s=d.friction["nu_s"], inertia=driven.params["inertia"],
               omega_final=driver.params["omega_final"], t1=driver.params["t1"],
               Ta_max=driven.params["load_torque"], start=d.run["start"],
               u0=-driver.params["centre_shift"][0],
               centre_distance=driven.centre[0],
               **{k: d.run[k] for k in ("dt", "rho_inf", "newton_tol", "t_end", "output_dt",
                                        "steady_window", "max_steps")})
    assert set(got) == set(p) - {"model", "strain_measure", "integrator", "T_i",
                                 "belt_length"}
    assert got == {k: p[k] for k in got}
    assert b["length"] == b3.belt_length(p) and p["T_i"] == 0 and p["belt_length"] is None
    assert driver.params["centre_shift"][1] == 0 and driven.radius == p["R"]
    assert (driver.params["centre_shift_time"], driver.params["t0"]) == (b3.T0, b3.T0)
    assert (driven.params["t0"], driven.params["t1"]) == (b3.T0, b3.TA_T1)
    assert driven.params["damping"] == 0 and d.gravity == (0.0, 0.0)
    spec = b3.spec(p)
    assert b["elastic_points"] == spec.ng and d.friction["law"] == b3.LAW
    assert laid_plate_belt(d.path, b["length"], 16, b["b"]).tobytes() == \
        laid_plate_belt(spec.path, spec.belt_length, 16, spec.width).tobytes()


# ------------------------------------------------------------------ bad input

BAD = [  # (file, overrides, the one line it gives)
    (THREE, ["pulleys.idler.centre_shift_time=-0.1"],
     r"^pulleys.1.centre_shift_time = -0.1 is out of range; allowed: a number in \(0, 100\]"),
    (THREE, ["pulleys.idler.centre_shift_time=0"],
     r"^pulleys.1.centre_shift_time = 0.0 is out of range; allowed: a number in \(0, 100\]"),
    (THREE, ["pulleys.idler.centre_shift=[nan, 0.0]"],
     r"^pulleys.1.centre_shift = \[nan, 0.0\] is out of range; allowed: \[x, y\], two numbers "
     r"in \[-1000, 1000\] m"),
    (THREE, ["pulleys.idler.centre_shift=[0.0, inf]"],
     r"^pulleys.1.centre_shift = \[0.0, inf\] is out of range; allowed: \[x, y\]"),
    (THREE, ["pulleys.idler.centre_shift=[0.01]"],
     r"^pulleys.1.centre_shift = \[0.01\] is out of range; allowed: \[x, y\]"),
    (THREE, ["pulleys.idler.centre_motion=jump"],
     r"^pulleys.1.centre_motion = 'jump' is out of range; allowed: one of ramp"),
    # the driver moved onto the driven pulley: the pulleys overlap
    (THREE, ["pulleys.driver.centre_shift=[0.3, 0.0]"],
     r"^pulleys.0.centre_shift = \[0.3, 0.0\]: the shifted layout cannot be wrapped \(pulleys "
     r"'driver' and 'driven' overlap: .*\); allowed: shifts that keep the pulleys apart"),
    # the idler pulled up through the line of the other centres: the belt no longer wraps it
    (THREE, ["pulleys.idler.centre_shift=[0.0, 0.3]"],
     r"^pulleys.1.centre_shift = \[0.0, 0.3\]: the shifted layout cannot be wrapped \(.*\); "
     r"allowed: shifts that keep the pulleys apart and the belt wrapping each"),
    # the driver moved 2 m away: a path more than twice the belt
    (MODEL1, ["pulleys.driver.centre_shift=[-2.0, 0.0]"],
     r"^pulleys.0.centre_shift = \[-2.0, 0.0\]: the shifted path \(5.\d+ m\) is more than "
     r"twice the belt \(1.25664 m\); allowed: shifts that keep the path within 2.51327 m"),
]


@pytest.mark.parametrize("path, sets, message", BAD,
                         ids=[f"{i}-{s[0].split('=')[0]}" for i, (_, s, _) in enumerate(BAD)])
def test_bad_centre_motion_is_one_line_naming_the_key(path, sets, message):
    with pytest.raises(InputError, match=message) as exc:
        describe(override(read(path), sets))
    assert "\n" not in str(exc.value) and "allowed:" in str(exc.value)


def test_bad_centre_motion_on_the_command_line_is_one_error_line(capsys):
    """``ancf run belt-drive`` prints the refusal as one ``error:`` line and exits 2."""
    code = main(["run", "belt-drive", "--file", str(THREE), "--set",
                 "pulleys.idler.centre_shift_time=-1"])
    err = capsys.readouterr().err.strip().splitlines()
    assert code == 2 and len(err) == 1
    assert err[0].startswith("error: pulleys.1.centre_shift_time = -1")


# ------------------------------------------------------------------ runs (slow)

@pytest.mark.slow
def test_model_1_file_runs_belt3d_model_1_exactly():
    """The same march on the same model: every sample's coordinates and velocities, the
    pulley speeds, the span tensions (the membrane's, along the edge z = 0), the driven
    pulley's friction moment and the run statistics equal ``belt3d --set model=1``'s at a
    short t_end (the driver moving, Eq. 4.46)."""
    a, xa = _run(MODEL1, [])
    out, rb = SCENES["belt3d"].execute({"model": 1, "t_end": SHORT})
    xb, b = rb.extra["result"], json.loads(json.dumps(out))["results"]
    assert out["converged"]
    assert_file_run_is_belt3d(xa, a, xb, b)


@pytest.mark.slow
@pytest.mark.parametrize("path, sets", [
    (THREE, IDLER_SHIFT), (SERPENTINE, ARM_SHIFT),
    (MODEL1, ["pulleys.driver.centre_shift=[0.0, 0.0]"])])
def test_the_shift_changes_the_answer(path, sets):
    """A shifted centre changes the belt's motion and its span tensions by more than 0.1 %
    (2D: an idler pressed 4 mm into the slack span, a tensioner's pivot moved 3.6 mm; 3D:
    Model 1 without its driver's shift)."""
    base, xb = _run(path, [])
    moved, xm = _run(path, sets)
    assert not np.array_equal(xm.q, xb.q)
    T0 = np.array([s["tension_N"] for s in base["spans"]])
    T1 = np.array([s["tension_N"] for s in moved["spans"]])
    assert np.max(np.abs(T1 - T0)) > 1e-3 * np.max(np.abs(T0))


@pytest.mark.slow
@pytest.mark.parametrize("path, t_end", [(THREE, SHORT), (SERPENTINE, SHORT),
                                         (EXAMPLES / "three_pulleys_3d.toml", "0.005")])
def test_no_key_is_a_zero_shift_bit_for_bit(path, t_end):
    """Without the keys the run is the run with every centre_shift = [0, 0] given, bit for
    bit: every sample's coordinates and velocities and every result (the CPU times
    aside)."""
    names = [p.name for p in load(path).pulleys]
    a, xa = _run(path, [], t_end)
    b, xb = _run(path, [f"pulleys.{n}.centre_shift=[0.0, 0.0]" for n in names], t_end)
    assert np.array_equal(xa.q, xb.q) and np.array_equal(xa.v, xb.v)
    cpu = {k for k in a if k.endswith("_cpu_s")}
    assert cpu and {k: a[k] for k in a if k not in cpu} == {k: b[k] for k in b if k not in cpu}
