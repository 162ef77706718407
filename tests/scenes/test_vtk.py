"""ParaView output (issue 23, item 6): ``ancf run SCENE --vtk DIR`` writes DIR/SCENE.pvd and
one .vtu per output step through meshio; read back: node counts, cells, point data, the
.pvd listing every step at its time; a bad directory is one error line, exit 2, before
the run starts."""
from __future__ import annotations

import json
import os
import xml.etree.ElementTree as ET

import numpy as np
import pytest

meshio = pytest.importorskip("meshio")

import ancf  # noqa: E402
from ancf.scenes.base import Scene  # noqa: E402

PER_ELEMENT = 8


def _series(directory, scene):
    """[(time, mesh)] of the .pvd, every listed file read back."""
    root = ET.parse(directory / f"{scene}.pvd").getroot()
    sets = root.find("Collection").findall("DataSet")
    return [(float(d.get("timestep")), meshio.read(directory / d.get("file"))) for d in sets]


def test_static_beam_is_its_centreline(tmp_path, cli):
    n = 4
    rc, out, err = cli("run", "cantilever", "--set", f"n_elements={n}", "--json",
                   "--vtk", str(tmp_path / "out"))
    assert rc == 0 and err == ""
    res = json.loads(out)["results"]  # stdout stays the JSON alone
    series = _series(tmp_path / "out", "cantilever")
    assert len(series) == 1 and sorted(os.listdir(tmp_path / "out")) == [
        "cantilever.pvd", "cantilever_00000.vtu"]
    t, m = series[0]
    assert t == 0.0
    assert m.points.shape == (n * PER_ELEMENT + 1, 3)
    lines = m.cells_dict["line"]
    assert lines.shape == (n * PER_ELEMENT, 2) and lines.max() == n * PER_ELEMENT
    assert np.allclose(m.points[-1, :2], [res["tip_x"], res["tip_y"]], rtol=0, atol=1e-12)
    assert np.allclose(m.points[0], 0, atol=1e-12)  # clamped root
    d = m.point_data["displacement"]
    assert np.allclose(d[-1, :2], [res["tip_x"] - 2.0, res["tip_y"]], rtol=0, atol=1e-12)
    # the shape functions interpolate between the nodes: points lie between their neighbours
    x = m.points[:, 0]
    assert np.all(np.diff(x) > 0)


def test_without_json_the_cli_says_what_it_wrote(tmp_path, cli):
    rc, out, err = cli("run", "pendulum", "--set", "n_elements=2", "--set",
                   "t_end=0.02", "--set", "output_dt=0.01", "--vtk", str(tmp_path))
    assert rc == 0 and err == ""
    assert f"vtk: wrote {tmp_path / 'pendulum.pvd'} (3 steps)" in out.splitlines()


def test_dynamic_scene_writes_every_step(tmp_path):
    r = ancf.run("pendulum", n_elements=2, t_end=0.1, output_dt=0.025, vtk=tmp_path / "p")
    series = _series(tmp_path / "p", "pendulum")
    assert [t for t, _ in series] == r.times.tolist() and len(series) == 5
    assert len([f for f in os.listdir(tmp_path / "p") if f.endswith(".vtu")]) == 5
    for (t, m), tip_x, tip_y in zip(series, r.series["tip_x"], r.series["tip_y"]):
        assert m.points.shape == (2 * PER_ELEMENT + 1, 3)
        assert set(m.point_data) == {"displacement", "velocity"}
        assert np.allclose(m.points[-1, :2], [tip_x, tip_y], rtol=0, atol=1e-12)
    assert np.abs(series[0][1].point_data["velocity"]).max() == 0.0  # released from rest
    assert np.abs(series[-1][1].point_data["velocity"]).max() > 0.0


def test_plate_is_quads_on_its_nodes(tmp_path):
    n = 4
    r = ancf.run("plate-square", n_elements=n)
    pvd = r.write_vtk(tmp_path / "sq")
    assert pvd == tmp_path / "sq" / "plate-square.pvd"
    (_, m), = _series(tmp_path / "sq", "plate-square")
    assert m.points.shape == ((n + 1) ** 2, 3) and m.cells_dict["quad"].shape == (n * n, 4)
    centre = np.argmin(np.linalg.norm(m.points[:, :2] - 0.5, axis=1))
    assert m.point_data["displacement"][centre, 2] == pytest.approx(
        r.results["center_deflection_m"], rel=1e-12)


def test_belt2d_has_axial_force_speed_and_contact_pressure(tmp_path, cli):
    n = 20
    rc, out, err = cli("run", "belt2d", "--set", f"n_elements={n}", "--set",
                   "t_end=0.004", "--set", "output_dt=0.002", "--json",
                   "--vtk", str(tmp_path / "b"))
    assert rc == 0, err
    res = json.loads(out)["results"]
    series = _series(tmp_path / "b", "belt2d")
    assert [t for t, _ in series] == res["times"]
    for _, m in series:
        assert m.points.shape == (n * PER_ELEMENT, 3)
        assert m.cells_dict["line"].shape == (n * PER_ELEMENT, 2)  # closed loop
        for key in ("axial_force_N", "speed_m_s", "contact_pressure_N_m", "penetration_m"):
            assert m.point_data[key].shape == (n * PER_ELEMENT,)
    m = series[-1][1]
    # pre-tensioned belt: pulled on the whole; pressed where it wraps, free on the spans
    assert m.point_data["axial_force_N"].mean() > 0
    p = m.point_data["contact_pressure_N_m"]
    assert p.max() > 0 and (p == 0).any()
    assert ((p > 0) == (m.point_data["penetration_m"] > 0)).all()
    span_mean = np.mean([res["tension_tight_N"], res["tension_slack_N"]])
    assert np.median(m.point_data["axial_force_N"]) == pytest.approx(span_mean, rel=0.5)


def test_belt3d_has_axial_force_speed_and_contact_pressure(tmp_path):
    r = ancf.run("belt3d", model=2, t_end=0.002, output_dt=0.002, vtk=tmp_path / "b3")
    n = r.params["n_elements"]
    series = _series(tmp_path / "b3", "belt3d")
    assert [t for t, _ in series] == r.times.tolist()
    _, m = series[-1]
    stations = n * PER_ELEMENT // 2
    assert m.points.shape == (2 * stations, 3) and m.cells_dict["quad"].shape == (stations, 4)
    w = r.params["width"]  # point 2 station + edge: edge 0 at z = 0, edge 1 at z = w
    assert np.abs(m.points[0::2, 2]).max() < 0.1 * w  # the width contracts (Poisson)
    assert np.abs(m.points[1::2, 2] - w).max() < 0.1 * w
    for key in ("axial_force_N", "speed_m_s", "contact_pressure_N_m2", "penetration_m"):
        assert m.point_data[key].shape == (2 * stations,)
    f = m.point_data["axial_force_N"]
    assert f.min() > 0 and np.median(f) == pytest.approx(r.params["T_i"], rel=0.2)
    assert m.point_data["contact_pressure_N_m2"].max() > 0
    # the API's arrays of the same run: the belt's nodes, two per station of the ring
    assert r.reference_nodes.shape == r.nodes.shape == (2 * n, 3)
    assert r.node_history.shape == (len(r.times), 2 * n, 3)
    assert np.array_equal(r.node_history[-1], r.nodes)
    at_nodes = m.points.reshape(n, PER_ELEMENT // 2, 2, 3)[:, 0].reshape(2 * n, 3)
    assert np.allclose(at_nodes, r.nodes, rtol=0, atol=1e-12)


@pytest.mark.parametrize("how", ["file", "under-file", "unwritable", "uncreatable"])
def test_bad_vtk_path_is_one_error_line_before_the_run(tmp_path, monkeypatch, how, cli):
    f = tmp_path / "a-file"
    f.write_text("x")
    if how == "file":
        target = f
    elif how == "under-file":
        target = f / "sub" / "dir"
    elif how == "uncreatable":  # even root cannot make a directory in /proc
        if not os.path.isdir("/proc/self"):
            pytest.skip("no /proc")
        target = "/proc/ancf-vtk-test/out"
    else:
        if os.geteuid() == 0:
            pytest.skip("root writes everywhere")
        ro = tmp_path / "ro"
        ro.mkdir()
        ro.chmod(0o500)
        target = ro / "out"

    def boom(self, overrides=None):
        raise AssertionError("the run started")
    monkeypatch.setattr(Scene, "execute", boom)
    rc, out, err = cli("run", "cantilever", "--vtk", str(target), "--json")
    assert rc == 2 and out == ""
    assert err.count("\n") == 1 and err.startswith("error: --vtk ") and str(target) in err
    with pytest.raises(ancf.InputError, match="--vtk"):
        ancf.run("cantilever", vtk=target)


def test_bad_input_wins_over_the_directory(tmp_path, cli):
    rc, _, err = cli("run", "cantilever", "--set", "n_elements=0", "--vtk",
                 str(tmp_path / "never"))
    assert rc == 2 and err.startswith("error: n_elements") and not (tmp_path / "never").exists()


def test_vtk_is_only_on_run(tmp_path, cli):
    rc, _, err = cli("analytic", "reissner", "--vtk", str(tmp_path))  # argparse: unknown option
    assert rc == 2 and err.count("\n") == 1 and "--vtk" in err


@pytest.mark.slow
def test_run_with_vtk_loads_meshio_and_without_does_not(tmp_path):
    import subprocess
    import sys
    code = ("import sys\nfrom ancf import cli\nrc = cli.main(%r)\n"
            "print('meshio' in sys.modules, file=sys.stderr)\n")
    for argv, loaded in ((["run", "cantilever", "--set", "n_elements=2"], "False"),
                         (["run", "cantilever", "--set", "n_elements=2", "--vtk",
                           str(tmp_path / "v")], "True")):
        p = subprocess.run([sys.executable, "-c", code % (argv,)], capture_output=True,
                           text=True, timeout=300, cwd=os.path.dirname(os.path.dirname(os.path.dirname(__file__))))
        assert p.returncode == 0, p.stderr
        assert p.stderr.strip().splitlines()[-1] == loaded


@pytest.mark.parametrize("scene, kw", [
    ("simply-supported", {"element": "omar-shabana", "n_elements": 4}),
    ("cantilever", {"n_elements": 3}),
    ("beam3d-cantilever", {"element": "belt3d", "n_elements": 2, "load_angle_deg": 45}),
    ("beam3d-cantilever", {"n_elements": 2, "load_angle_deg": 45}),
    ("spinning-beam", {"element": "omar-shabana", "t_end": 0.1, "mean_window": 0.05}),
    ("belt-free-static", {"n_elements": 10}),
])
def test_the_sampled_centreline_passes_through_the_nodes(scene, kw):
    r = ancf.run(scene, **kw)
    states = r.node_history if r.times is not None else r.nodes[None]
    frames = r.frames()
    assert len(frames) == len(states)
    for fr, nodes in zip(frames, states):
        d = nodes.shape[1]
        assert np.allclose(fr.points[::PER_ELEMENT, :d], nodes, rtol=0, atol=1e-12)
        assert np.all(fr.points[:, d:] == 0)
    # between the nodes the element's own shape functions: cubic along the axis for the
    # elements with r_x (off the chord), linear for the others (on it)
    last = frames[-1].points  # deformed (a dynamic run starts straight)
    chord = 0.5 * (last[0] + last[PER_ELEMENT])
    cubic = kw.get("element") in ("omar-shabana", "belt3d") or scene == "belt-free-static"
    assert np.allclose(last[PER_ELEMENT // 2], chord, rtol=0, atol=1e-12) is not cubic
