"""Belt animations (issue 23, item 6): ``ancf.reports.animations.animate`` writes a GIF of a
belt drive's run that Pillow reads back with one frame per output step shown, the same
bytes on a rerun; the pulleys' angles are the speed law's integral (prescribed) and the
free coordinates (driven, idler, tensioner pulleys)."""
from __future__ import annotations

import numpy as np
import pytest

PIL = pytest.importorskip("PIL.Image")

import ancf  # noqa: E402
from ancf.reports.animations import animate, driver, last_revolution, pulley_angles  # noqa: E402
from ancf.scenes.frames import frames  # noqa: E402

#: a short run of the serpentine drive: the crank ramps from 0.05 s (to 40 rad/s at 0.3 s)
SHORT = {"file": "examples/serpentine.toml", "belt.damping_axial": 0, "run.t_end": 0.1,
         "run.steady_window": 0.05,
         "run.output_dt": 0.01}


@pytest.fixture(scope="module")
def serpentine():
    res = ancf.run("belt-drive", SHORT)
    assert res.converged, res.message
    return res


@pytest.mark.slow
def test_gif_reads_back_frame_per_step(serpentine, tmp_path):
    a = animate(serpentine, tmp_path / "serp.gif", max_frames=8)
    n = serpentine.times.size  # the crank turns 0.2 rad: every step is in the last revolution
    assert a.frames == 8 < n and a.t1 == pytest.approx(0.1)
    with PIL.open(a.path) as im:
        assert im.n_frames == a.frames and im.format == "GIF"
    assert a.size == a.path.stat().st_size < 2e6


@pytest.mark.slow
def test_rerun_writes_the_same_bytes(serpentine, tmp_path):
    one = animate(serpentine, tmp_path / "a.gif", max_frames=4).path.read_bytes()
    two = animate(serpentine, tmp_path / "b.gif", max_frames=4).path.read_bytes()
    assert one == two


def test_pulley_angles(serpentine):
    drive, res = serpentine.extra["drive"], serpentine.extra["result"]
    ang = pulley_angles(drive, res)
    t = np.asarray(res.t, float)
    # the crank's ramp 40 (t - 0.05)/0.25 rad/s integrated: 80 (t - 0.05)^2 rad
    crank = 80.0 * np.clip(t - 0.05, 0.0, None) ** 2
    assert np.allclose(ang[:, driver(drive)], crank, rtol=1e-9, atol=1e-12)
    free = np.flatnonzero(drive.rig.free >= 0)
    x = np.asarray(res.q, float)
    assert np.array_equal(ang[:, free], x[:, drive.n + drive.rig.free[free]])


def test_last_revolution_picks_the_final_turn():
    turn = np.linspace(0.0, 3 * np.pi, 31)  # 1.5 revolutions in 30 steps
    idx = last_revolution(turn, 100)
    assert idx[-1] == 30 and turn[idx[1]] >= turn[-1] - 2 * np.pi > turn[idx[0]]
    assert last_revolution(turn[:5], 100).tolist() == list(range(5))
    assert last_revolution(turn, 5).size == 5


def test_frames_of_a_drive_file_run(serpentine):
    fr = frames("belt-drive", serpentine.extra, per_element=4)
    assert len(fr) == serpentine.times.size
    assert fr[0].points.shape == (60 * 4, 3) and "axial_force_N" in fr[-1].point_data
