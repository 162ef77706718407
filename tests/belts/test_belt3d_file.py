"""The 3D plate belt from a drive file (issue 21 item 3): ``belt.element = "plate36"``.

The thesis's 3D drive file (examples/thesis_table_4_1.toml, Table 4.1 Model 2) holds
``ancf run belt3d``'s defaults key for key and its run equals belt3d's bit for bit (belt
coordinates, pulley speeds, span tensions, the driven pulley's friction moment); a
three-pulley plate belt (examples/three_pulleys_3d.toml: driver, idler, driven pulley)
runs a short time without a warning; the plate belt's weight is its mass times gravity."""
import json

import numpy as np
import pytest

from ancf.belts.drive3d import laid_plate_belt
from ancf.belts.drive_file import load
from ancf.belts.drive_model import build
from ancf.common.paths import REPO
from ancf.scenes import SCENES
from ancf.scenes import belt3d as b3
from ancf.study.schemas import schema, validate
from tests.belts.plate_runs import assert_file_run_is_belt3d

EXAMPLES = REPO / "examples"
THESIS3D, THREE3D = EXAMPLES / "thesis_table_4_1.toml", EXAMPLES / "three_pulleys_3d.toml"
SHORT = "0.02"  # s: 200 steps of 1e-4 s


def test_thesis_4_1_file_is_belt3d_defaults_key_for_key():
    """Every parameter of ``ancf run belt3d`` (model 2) that defines the drive has its value
    in the file (the model, the reported strain measure, the integrator and the derived T_i,
    u0 = 0 and centre distance aside, each checked through what it gives), and the belt laid
    on the file's path is belt3d's, bit for bit."""
    d, p = load(THESIS3D), SCENES["belt3d"].resolve({})
    driver, driven = d.pulleys
    b = d.belt
    got = dict(n_elements=b["n_elements"], E=b["E"], nu=b["nu"], rho=b["rho"], h=b["h"],
               width=b["b"], bending=b["bending"], R=driver.radius,
               belt_length=b["length"], k_p=d.contact["k_p"], c_p=d.contact["c_p"],
               contact_points=d.contact["gauss_points"], mu=d.friction["mu"],
               nu_s=d.friction["nu_s"], inertia=driven.params["inertia"],
               omega_final=driver.params["omega_final"], t1=driver.params["t1"],
               Ta_max=driven.params["load_torque"], start=d.run["start"],
               **{k: d.run[k] for k in ("dt", "rho_inf", "newton_tol", "t_end", "output_dt",
                                        "steady_window", "max_steps")})
    assert set(got) == set(p) - {"model", "strain_measure", "integrator", "T_i", "u0",
                                 "centre_distance"}
    want = dict(p, belt_length=b3.belt_length(p))
    assert got == {k: want[k] for k in got}
    assert p["u0"] == 0.0 and driven.radius == p["R"]
    assert (driver.centre, driven.centre) == ((0.0, 0.0), (p["centre_distance"], 0.0))
    assert (driver.params["speed"], driven.params["load"]) == ("ramp", "cosine-ramp")
    assert (driver.params["t0"], driven.params["t0"], driven.params["t1"]) == (b3.T0, b3.T0,
                                                                              b3.TA_T1)
    assert driven.params["damping"] == 0 and d.gravity == (0.0, 0.0)
    assert b["elastic_points"] == b3.spec(p).ng and d.friction["law"] == b3.LAW
    spec = b3.spec(p)
    assert laid_plate_belt(d.path, b["length"], 20, b["b"]).tobytes() == \
        laid_plate_belt(spec.path, spec.belt_length, 20, spec.width).tobytes()


def test_thesis_4_1_file_runs_belt3d_exactly():
    """The same march on the same model: every sample's coordinates and velocities, the
    pulley speeds, the span tensions (the membrane's, along the edge z = 0), the driven
    pulley's friction moment and the run statistics equal belt3d's at a short t_end."""
    a, ra = SCENES["belt-drive"].execute({"file": str(THESIS3D), "run.t_end": SHORT,
                                          "run.steady_window": SHORT})
    b, rb = SCENES["belt3d"].execute({"t_end": SHORT})
    xa, xb = ra.extra["result"], rb.extra["result"]
    assert a["converged"] and b["converged"]
    a, b = json.loads(json.dumps(a))["results"], json.loads(json.dumps(b))["results"]
    assert_file_run_is_belt3d(xa, a, xb, b)


#: the idler inside the loop (the example's), or on the belt's back pressing the lower
#: span up by 25 mm from outside (a 42 deg wrap)
IDLERS = {"inner": [], "back": ["pulleys.idler.side=-1", "pulleys.idler.centre=[0.0785, -0.05]"]}


@pytest.mark.parametrize("idler", IDLERS)
def test_three_pulley_plate_belt_runs_sane(idler):
    """Driver, idler on the lower span and driven pulley, the laws ramped within the first
    10 ms: converged, valid JSON, every span in tension, every pulley turning with the belt
    (counter-clockwise; an idler on the belt's back clockwise), the penetration below 5 % of
    the pre-stretch per wrap, the belt not walking along the axes; no warning but the ones
    this 20 ms run must give: the idler and the driven pulley, spun up within 10 ms, still
    overshoot and slide over their wraps in the 5 ms window (``sense.gross_slip``: rims 0.2
    to 0.5 ahead of the driver's; the example's own 0.6 s run gives no warning)."""
    sets = ["pulleys.driver.t0=0", "pulleys.driver.t1=0.01", "pulleys.driven.t0=0",
            "pulleys.driven.t1=0.01", "pulleys.driver.omega_final=20",
            "pulleys.driven.load_torque=0.05", *IDLERS[idler]]
    out, res = SCENES["belt-drive"].execute({"file": str(THREE3D), "run.t_end": SHORT,
                                             "run.steady_window": "0.005",
                                             "set": "; ".join(sets)})
    out = json.loads(json.dumps(out))
    transient = [w for w in out["warnings"] if w.startswith(("idler: gross slip",
                                                             "driven: gross slip"))]
    assert out["converged"] and out["warnings"] == transient, out["warnings"]
    assert validate(out, schema("belt-drive")) == []
    r, desc = out["results"], res.extra["description"]
    assert [p["name"] for p in r["pulleys"]] == ["driver", "idler", "driven"]
    assert all(s["tension_N"] > 0 and s["tension_mean_N"] > 0 for s in r["spans"])
    assert all(p["omega"][-1] * q.side > 0 for p, q in zip(r["pulleys"], desc.pulleys))
    pre = -desc.belt["prestretch"] * desc.path.length / (2 * np.pi)
    assert 0 < r["penetration_max_m"] < 0.05 * pre
    drive, q = res.extra["drive"], res.extra["result"].q
    z0, z1 = (drive.belt(x).reshape(-1, 3, 3)[:, 0, 2] for x in (q[0], q[-1]))
    assert abs(z1.mean() - z0.mean()) < 1e-3 * desc.belt["b"]


def test_plate_belt_weight_is_its_mass_times_gravity():
    """The in-plane gravity's generalised forces sum to m g (the position shape functions
    sum to 1), m = rho h b L0, to round-off."""
    d = load(THREE3D, ["gravity=[3.0, -9.81]"])
    drive = build(d)
    w = drive.belt(np.append(drive.weight, np.zeros(drive.k))).reshape(-1, 3, 3)
    m = d.belt["rho"] * d.belt["h"] * d.belt["b"] * d.belt["length"]
    assert w[:, 0].sum(axis=0) == pytest.approx([3.0 * m, -9.81 * m, 0.0], rel=1e-12, abs=1e-15)


@pytest.mark.parametrize("path, element", [(THESIS3D, "plate36"), (None, "dufva2d")])
def test_sweeps_and_recommend_vary_the_files_own_element(path, element):
    """``ancf sweep|recommend belt-drive --file F`` vary the contact points the file's element
    takes (a plate: n x n over its surface; Dufva's: Gauss points along it), and every value
    of the grid is one the file accepts."""
    from ancf.scenes.belt_drive import DRIVE_GRIDS
    from ancf.study.references import spec
    p = SCENES["belt-drive"].resolve({"file": str(path)} if path else {})
    grids = spec("belt-drive").grids(p)
    assert grids == DRIVE_GRIDS[element] == spec("belt-drive").grids(p, "report")
    for g in grids:
        for n in g["n_elements"]:
            for k in g["gauss_points"]:
                SCENES["belt-drive"].resolve({**p, "n_elements": n, "gauss_points": k})


@pytest.mark.parametrize("path", [THESIS3D, THREE3D])
def test_the_plate_belt_files_have_a_steady_reference(path):
    """The steady belt of a plate-belt file (the belt_drives chapter tabulates every
    example's): its tensions balance each pulley's torque, (T_in - T_out) R."""
    from ancf.belts.drive_steady import steady_reference
    desc = load(path)
    ref = steady_reference(desc)
    assert len(ref["spans"]) == len(desc.pulleys) == len(ref["pulleys"])
    assert all(s["tension_N"] > 0 for s in ref["spans"])
