"""The Python API (issue 23, item 5): ``ancf.run`` / ``ancf.analytic`` return what the CLI
prints (to_json equal to ``--json`` apart from the timing values), raise ``ancf.InputError``
with the CLI's one-line message, give the mesh, the final coordinates and the time
histories; ``ancf.sweep`` / ``ancf.recommend`` wrap the study layer; the docstring examples
and each example of the Python API guide (docs/guide/python.md) runs by itself."""
from __future__ import annotations

import doctest
import json
import re
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

import ancf

ROOT = Path(__file__).resolve().parents[2]


def _untimed(obj):
    """``obj`` with every timing value (a key naming cpu or wall time) set to 0."""
    if isinstance(obj, dict):
        return {k: 0 if re.search(r"cpu|wall", k) else _untimed(v) for k, v in obj.items()}
    if isinstance(obj, list):
        return [_untimed(v) for v in obj]
    return obj


@pytest.mark.parametrize("command, name, sets", [
    ("run", "cantilever", {"n_elements": 4, "h": 0.5, "nu": 0}),
    ("analytic", "reissner", {"h": 0.5}),
    ("run", "pendulum", {"t_end": 0.05, "output_dt": 0.01}),
    ("run", "plate-square", {"n_elements": 4}),
])
def test_to_json_is_what_the_cli_prints(cli, command, name, sets):
    res = getattr(ancf, command if command == "analytic" else "run")(name, **sets)
    argv = [command, name, *[a for k, v in sets.items() for a in ("--set", f"{k}={v}")], "--json"]
    rc, out, _ = cli(*argv)
    assert rc == (0 if res.converged else 3)
    cli, api = json.loads(out), json.loads(res.to_json())
    assert list(api) == list(cli)  # same keys, same order
    assert _untimed(api) == _untimed(cli)
    # the string itself, timing values aside
    strip = lambda s: re.sub(r'("[a-z_]*(?:cpu|wall)[a-z_]*": )[-0-9.e+]+', r"\1 0", s)  # noqa: E731
    assert strip(res.to_json()) == strip(out.strip())
    assert (res.scene, res.params, res.converged, res.message, res.warnings) == (
        cli["scene"], cli["params"], cli["converged"], cli["message"], cli["warnings"])
    assert res.cpu_time_s >= 0 and res.command == command
    assert res.to_dict()["results"] == json.loads(res.to_json())["results"]


@pytest.mark.parametrize("command, name, sets", [
    ("run", "cantilever", {"n_elements": 0}),
    ("run", "cantilever", {"n_elements": 2.5}),
    ("run", "cantilever", {"element": "quadratic"}),
    ("run", "cantilever", {"surprise": 1}),
    ("run", "cantileverr", {}),
    ("analytic", "reissner", {"nu": 0.5}),
    ("analytic", "nope", {}),
    ("run", "spinning-beam", {"t_end": 1, "mean_window": 2}),
])
def test_bad_input_raises_the_cli_message(cli, command, name, sets):
    fn = ancf.analytic if command == "analytic" else ancf.run
    with pytest.raises(ancf.InputError) as exc:
        fn(name, **sets)
    argv = [command, name, *[a for k, v in sets.items() for a in ("--set", f"{k}={v}")]]
    rc, out, err = cli(*argv)
    assert rc == 2 and out == ""
    assert err == f"error: {exc.value}\n"
    assert "\n" not in str(exc.value)
    assert ancf.InputError is __import__("ancf.common.params", fromlist=["x"]).InputError


def test_static_beam_mesh_and_final_coordinates():
    n = 4
    r = ancf.run("cantilever", n_elements=n)
    L = r.params["L"]
    assert r.reference_nodes.shape == (n + 1, 2)
    assert np.allclose(r.reference_nodes[:, 0], np.linspace(0, L, n + 1), atol=0, rtol=1e-15)
    assert np.all(r.reference_nodes[:, 1] == 0)
    assert r.nodes[-1].tolist() == [r.results["tip_x"], r.results["tip_y"]]
    assert r.nodes[0].tolist() == r.reference_nodes[0].tolist()  # clamped
    assert r.q.shape == r.q0.shape and not np.array_equal(r.q, r.q0)
    assert r.times is None and r.node_history is None and r.series == {}


def test_other_meshes_give_their_nodes():
    sq = ancf.run("plate-square", n_elements=4)
    centre = np.argmin(np.linalg.norm(sq.reference_nodes[:, :2] - [0.5 * sq.params["a"]] * 2, axis=1))
    dz = sq.nodes[centre, 2] - sq.reference_nodes[centre, 2]
    assert dz == pytest.approx(sq.results["center_deflection_m"], rel=1e-12)
    assert sq.reference_nodes.shape == (25, 3)
    strip = ancf.run("plate-strip", n_elements=2)
    tip = strip.reference_nodes[:, 0] == strip.params["L"]
    assert strip.nodes[tip, 2].mean() == pytest.approx(strip.results["tip_z"], rel=1e-12)
    b3 = ancf.run("beam3d-cantilever", n_elements=2, load_angle_deg=30)
    assert b3.nodes[-1].tolist() == [b3.results[f"tip_{c}"] for c in "xyz"]
    free = ancf.run("belt-free-static", n_elements=10)
    c = free.nodes.mean(axis=0)
    rad = np.linalg.norm(free.nodes - c, axis=1)  # the nodes lie on the circle
    assert np.abs(rad - free.results["radius_mean_m"]).max() <= 2 * free.results["radius_max_dev_m"]
    assert not np.allclose(free.reference_nodes, free.nodes)  # from the wrapped path


def test_dynamic_scene_time_histories():
    r = ancf.run("pendulum", t_end=0.1, output_dt=0.02, n_elements=2)
    t = r.times
    assert np.allclose(t, np.linspace(0, 0.1, 6), rtol=0, atol=1e-15)
    assert set(r.series) >= {"times", "tip_x", "tip_y", "energy_total"}
    h = r.node_history
    assert h.shape == (6, 3, 2)
    assert np.array_equal(h[:, -1, 0], r.series["tip_x"])
    assert np.array_equal(h[:, -1, 1], r.series["tip_y"])
    assert np.array_equal(h[0], r.reference_nodes) and np.array_equal(h[-1], r.nodes)
    assert np.allclose(h[:, 0], 0, atol=1e-12)  # pinned
    assert h[-1, -1, 1] < 0  # falling


def test_analytic_reference_has_results_but_no_mesh():
    r = ancf.analytic("rigid-pendulum", t_end=0.1, output_dt=0.05)
    assert r.times.tolist() == [0.0, 0.05, 0.1]
    assert np.array_equal(r.series["tip_y"], np.array(r.results["tip_y"], float))
    assert r.nodes is None and r.reference_nodes is None and r.node_history is None
    with pytest.raises(ancf.InputError, match="no mesh"):
        r.write_vtk("unused")


def test_scenes_lists_scenes_and_references_with_parameters():
    from ancf.scenes import SCENES
    from ancf.scenes.analytic import REFERENCES
    import ancf.api
    info = ancf.scenes()  # the package ancf.scenes, callable
    assert info == ancf.api.scenes() and ancf.scenes is sys.modules["ancf.scenes"]
    assert [(s["command"], s["name"]) for s in info] == (
        [("run", n) for n in SCENES] + [("analytic", n) for n in REFERENCES])
    for s in info:
        sc = (SCENES if s["command"] == "run" else REFERENCES)[s["name"]]
        assert list(s["params"]) == [p.name for p in sc.params] and s["doc"] == sc.doc
    cant = next(s for s in info if s["name"] == "cantilever")["params"]
    assert cant["F"]["default"] is None and cant["F"]["depends_on_others"]
    assert cant["n_elements"]["default"] == ancf.run("cantilever").params["n_elements"]


@pytest.mark.slow
def test_sweep_returns_a_dataframe_and_recommend_answers_from_it(tmp_path):
    import pandas as pd
    out = tmp_path / "sw.parquet"
    df = ancf.sweep("cantilever", grid={"n_elements": [2, 4]}, workers=1, out=out)
    assert isinstance(df, pd.DataFrame) and out.exists()
    assert sorted(df["n_elements"]) == [2, 4] and set(df["status"]) == {"ok"}
    tips = {n: ancf.run("cantilever", n_elements=n).results["tip_y"] for n in (2, 4)}
    for _, row in df.iterrows():
        assert row["res_tip_y"] == tips[row["n_elements"]]
    again = ancf.sweep("axial-bar", grid={"n_elements": 1})  # a temporary file, removed
    assert len(again) == 1
    with pytest.raises(ancf.InputError, match="n_elements"):
        ancf.sweep("cantilever", grid={"n_elements": [0]})
    with pytest.raises(ancf.InputError, match="unknown parameter"):
        ancf.sweep("cantilever", grid={"nope": [1]})
    best = df.loc[df["error"].idxmin()]
    tol = float(best["error"]) * 1.01
    rec = ancf.recommend("cantilever", tol, data=out)
    assert rec["found"] and rec["params"]["n_elements"] == best["n_elements"]
    assert ancf.run("cantilever", **rec["params"]).converged
    with pytest.raises(ancf.InputError):
        ancf.recommend("cantilever", -1.0, data=out)


@pytest.mark.slow
def test_import_ancf_is_cheap_and_the_api_light():
    code = ("import sys, ancf\n"
            "before = 'ancf.api' in sys.modules or 'numpy' in sys.modules\n"
            "r = ancf.run('cantilever', n_elements=2)\n"
            "heavy = [m for m in ('sympy', 'pandas', 'dask', 'matplotlib', 'meshio') if m in sys.modules]\n"
            "print(before, 'ancf.api' in sys.modules, heavy, r.converged)\n"
            "import ancf.scenes as pkg\n"
            "print(ancf.scenes is pkg, len(ancf.scenes()) == len(pkg.catalogue()) > 10)\n")
    p = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, cwd=ROOT,
                       timeout=300)
    assert p.returncode == 0, p.stderr
    assert p.stdout.split() == ["False", "True", "[]", "True", "True", "True"]
    with pytest.raises(AttributeError, match="nope"):
        ancf.nope  # noqa: B018
    assert {"run", "analytic", "sweep", "recommend", "scenes"} <= set(dir(ancf))


def test_the_docstring_examples_run():
    import ancf.api
    import ancf.result
    flags = doctest.ELLIPSIS | doctest.NORMALIZE_WHITESPACE
    res = [doctest.testmod(m, optionflags=flags) for m in (ancf.api, ancf.result)]
    assert [r.failed for r in res] == [0, 0]
    assert res[0].attempted >= 20 and res[1].attempted >= 8


GUIDE = ROOT / "docs" / "guide" / "python.md"


def _guide_python_blocks():
    """The ```python blocks of the Python API guide page, in order."""
    return re.findall(r"```python\n(.*?)```", GUIDE.read_text(), flags=re.S)


def test_the_guide_shows_the_api_in_several_blocks():
    assert len(_guide_python_blocks()) >= 4


@pytest.mark.slow
@pytest.mark.parametrize("index", range(len(_guide_python_blocks())))
def test_each_guide_python_example_runs_by_itself(index, tmp_path, monkeypatch, capsys):
    """Each block of docs/guide/python.md runs alone, in a fresh namespace (a newcomer
    pastes one block; a block that needs an earlier one's names fails here)."""
    monkeypatch.chdir(tmp_path)
    block = _guide_python_blocks()[index]
    exec(compile(block, f"{GUIDE.name} (block {index + 1})", "exec"), {})  # noqa: S102
    assert capsys.readouterr().out  # the examples print what they show
