"""The Python API validates like the command line (issue 33, item 5): a wrong type, a
boolean where a number is expected, or two arguments that contradict each other raise
``ancf.InputError`` naming the argument and what is allowed, never a raw TypeError /
ValueError and never one of the two silently winning.  Every case is refused before any
run starts, so the list is fast; the accepted neighbours at the end show the checks do
not refuse what is right.
"""
from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

import ancf
from ancf.common.params import Param

#: (the call, words the message must hold: the argument named, then what is allowed)
BAD_CALLS = [
    # the issue's examples
    (lambda: ancf.run("cantilever", 8), ("overrides: 8", "allowed: a dict")),
    (lambda: ancf.sweep("axial-bar", grid="n_elements=2"), ("grid: 'n_elements=2'", "allowed:")),
    (lambda: ancf.sweep("axial-bar", grid={"n_elements": None}), ("grid n_elements: None",
                                                                  "allowed: a value")),
    (lambda: ancf.sweep("axial-bar", grid={"n_elements": [2]}, out=123), ("out: 123",
                                                                          "allowed: a file")),
    (lambda: ancf.sweep("axial-bar", grid={"n_elements": [2]}, workers=0),
     ("workers = 0", "allowed: an integer in [1, inf)")),
    # wrong types, any function
    (lambda: ancf.run(["cantilever"]), ("run: unknown name ['cantilever']", "allowed:")),
    (lambda: ancf.run("cantilever", "n_elements=2"), ("overrides: 'n_elements=2'", "allowed:")),
    (lambda: ancf.run("cantilever", {1: 2}), ("overrides: {1: 2}", "allowed: a dict")),
    (lambda: ancf.run("cantilever", n_elements=[1, 2]), ("n_elements: [1, 2]", "an integer")),
    (lambda: ancf.run("cantilever", E={"a": 1}), ("E: {'a': 1}", "a number")),
    (lambda: ancf.run("cantilever", vtk=5), ("vtk: 5", "allowed: a file name")),
    (lambda: ancf.analytic("reissner", [1]), ("overrides: [1]", "allowed: a dict")),
    (lambda: ancf.analytic(None), ("analytic: unknown name None", "allowed: timoshenko")),
    (lambda: ancf.modes("cantilever", 3), ("overrides: 3", "allowed: a dict")),
    (lambda: ancf.modes(["cantilever"]), ("modes: unknown name", "allowed:")),
    (lambda: ancf.modes("cantilever", count=[2]), ("count: [2]", "an integer")),
    (lambda: ancf.modes("cantilever", about=3), ("about: 3", "reference, equilibrium")),
    (lambda: ancf.sweep(["axial-bar"]), ("sweep: unknown name", "allowed:")),
    (lambda: ancf.sweep("axial-bar", grid=[]), ("grid: []", "allowed:")),
    (lambda: ancf.sweep("axial-bar", grid={}), ("grid: {}", "at least one parameter")),
    (lambda: ancf.sweep("axial-bar", grid=["n_elements=2"]), ("grid: 'n_elements=2'", "allowed:")),
    (lambda: ancf.sweep("axial-bar", grid={"n_elements": []}), ("grid n_elements: []",
                                                                "non-empty")),
    (lambda: ancf.sweep("axial-bar", grid={"n_elements": {2, 4}}), ("grid n_elements",
                                                                    "allowed:")),
    (lambda: ancf.sweep("axial-bar", fixed="F=1"), ("fixed: 'F=1'", "allowed: a dict")),
    (lambda: ancf.sweep("axial-bar", time_limit="5"), ("time_limit: '5'", "a number")),
    (lambda: ancf.sweep("axial-bar", time_limit=0), ("time_limit = 0", "(0, inf)")),
    (lambda: ancf.sweep("axial-bar", workers=1.5), ("workers = 1.5", "an integer")),
    (lambda: ancf.sweep("axial-bar", workers="2"), ("workers: '2'", "an integer")),
    (lambda: ancf.sweep("axial-bar", retry_failed="no"), ("retry_failed: 'no'", "True or False")),
    (lambda: ancf.sweep("axial-bar", progress=1), ("progress: 1", "True or False")),
    (lambda: ancf.sweep("axial-bar", log="stderr"), ("log: 'stderr'", "a function")),
    (lambda: ancf.sweep("axial-bar", reference=3), ("reference: 3", "allowed:")),
    (lambda: ancf.sweep("axial-bar", scheduler=8786), ("scheduler: 8786", "tcp://")),
    (lambda: ancf.sweep("axial-bar", quantity=None), ("quantity: None", "results or frequency")),
    (lambda: ancf.recommend(["cantilever"], 1e-3), ("recommend: unknown name", "allowed:")),
    (lambda: ancf.recommend("cantilever", "1e-3"), ("tol: '1e-3'", "a number in (0, inf)")),
    (lambda: ancf.recommend("cantilever", 1e-3, fixed=[("E", 1)]), ("fixed:", "a dict")),
    (lambda: ancf.recommend("cantilever", 1e-3, data=7), ("data: 7", "a file name")),
    (lambda: ancf.recommend("cantilever", 1e-3, workers=0), ("workers = 0", "[1, inf)")),
    # booleans are not numbers (Python counts True as 1: E = 1 Pa, one element)
    (lambda: ancf.run("cantilever", E=True), ("E: True", "(a boolean)")),
    (lambda: ancf.run("cantilever", n_elements=True), ("n_elements: True", "[1, 4096]")),
    (lambda: ancf.run("pendulum", t_end=np.bool_(True)), ("t_end: ", "(a boolean)")),
    (lambda: ancf.analytic("timoshenko", F=False), ("F: False", "(a boolean)")),
    (lambda: ancf.modes("cantilever", count=True), ("count: True", "an integer")),
    (lambda: ancf.sweep("axial-bar", grid={"n_elements": [True, 2]}),
     ("n_elements: True", "(a boolean)")),
    (lambda: ancf.sweep("axial-bar", workers=True), ("workers: True", "an integer")),
    (lambda: ancf.sweep("axial-bar", time_limit=True), ("time_limit: True", "a number")),
    (lambda: ancf.recommend("cantilever", True), ("tol: True", "a number")),
    # conflicting arguments: refused, not one of them silently dropped
    (lambda: ancf.run("cantilever", {"n_elements": 2}, n_elements=4),
     ("n_elements: given as overrides (2) and as a keyword (4)", "one value")),
    (lambda: ancf.modes("cantilever", {"h": 0.1}, h=0.2), ("h: given as overrides", "one value")),
    (lambda: ancf.sweep("axial-bar", grid={"n_elements": [2, 4]}, fixed={"n_elements": 8}),
     ("n_elements: given in the grid (2, 4) and fixed", "one of them")),
    (lambda: ancf.sweep("axial-bar", grid=[{"F": [1.0]}, {"n_elements": [2, 3]}],
                        fixed={"n_elements": "4"}), ("n_elements: given in the grid", "one of")),
    (lambda: ancf.sweep("axial-bar", workers=2, scheduler="tcp://127.0.0.1:1"),
     ("workers = 2 and scheduler: both given", "one of them")),
    (lambda: ancf.recommend("cantilever", 1e-3, data="x.csv", workers=2),
     ("--data and --workers / --scheduler: both given", "allowed:")),
    # bounded cost: a grid above the run limit, unless forced
    (lambda: ancf.sweep("axial-bar", grid={"n_elements": list(range(1, 401)),
                                           "F": [float(f) for f in range(1, 301)]}),
     ("sweep: 120000 runs (at least", "allowed: at most 100000 runs")),
]


@pytest.mark.parametrize("call, words", BAD_CALLS, ids=[f"bad{i}" for i in range(len(BAD_CALLS))])
def test_bad_call_raises_input_error_naming_the_argument(call, words, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)  # a sweep that got through would write here, not in the tree
    with pytest.raises(ancf.InputError) as exc:
        call()
    message = str(exc.value)
    assert "\n" not in message and "allowed: " in message, message
    for w in words:
        assert w in message, message
    assert not any(tmp_path.iterdir()), "refused before anything was written"


def test_the_list_is_long_enough_and_every_function_is_in_it():
    import inspect
    src = inspect.getsource(inspect.getmodule(test_bad_call_raises_input_error_naming_the_argument))
    assert len(BAD_CALLS) >= 30
    for name in ("run", "modes", "analytic", "sweep", "recommend"):
        assert f"ancf.{name}(" in src


def test_a_boolean_is_refused_by_every_parameter_kind():
    for kind, default in ((float, 1.0), (int, 1), (str, "a")):
        p = Param("x", default, kind, lo=0 if kind is not str else None)
        for value in (True, False, np.bool_(True)):
            with pytest.raises(ancf.InputError, match=r"x: .* is not valid \(a boolean\)"):
                p.parse(value)
    assert Param("x", 1.0, float, lo=0).parse(1) == 1.0  # a number still is one
    assert Param("n", 1, int, lo=1).parse(np.int64(3)) == 3


def test_the_accepted_neighbours_still_run():
    """The same value in both places is no conflict; numpy numbers are numbers; a
    bar of two elements under F stretches by F L / (E A) (linear: the analytic answer)."""
    r = ancf.run("axial-bar", {"n_elements": 2}, n_elements=np.int64(2), F=np.float64(1e3))
    assert r.converged and r.params["n_elements"] == 2
    p = r.params
    stretch = p["F"] * p["L"] / (p["E"] * p["b"] * p["h"])
    assert r.results["elongation_m"] == pytest.approx(stretch, rel=1e-5)  # strain 5e-7


def test_a_drive_file_boolean_is_refused_by_name(tmp_path, examples, cli):
    """TOML's ``E = true`` ran as E = 1 Pa; now one error line naming belt.E, and a vector
    with a boolean entry too (exit 2)."""
    text = (examples / "three_pulleys.toml").read_text()
    for old, new, key in (("E = 1e8", "E = true", "belt.E = True"),
                          ("centre = [0.0, -0.2]", "centre = [false, -0.2]",
                           "pulleys.1.centre = [False, -0.2]"),
                          ("inertia = 0.1 ", "inertia = true ", "pulleys.2.inertia = True")):
        assert old in text
        f = tmp_path / "drive.toml"
        f.write_text(text.replace(old, new))
        rc, out, err = cli("run", "belt-drive", "--file", str(f), "--json")
        assert rc == 2 and err.startswith(f"error: {key} is not valid (a boolean); allowed:"), err
        assert len(err.splitlines()) == 1 and out == ""


def test_api_message_is_the_cli_message_for_the_same_input(cli):
    """A boolean given to the API and ``--set E=true`` name the same field; a duplicate
    ``--set`` of different values is a conflict as a dict plus keyword is."""
    rc, _, err = cli("run", "cantilever", "--set", "n_elements=2", "--set", "n_elements=4")
    assert rc == 2 and err == ("error: --set n_elements: given twice (n_elements=2, "
                               "n_elements=4); allowed: one value per key\n")
    rc, _, err = cli("run", "cantilever", "--set", "E=true")
    assert rc == 2 and err.startswith("error: E: 'true' is not valid; allowed: a number")


def test_file_and_set_file_together_are_a_conflict(cli, examples):
    a, b = examples / "three_pulleys.toml", examples / "thesis_table_3_1.toml"
    for cmd in (["run", "belt-drive"], ["sweep", "belt-drive", "--out", "never.csv"]):
        rc, _, err = cli(*cmd, "--file", str(a), "--set", f"file={b}")
        assert rc == 2 and "two drive files; allowed: one of them" in err, err
        assert not Path("never.csv").exists()
