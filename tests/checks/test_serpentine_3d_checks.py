"""The serpentine drive as a plate belt (ancf/checks/serpentine_3d.py): the planar run gets
the plate file's data, runs that equal the steady reference pass and a wrong arm spring
fails (fast, from the steady reference alone), and the full runs (slow) meet the issue's
1 % on speeds and 0.2° on the arm."""
import math

import pytest

from ancf.belts.drive_file import load
from ancf.belts.drive_steady import steady_reference
from ancf.checks import serpentine_3d as s3


def _as_run(ref: dict) -> dict:
    """A run's JSON whose window means are the steady reference ``ref``'s."""
    return {"results": {
        "pulleys": [{"name": p["name"], "omega_mean": p["omega"]} for p in ref["pulleys"]],
        "arms": [{"name": p["name"], "angle_mean_rad": p["arm_angle_rad"]}
                 for p in ref["pulleys"] if p["arm_angle_rad"] is not None]}}


@pytest.fixture(scope="module")
def plate():
    desc = load(s3.PLATE)
    return desc, steady_reference(desc)


def test_planar_run_gets_the_plate_files_data(plate):
    """The planar file with :func:`planar_items` has the plate file's time laws and run
    times, and the same steady reference (layout, EA, rho A, L0, laws): speeds and arm
    angle to round-off (1e-9)."""
    desc, ref = plate
    planar = load(s3.PLANAR_FILE, s3.planar_items(desc))
    for a, b in zip(desc.pulleys, planar.pulleys):
        assert a.name == b.name and a.params.get("t0") == b.params.get("t0")
        assert a.params.get("t1") == b.params.get("t1")
    assert all(desc.run[k] == planar.run[k] for k in s3.RUN_KEYS)
    other = steady_reference(planar)
    for a, b in zip(ref["pulleys"], other["pulleys"]):
        assert a["omega"] == pytest.approx(b["omega"], rel=1e-9)
        if a["arm_angle_rad"] is not None:
            assert a["arm_angle_rad"] == pytest.approx(b["arm_angle_rad"], rel=1e-9)


def test_reference_passes_and_a_wrong_arm_spring_fails(plate):
    """Runs equal to the reference pass with zero differences; a plate whose arm spring is
    ten times stiffer (the reference of that data standing for its run) moves the arm by
    more than 0.2° and fails the arm row, its speeds still within 1 %."""
    desc, ref = plate
    run = _as_run(ref)
    got = s3.checks(s3.rows(run, run, ref))
    assert [c.name for c in got] == list(s3.NAMES)
    assert all(c.passed and c.difference == 0.0 for c in got)
    k = desc.pulleys[1].params["arm_stiffness"]
    stiff = steady_reference(load(s3.PLATE, (f"pulleys.tensioner.arm_stiffness={10 * k!r}",)))
    moved = abs(math.degrees(stiff["pulleys"][1]["arm_angle_rad"]
                             - ref["pulleys"][1]["arm_angle_rad"]))
    assert moved > s3.TOL["arm"]
    speeds, arm = s3.checks(s3.rows(_as_run(stiff), run, ref))
    assert speeds.passed and not arm.passed
    assert arm.difference == pytest.approx(moved, rel=1e-12)


@pytest.mark.slow
def test_plate_serpentine_within_the_issue_tolerances():
    """The full runs of examples/serpentine_3d.toml and of the planar file at its data:
    pulley speeds within 1 % and the arm within 0.2° of the steady reference's and the
    planar run's (seen: speeds 0.14 % from the reference, the alternator, and 0.04 % from
    the planar run; the arm 0.007° from both)."""
    got, cpu = s3.compare()
    checks = s3.checks(got)
    assert all(c.passed for c in checks), got
    assert cpu["plate"] > 0 and cpu["planar"] > 0
