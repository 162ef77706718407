"""Belt drives on N pulleys (issue 21 items 3-4): `ancf run belt-drive --file`.

The thesis drive's file gives belt2d's numbers exactly; a three-pulley drive with an idler
(examples/three_pulleys.toml) settles to the steady reference of analytic/belt_steady.py
(Bechtel's extensible string on the same layout, Coulomb friction with stick and creep
arcs); bad input is one line."""
import json

import numpy as np
import pytest

from ancf.belts.drive_file import describe, load, read
from ancf.cli import main
from ancf.common.paths import REPO
from ancf.scenes import SCENES
from ancf.belts.system import small_lu, small_solve
from analytic.belt_steady import solve

EXAMPLES = REPO / "examples"
TIMING = ("cpu_time_s", "compile_cpu_s")


def _run(overrides):
    out, _ = SCENES["belt-drive"].execute(overrides)
    return json.loads(json.dumps(out))


def test_thesis_file_gives_belt2d_exactly():
    a = _run({"file": str(EXAMPLES / "thesis_table_3_1.toml"), "run.t_end": "0.1"})
    b = json.loads(json.dumps(SCENES["belt2d"].execute({"t_end": "0.1"})[0]))
    ra, rb = a["results"], b["results"]
    assert a["converged"] and b["converged"]
    assert ra["times"] == rb["times"]
    assert ra["pulleys"][0]["omega"] == rb["omega_driver"]
    assert ra["pulleys"][1]["omega"] == rb["omega_driven"]
    lower, upper = ra["spans"]  # driver -> driven below, driven -> driver above (tight)
    assert (upper["tension_N"], lower["tension_N"]) == (rb["tension_tight_N"],
                                                        rb["tension_slack_N"])
    assert (upper["tension_mean_N"], lower["tension_mean_N"]) == (rb["tension_tight_mean_N"],
                                                                  rb["tension_slack_mean_N"])
    for key in ("steps", "nfev", "newton_iterations", "contact_pairs", "penetration_max_m",
                "total_dofs", "pretension_iterations"):
        assert ra[key] == rb[key], key


def _reference(drive):
    """analytic.belt_steady on the drive file's layout and final laws."""
    pulleys = []
    for p in drive.pulleys:
        q = {"name": p.name, "centre": p.centre, "radius": p.radius, "side": p.side,
             "law": p.law}
        if p.law == "prescribed":
            q["omega"] = p.params["omega_final"]
        elif p.law == "driven":
            q.update(torque=p.params["load_torque"], damping=p.params["damping"])
        else:
            q["damping"] = p.params["damping"]
        pulleys.append(q)
    b = drive.belt
    return solve(pulleys, EA=b["EA"], rhoA=b["rho"] * b["b"] * b["h"], L0=b["length"],
                 mu=drive.friction["mu"])


def test_three_pulleys_with_an_idler_settle_to_the_steady_reference():
    """Speeds within 0.5 % (the creep-rate law's slip against Coulomb's stick arcs: 0.15 %
    seen), the driver's torque within 1 % (0.46 % seen: the driven pulley's inertia and the
    span oscillations in the window), span tensions within 3 % (0.7 % tight, 2.2 % slack
    seen: the creep-rate law spreads each tension change over the whole wrap, Coulomb's
    puts it at the exit; the penalty's penetration shortens the path by ~0.2 mm), and the
    idler's moment below 0.2 % of the driver's (0.1 % seen)."""
    path = EXAMPLES / "three_pulleys.toml"
    out = _run({"file": str(path)})
    assert out["converged"] and out["warnings"] == []
    r, ref = out["results"], _reference(load(path))
    window = np.array(r["times"]) >= r["times"][-1] - 0.3 - 1e-12
    for ours, theirs in zip(r["pulleys"], ref["pulleys"]):
        assert ours["name"] == theirs["name"]
        assert ours["omega_mean"] == pytest.approx(theirs["omega"], rel=5e-3)
    torques = [np.mean(np.array(p["torque_Nm"])[window]) for p in r["pulleys"]]
    assert torques[0] == pytest.approx(ref["pulleys"][0]["torque_Nm"], rel=1e-2)
    assert abs(torques[1]) < 2e-3 * abs(torques[0])
    for ours, theirs in zip(r["spans"], ref["spans"]):
        assert (ours["from"], ours["to"]) == (theirs["from"], theirs["to"])
        assert ours["tension_mean_N"] == pytest.approx(theirs["tension_N"], rel=3e-2)


@pytest.mark.parametrize("k", [1, 2, 4])
def test_small_lu_solves_with_pivoting(k):
    rng = np.random.default_rng(k)
    A = rng.normal(size=(k, k))
    A[0, 0] = 0.0 if k > 1 else A[0, 0]  # a zero first pivot: the rows must be swapped
    b = rng.normal(size=k)
    F, piv, x = A.copy(), np.zeros(k, dtype=np.int64), b.copy()
    assert small_lu(F, piv)
    small_solve(F, piv, x)
    assert np.allclose(A @ x, b, rtol=0, atol=1e-12)


@pytest.mark.parametrize("args,message", [
    (["--file", "no/such.toml"], "no/such.toml: no such file"),
    (["--set", "pulleys.idler.radius=0.3"], "pulleys: pulleys 'driver' and 'idler' overlap"),
    (["--set", "friction.mu=-1"], "friction.mu = -1.0 is out of range"),
    (["--set", "belt.damping_axial=1"], "belt.damping_axial = 1.0: strain-rate damping is not"),
    (["--set", "pulleys.idler.law=fixed"], "pulleys.1.inertia: unknown key"),
])
def test_bad_input_is_one_line(args, message, capsys):
    argv = ["run", "belt-drive", "--json"] + args
    if "--file" not in args:
        argv += ["--file", str(EXAMPLES / "three_pulleys.toml")]
    assert main(argv) == 2
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1 and err.startswith("error: ") and message in err, err


def test_file_only_for_the_file_scene(capsys):
    assert main(["run", "belt2d", "--file", str(EXAMPLES / "three_pulleys.toml")]) == 2
    assert "--file: scene 'belt2d' takes no file" in capsys.readouterr().err


def test_what_the_dynamics_lack_is_refused_in_one_line():
    from ancf.belts.drive_model import build
    from ancf.common.params import InputError
    with pytest.raises(InputError, match=r"^pulleys.1.law = 'tensioner' is not in the dynamics "
                       "yet; allowed: prescribed, driven, idler, fixed$"):
        build(load(EXAMPLES / "serpentine.toml"))
    data = read(EXAMPLES / "serpentine.toml")
    data["pulleys"][1] = {k: data["pulleys"][1][k] for k in ("name", "centre", "radius", "side")}
    data["pulleys"][1]["law"] = "fixed"
    with pytest.raises(InputError, match=r"^pulleys.1.side = -1: a pulley on the belt's back"):
        build(describe(data))
