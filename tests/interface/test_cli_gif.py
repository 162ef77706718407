"""``ancf run SCENE --gif PATH``: a belt drive's run written as an animated GIF (the
newcomer's path from a drive file of their own to its animation, issue 38), its path
checked before the run (one ``error:`` line, exit 2), nothing written for a run that did
not converge."""
import subprocess
import sys

from PIL import Image

from ancf.common.paths import REPO

DRIVE = REPO / "examples" / "three_pulleys.toml"


def _ancf(*args, cwd=None):
    return subprocess.run([sys.executable, "-m", "ancf.cli", *args], capture_output=True,
                          text=True, cwd=cwd)


def test_a_drive_file_run_writes_its_gif_from_t_0(tmp_path):
    gif = tmp_path / "anim" / "mine.gif"
    p = _ancf("run", "belt-drive", "--file", str(DRIVE), "--set", "run.t_end=0.1",
              "--set", "run.output_dt=0.01", "--set", "run.steady_window=0.01", "--gif", str(gif))
    assert p.returncode == 0, p.stderr
    line = [x for x in p.stdout.splitlines() if x.startswith("gif: wrote")]
    assert line and "t = 0.000-0.100 s" in line[0]
    with Image.open(gif) as im:
        assert im.format == "GIF" and im.n_frames == round(0.1 / 0.01) + 1


def test_json_stays_one_object_with_a_gif(tmp_path):
    import json
    p = _ancf("run", "belt-drive", "--file", str(DRIVE), "--set", "run.t_end=0.02",
              "--set", "run.output_dt=0.01", "--set", "run.steady_window=0.01", "--gif", str(tmp_path / "a.gif"), "--json")
    assert p.returncode == 0, p.stderr
    assert json.loads(p.stdout)["converged"] and (tmp_path / "a.gif").is_file()


def _one_error(p, *words):
    assert p.returncode == 2 and p.stdout == ""
    lines = p.stderr.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith("error: --gif")
    assert all(w in lines[0] for w in words), lines[0]


def test_bad_gif_paths_are_one_error_line_before_the_run(tmp_path):
    (tmp_path / "file").write_text("x")
    _one_error(_ancf("run", "cantilever", "--gif", str(tmp_path / "c.gif")),
               "cantilever has no animation", "belt2d, belt3d, belt-drive")
    _one_error(_ancf("run", "belt2d", "--gif", str(tmp_path / "c.png")), "ending in .gif")
    _one_error(_ancf("run", "belt2d", "--gif", str(tmp_path / "file" / "c.gif")),
               "is a file")
    (tmp_path / "d.gif").mkdir()
    _one_error(_ancf("run", "belt2d", "--gif", str(tmp_path / "d.gif")), "is a directory")


def test_the_api_writes_the_same_gif_and_refuses_a_scene_without_one(tmp_path):
    import pytest

    import ancf
    res = ancf.run("belt-drive", {"file": str(DRIVE), "run.t_end": 0.05, "run.output_dt": 0.01,
                                  "run.steady_window": 0.01})
    path = res.write_gif(tmp_path / "api.gif")
    with Image.open(path) as im:
        assert im.n_frames == round(0.05 / 0.01) + 1
    with pytest.raises(ancf.InputError, match="cantilever has no animation"):
        ancf.run("cantilever", n_elements=2).write_gif(tmp_path / "c.gif")
