"""The GIF of the plate belt walking on a tilted, flanged pulley (ancf.reports.walk_animation):
examples/misaligned.toml cut to 0.03 s, every output step a frame, frame 0 at t = 0."""
import numpy as np
from PIL import Image

from ancf.reports.walk_animation import run_example, walk_animation


def test_walk_animation_has_a_frame_per_output_step(tmp_path):
    out, extra = run_example(overrides={"run.t_end": "0.03", "run.steady_window": "0.01"})
    a = walk_animation(out, extra, tmp_path / "walk.gif")
    times = np.array(out["results"]["times"])
    assert times[0] == 0.0 and a["frames"] == times.size and a["t1"] == times[-1]
    with Image.open(tmp_path / "walk.gif") as im:
        assert im.n_frames == times.size
    assert a["size"] == (tmp_path / "walk.gif").stat().st_size
