"""The serpentine's acceptance checks (ancf/checks/belt_drives.py) on the steady reference
itself (all pass, differences 0) and on perturbed copies (each fails)."""
import pytest

from ancf.belts.drive_file import load
from ancf.belts.drive_steady import steady_reference
from ancf.checks import belt_drives as bd
from ancf.common.paths import REPO

SERPENTINE = REPO / "examples" / "serpentine.toml"


def _as_run(desc) -> dict:
    ref = steady_reference(desc)
    return {"times": [0.0, desc.run["t_end"]],
            "pulleys": [{"name": p["name"], "omega_mean": p["omega"],
                         "torque_mean_Nm": p["torque_Nm"]} for p in ref["pulleys"]],
            "spans": [dict(s, tension_mean_N=s["tension_N"]) for s in ref["spans"]],
            "arms": [{"name": p["name"], "angle_mean_rad": p["arm_angle_rad"]}
                     for p in ref["pulleys"] if p["arm_angle_rad"] is not None]}


def test_reference_against_itself_passes():
    desc = load(SERPENTINE)
    checks = bd.serpentine_checks(_as_run(desc), desc)
    assert [c.name for c in checks] == list(bd.SERPENTINE_NAMES)
    assert all(c.passed for c in checks)
    assert max(c.difference for c in checks[:3]) < 1e-12


@pytest.mark.parametrize("row", range(4))
def test_perturbed_copy_fails(row):
    desc = load(SERPENTINE)
    run = _as_run(desc)
    if row == 0:
        run["pulleys"][2]["omega_mean"] *= 1.03
    elif row == 1:
        run["spans"][0]["tension_mean_N"] *= 0.97
    elif row == 2:
        run["arms"][0]["angle_mean_rad"] += 0.01
    else:
        run["pulleys"][3]["torque_mean_Nm"] = 0.02 * abs(run["pulleys"][4]["torque_mean_Nm"])
    assert not bd.serpentine_checks(run, desc)[row].passed
