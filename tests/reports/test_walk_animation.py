"""The GIF of the plate belt walking on a tilted, flanged pulley (ancf.reports.walk_animation):
examples/misaligned.toml cut to 0.03 s, every output step a frame, frame 0 at t = 0, every
pulley named, every text at least FONT_PT pt (MIN_FONT_PX px in the GIF)."""
import numpy as np
import pytest
from PIL import Image

from ancf.reports.animations import FONT_PT, MIN_FONT_PX
from ancf.reports.walk_animation import DPI, run_example, walk_animation


@pytest.fixture(scope="module")
def walk(tmp_path_factory):
    out, extra = run_example(overrides={"run.t_end": "0.03", "run.steady_window": "0.01"})
    path = tmp_path_factory.mktemp("walk") / "walk.gif"
    return out, extra, path, walk_animation(out, extra, path)


def test_walk_animation_has_a_frame_per_output_step(walk):
    out, _, path, a = walk
    times = np.array(out["results"]["times"])
    assert times[0] == 0.0 and a["frames"] == times.size and a["t1"] == times[-1]
    with Image.open(path) as im:
        assert im.n_frames == times.size
    assert a["size"] == path.stat().st_size


def test_walk_first_frame_at_rest(walk):
    out, _, _, a = walk
    times = np.array(out["results"]["times"])
    assert a["times"] == tuple(times) and a["times"][0] == 0.0


def test_walk_names_every_pulley(walk):
    _, extra, _, a = walk
    names = extra["drive"].rig.names
    assert len(names) == extra["drive"].radii.size
    assert set(names) <= {text for text, _ in a["texts"]}


def test_walk_fonts_meet_the_floor(walk):
    sizes = np.array([px for _, px in walk[3]["texts"]])
    assert sizes.size > 10
    assert sizes.min() >= MIN_FONT_PX and (sizes * 72 / DPI).min() >= FONT_PT
