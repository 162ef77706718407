"""Flanges hold a walking plate belt (issue 36, ancf.belts.flange3d): the driven pulley of
examples/three_pulleys_3d.toml coarsened (20 plates, 5 x 5 contact points, the driver at
20 rad/s: v = 1 m/s, laid on its path) tilted by 3 deg, 0.36 s (3.3 lengths L of its
entering span of travel: without flanges the belt's entry settles toward L tan 3 deg =
5.7 mm, analytic/belt_tracking.py), with flanges 40 mm apart (the belt's width; the
stretched belt is 37.8 mm wide on the pulley, Poisson's contraction of its 19 % strain)
and without.  Seen: without flanges the mean lateral position walks to -4.9 mm, still
walking; with them it stops at -1.5 mm, the flanges pushing 7.0 N along the axis."""
import json

import numpy as np
import pytest

from ancf.belts import post3d
from ancf.common.paths import REPO
from ancf.scenes import SCENES

THREE3D = REPO / "examples" / "three_pulleys_3d.toml"
T_END, TILT, FACE = 0.36, 3.0, 0.04  # s, deg, m


def _run(flanges, t_end: float = T_END, tilt: float = TILT) -> tuple:
    """(results, the scene's result) of the coarse run, the driven pulley tilted by
    ``tilt`` deg with ``flanges`` (True, False, or None: the key not given)."""
    sets = ["pulleys.driver.t0=0", "pulleys.driver.t1=0.02", "pulleys.driven.t0=0",
            "pulleys.driven.t1=0.02", "pulleys.driver.omega_final=20",
            "pulleys.driven.load_torque=0.05", f"pulleys.driven.axis_tilt_deg={tilt}",
            "belt.n_elements=20", "contact.gauss_points=25", "run.start=laid"]
    if flanges is not None:
        sets.append(f"pulleys.driven.flanges={str(flanges).lower()}")
    if flanges:
        sets.append(f"pulleys.driven.face_width_m={FACE}")
    out, res = SCENES["belt-drive"].execute({
        "file": str(THREE3D), "run.t_end": str(t_end), "run.steady_window": "0.005",
        "run.output_dt": "0.0025", "set": "; ".join(sets)})
    assert out["converged"]
    return json.loads(json.dumps(out))["results"], res


@pytest.fixture(scope="module")
def runs() -> dict:
    return {flanges: _run(flanges) for flanges in (True, False)}


def _last_third(results, key: str) -> np.ndarray:
    t = np.array(results["times"])
    return np.array(results["pulleys"][2][key], float)[t >= 2 * T_END / 3]


@pytest.mark.slow
def test_flanges_hold_the_walking_belt(runs):
    """Over the last third of the run the flanged belt's mean lateral position moves less
    than 10 % of the free belt's walk, and ends within half the free belt's offset."""
    held, free = (_last_third(runs[f][0], "lateral_position_m") for f in (True, False))
    assert abs(held[-1] - held[0]) < 0.1 * abs(free[-1] - free[0]), (held, free)
    assert abs(held[-1]) < 0.5 * abs(free[-1]), (held[-1], free[-1])


@pytest.mark.slow
def test_axial_force_picks_up_the_flange_force(runs):
    """The flanges push the belt back toward +p (it walks toward -p), and the pulley's
    axial force is its rim's friction along p (recomputed here from the contact points)
    plus the flanges' force, to round-off; without flanges the flange force is 0."""
    results, res = runs[True]
    flange = _last_third(results, "flange_force_N")
    assert np.all(flange > 0)
    drive, march = res.extra["drive"], res.extra["result"]
    x, v, t = march.q[-1], march.v[-1], float(march.t[-1])
    _, d, _, ft = post3d.contact_sample(drive, x, v, t)[:4]
    rim = np.einsum("eq,eqc,c->", drive.w * (d[:, :, 2] > 0), ft[:, :, 2], drive.axes[2])
    axial = results["pulleys"][2]["axial_force_N"][-1]
    assert axial == pytest.approx(rim + flange[-1], rel=1e-12)
    assert not np.any(_last_third(runs[False][0], "flange_force_N"))


def test_flanges_false_is_the_drive_without_the_key():
    """``flanges = false`` runs bit for bit the drive that does not name the key (the
    flange kernel is not called: ancf.belts.flange3d.NO_FLANGES)."""
    (a, ra), (b, rb) = (_run(f, t_end=0.05, tilt=1.0) for f in (False, None))
    assert a["times"] == b["times"] and a["pulleys"] == b["pulleys"]
    assert np.array_equal(ra.extra["result"].q, rb.extra["result"].q)


def test_misaligned_example_runs_from_the_cli(capsys):
    """``ancf run belt-drive --file examples/misaligned.toml`` (cut to 0.05 s) converges
    and reports the driven pulley's flange force (the example's flanged, tilted pulley)."""
    from ancf.cli import main
    assert main(["run", "belt-drive", "--json", "--file", str(REPO / "examples" /
                                                             "misaligned.toml"),
                 "--set", "run.t_end=0.05", "--set", "run.steady_window=0.01"]) == 0
    out = json.loads(capsys.readouterr().out)
    driven = out["results"]["pulleys"][2]
    assert out["converged"] and driven["name"] == "driven"
    assert len(driven["flange_force_N"]) == len(out["results"]["times"])
    assert all(f == 0.0 for p in out["results"]["pulleys"][:2] for f in p["flange_force_N"])
