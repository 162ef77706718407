"""The CLI contract: `ancf scenes`, `ancf run SCENE --set k=v --json`, `ancf analytic NAME`.

JSON keys: scene, params, converged, message, results, cpu_time_s, compile_cpu_s,
warnings.  Exit codes: 0 ok, 2 bad input (one line on stderr naming the field and its
range), 3 no convergence.
"""
import json
import subprocess
import sys

import pytest

from ancf.cli import main

KEYS = {"scene", "params", "converged", "message", "results", "cpu_time_s", "compile_cpu_s",
        "warnings"}


def test_scenes_lists_every_scene_and_reference(cli):
    rc, out, _ = cli("scenes")
    assert rc == 0
    for name in ("simply-supported", "cantilever", "axial-bar", "timoshenko", "reissner"):
        assert name in out


def test_scenes_name_lists_that_entry_only(cli):
    _, full, _ = cli("scenes")
    for name in ("pendulum", "rigid-pendulum", "belt-drive"):
        rc, out, _ = cli("scenes", name)
        assert rc == 0 and out.split()[0] == name and out in full
        assert all(ln.startswith("      ") for ln in out.splitlines()[1:])  # its parameters
        assert len(out.splitlines()) > 2
    rc, out, err = cli("scenes", "pendulums")
    assert rc == 2 and out == "" and len(err.splitlines()) == 1
    assert "'pendulums'" in err and "pendulum," in err and "rigid-pendulum" in err


@pytest.mark.parametrize("cmd,names", [("run", ("cantilever", "belt-drive", "belt3d")),
                                       ("analytic", ("timoshenko", "rigid-pendulum"))])
def test_run_help_names_the_scenes(capsys, cmd, names):
    with pytest.raises(SystemExit) as exc:
        main([cmd, "--help"])
    assert exc.value.code == 0
    text = " ".join(capsys.readouterr().out.split())
    assert "ancf scenes NAME" in text and all(f" {n}," in text or f" {n} " in text for n in names)


@pytest.mark.parametrize("argv,key", [
    (("run", "simply-supported"), "mid_deflection_m"),
    (("run", "cantilever", "--set", "n_elements=4"), "tip_y"),
    (("run", "axial-bar"), "elongation_m"),
    (("analytic", "timoshenko"), "mid_deflection_m"),
    (("analytic", "reissner", "--set", "h=0.5", "--set", "nu=0"), "tip_x"),
])
def test_json_shape(cli, argv, key):
    rc, out, _ = cli(*argv, "--json")
    data = json.loads(out)
    assert rc == 0 and set(data) == KEYS and data["converged"] is True and data["warnings"] == []
    assert isinstance(data["results"][key], float)
    assert data["cpu_time_s"] >= 0


def test_cantilever_default_force_follows_h(cli):
    _, out, _ = cli("run", "cantilever", "--set", "h=0.5", "--set", "n_elements=2", "--json")
    assert json.loads(out)["params"]["F"] == pytest.approx(-5e8 * 0.5**3)


def test_simply_supported_sign_convention(cli):
    _, out, _ = cli("run", "simply-supported", "--json")
    assert json.loads(out)["results"]["mid_deflection_m"] < 0  # downward load, negative


@pytest.mark.parametrize("argv,field", [
    (("run", "cantilever", "--set", "nu=0.5"), "nu"),
    (("run", "cantilever", "--set", "n_elements=0"), "n_elements"),
    (("run", "cantilever", "--set", "n_elements=2.5"), "n_elements"),
    (("run", "cantilever", "--set", "E=-1"), "E"),
    (("run", "cantilever", "--set", "h=abc"), "h"),
    (("run", "cantilever", "--set", "element=beam3"), "element"),
    (("run", "cantilever", "--set", "integration=bogus"), "integration"),
    (("run", "cantilever", "--set", "colour=red"), "colour"),
    (("run", "simply-supported", "--set", "n_elements=3"), "n_elements"),
    (("run", "no-such-scene"), "run"),
    (("analytic", "reissner", "--set", "L=0"), "L"),
])
def test_bad_input_exit_2_one_line(cli, argv, field):
    rc, out, err = cli(*argv)
    assert rc == 2 and out == ""
    lines = err.strip().splitlines()
    assert len(lines) == 1 and field in lines[0] and "allowed" in lines[0]


def test_non_convergence_exit_3_with_json(cli):
    rc, out, _ = cli("run", "cantilever", "--set", "h=0.5", "--set", "nu=0",
                     "--set", "n_elements=64", "--set", "integration=report-selective", "--json")
    data = json.loads(out)
    assert rc == 3 and data["converged"] is False and "No convergence" in data["message"]
    assert set(data) == KEYS


def test_nonconvergence_is_not_nan(cli):
    """A solve that cannot converge (one Newton iteration allowed) reports null, not NaN."""
    rc, out, _ = cli("run", "cantilever", "--set", "max_iterations=1", "--set",
                     "n_elements=2", "--json")
    data = json.loads(out)
    assert rc == 3 and data["results"]["tip_x"] is None and "No convergence" in data["message"]


def test_console_entry_point_runs_as_module():
    proc = subprocess.run([sys.executable, "-m", "ancf.cli", "run", "axial-bar", "--json"],
                          capture_output=True, text=True, check=False)
    assert proc.returncode == 0, proc.stderr
    assert json.loads(proc.stdout)["results"]["elongation_m"] > 0


def test_help_lists_every_command_in_plain_words(capsys):
    with pytest.raises(SystemExit) as exc:
        main(["--help"])
    text = capsys.readouterr().out
    assert exc.value.code == 0
    for cmd in ("scenes", "run", "analytic", "sweep", "recommend"):
        assert f"\n    {cmd} " in text
    assert "run an analytic reference" in text and " a analytic" not in text


def test_recommended_command_line_prints_no_derived_default():
    """`ancf recommend` prints the run as `--set` values: the model knobs and the parameters
    that differ from the scene's derived defaults, so F = -5e8 h^3 (-500000.0000000001 N at
    h = 0.1) is not printed, and the printed line resolves to the very same parameters."""
    from ancf.scenes import SCENES
    from ancf.study.recommend import command_sets
    sc = SCENES["cantilever"]
    for given in ({"n_elements": "16"}, {"n_elements": "16", "h": "0.5"},
                  {"n_elements": "16", "F": "-5e5"}):
        p = sc.resolve(given)
        sets = command_sets("cantilever", p)
        assert ("F" in sets) == ("F" in given) and sets["n_elements"] == 16
        assert sc.resolve({k: repr(v) if isinstance(v, float) else str(v)
                           for k, v in sets.items()}) == p
    assert "-500000.0000000001" not in " ".join(map(str, command_sets(
        "cantilever", sc.resolve({})).values()))
