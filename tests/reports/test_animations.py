"""Belt animations (issue 23, item 6; issue 38, item 5): ``ancf.reports.animations.animate``
writes a GIF of a belt drive's run that Pillow reads back with one frame per output step
shown, from rest (frame 0 at t = 0), the same bytes on a rerun; every pulley carries its
name from the drive, every text is at least ``FONT_PT`` pt (``MIN_FONT_PX`` px in the GIF);
the pulleys' angles are the speed law's integral (prescribed) and the free coordinates
(driven, idler, tensioner pulleys)."""
from __future__ import annotations

import numpy as np
import pytest

PIL = pytest.importorskip("PIL.Image")

import ancf  # noqa: E402
from ancf.reports.animations import (DPI, FONT_PT, MIN_FONT_PX, animate, driver,  # noqa: E402
                                     from_rest, pulley_angles)
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


@pytest.fixture(scope="module")
def serpentine_gif(serpentine, tmp_path_factory):
    return animate(serpentine, tmp_path_factory.mktemp("gif") / "serp.gif", max_frames=4)


@pytest.mark.slow
def test_gif_reads_back_frame_per_step(serpentine, tmp_path):
    a = animate(serpentine, tmp_path / "serp.gif", max_frames=8)
    n = serpentine.times.size
    assert a.frames == 8 < n and a.t1 == serpentine.times[-1]
    with PIL.open(a.path) as im:
        assert im.n_frames == a.frames and im.format == "GIF"
    assert a.size == a.path.stat().st_size < 2e6


@pytest.mark.slow
def test_rerun_writes_the_same_bytes(serpentine, tmp_path):
    one = animate(serpentine, tmp_path / "a.gif", max_frames=4).path.read_bytes()
    two = animate(serpentine, tmp_path / "b.gif", max_frames=4).path.read_bytes()
    assert one == two


def test_every_pulley_named(serpentine, serpentine_gif):
    """The drive file's names (crank, tensioner, alternator, idler, pump) are texts."""
    names = serpentine.extra["drive"].rig.names
    assert len(names) == serpentine.extra["drive"].radii.size
    assert set(names) <= {text for text, _ in serpentine_gif.texts}


def test_preset_pulleys_named(tmp_path):
    """The belt2d preset's pulleys (driver, driven) are named in its GIF too."""
    res = ancf.run("belt2d", {"t_end": 0.01})
    a = animate(res, tmp_path / "b2.gif", max_frames=2)
    assert set(res.extra["drive"].rig.names) <= {text for text, _ in a.texts}


def test_fonts_meet_the_floor(serpentine_gif):
    """Every text (title, stamp, labels, ticks, names) is >= FONT_PT pt at DPI, so at
    least MIN_FONT_PX px high in the GIF (no tolerance: the sizes are set, not measured)."""
    sizes = np.array([px for _, px in serpentine_gif.texts])
    assert sizes.size > 10 and FONT_PT * DPI / 72 >= MIN_FONT_PX
    assert sizes.min() >= MIN_FONT_PX and (sizes * 72 / DPI).min() >= FONT_PT
    stamps = [t for t, _ in serpentine_gif.texts if t.startswith("t = ")]
    assert stamps == [f"t = {serpentine_gif.t1:.3f} s, driver "
                      f"{serpentine_gif.driver_turn / (2 * np.pi):.2f} rev"]


def test_first_frame_at_rest(serpentine, serpentine_gif):
    """Frame 0 is the run's first output step, t = 0 (the run starts from rest); the frame
    times are the output times of the steps :func:`from_rest` selects."""
    t = np.asarray(serpentine.extra["result"].t, float)
    idx = from_rest(t.size, 4)
    assert serpentine_gif.times == tuple(t[idx]) and serpentine_gif.times[0] == t[0] == 0.0
    assert serpentine_gif.t0 == 0.0 and serpentine_gif.t1 == t[-1]
    assert np.all(np.diff(serpentine_gif.times) > 0)


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


def test_from_rest_keeps_both_ends():
    n = 31
    idx = from_rest(n, 5)
    assert idx[0] == 0 and idx[-1] == n - 1 and idx.size == 5
    assert np.all(np.diff(idx) > 0)
    assert from_rest(4, 100).tolist() == list(range(4))


def test_frames_of_a_drive_file_run(serpentine):
    fr = frames("belt-drive", serpentine.extra, per_element=4)
    assert len(fr) == serpentine.times.size
    assert fr[0].points.shape == (60 * 4, 3) and "axial_force_N" in fr[-1].point_data
