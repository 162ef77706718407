"""The plate belt walking on a tilted pulley and held by its flanges, as a GIF
(matplotlib's ``PillowWriter``, as :mod:`ancf.reports.animations`): a run of
``examples/misaligned.toml`` (the driven pulley's axis tilted by 1 deg, flanges 40 mm apart).

Each frame (an output step, frame 0 at t = 0, thinned evenly to at most ``max_frames``)
has three panels:

* the drive seen along the pulley axes (x-y, m), every pulley with its name, the belt's
  mid-line, the tilted pulley drawn in red;
* the tilted pulley's face developed flat near each flange (across: the axial coordinate
  s = (r - f) . p from the mid-face f, mm, :data:`ZOOM` mm inside each flange; up: the angle
  round the pulley from the entering tangent point, deg): the belt's edges where they lie
  on the pulley (the points of its edges within the rim's radius + 1 mm), the belt shaded
  inside them, the flanges beyond s = +-F / 2 in grey, so that the lateral walk, a
  millimetre or two on a 40 mm belt, shows at its true scale;
* the histories up to the frame of the pulley's ``lateral_position_m`` (mm) and its
  ``flange_force_N`` (N, right axis), the axes' limits their ranges from the first output
  step on (at t = 0 the belt laid on the aligned path cuts into the tilted face's flanges,
  tens of newtons for an instant, which would flatten the rest).

:func:`report_walk_animation` runs the example, writes ``figures/belt3d_walk.gif`` under the
report folder and returns the Markdown lines for the belt3d chapter (a link and a caption
stating the run and what the frames show; in the reduced configuration a line saying it is
skipped).
"""
from __future__ import annotations

from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from matplotlib.animation import PillowWriter  # noqa: E402
from matplotlib.ticker import MaxNLocator  # noqa: E402

from ancf.belts import post3d  # noqa: E402
from ancf.belts.flange3d import PULLEY, HALF  # noqa: E402
from ancf.common.paths import REPO  # noqa: E402
from ancf.reports.animations import FONT_PT, FONTS, figure_texts  # noqa: E402
from ancf.reports.output import progress, settings  # noqa: E402

EXAMPLE = REPO / "examples" / "misaligned.toml"
FPS, DPI, MAX_FRAMES = 10, 80, 61  # frames/s, px per inch (a 12 in figure: 960 px)
ZOOM = 4.5  # mm of the face shown inside each flange
ON_RIM = 1e-3  # m: an edge point within the rim's radius + ON_RIM is drawn on the face
PER_ELEMENT = 8  # edge points per plate


def _tilted(drive) -> int:
    """The pulley whose axis is turned most from e_z."""
    return int(np.argmin(drive.axes[:, 2]))


def _face(drive, desc, k: int, x, v, t: float) -> list:
    """The belt's two edges (y = 0, y = w) on pulley k's face developed flat: per edge,
    (s mm, angle deg from the entering tangent point in the belt's running direction),
    points on the rim only (module docstring)."""
    o = drive.moved(x, v, t)[0][k]
    p, R = drive.axes[k], drive.radii[k]
    f = np.array([o[0], o[1], 0.5 * drive.spec.width])
    T = desc.path.spans[k - 1].end
    side = desc.pulleys[k].side
    a0 = np.arctan2(T[1] - o[1], T[0] - o[0])
    out = []
    for y in (0.0, drive.spec.width):
        r = post3d.line_sample(drive, x, v, y=y, npts=PER_ELEMENT)["r"].reshape(-1, 3)
        a = r - o
        N = a - np.outer(a @ p, p)
        on = np.linalg.norm(N, axis=1) < R + ON_RIM
        ang = np.degrees(np.mod(side * (np.arctan2(a[:, 1], a[:, 0]) - a0) + 1.0, 2 * np.pi)
                         - 1.0)
        order = np.argsort(ang[on])
        out.append((1e3 * ((r - f) @ p)[on][order], ang[on][order]))
    return out


def walk_animation(out: dict, extra: dict, path, *, max_frames: int = MAX_FRAMES,
                   fps: int = FPS, dpi: int = DPI) -> dict:
    """Write the GIF of a belt-drive run with a tilted, flanged pulley to ``path``:
    ``out`` the scene's output (its results), ``extra`` its ``SceneResult.extra``; returns
    {"frames", "t1" s, "size" bytes, "lateral_mm" (first, last), "flange_N" last, "times"
    (every frame's, s), "texts" (the figure's visible texts and their sizes in the GIF, px)}.
    Every text is at least :data:`ancf.reports.animations.FONT_PT` pt."""
    with plt.rc_context(FONTS):
        return _walk_animation(out, extra, Path(path), max_frames, fps, dpi)


def _walk_animation(out, extra, path, max_frames, fps, dpi) -> dict:
    drive, res, desc = extra["drive"], extra["result"], extra["description"]
    k = _tilted(drive)
    name = drive.rig.names[k]
    results = out["results"]
    t = np.asarray(results["times"], float)
    lat = 1e3 * np.array(results["pulleys"][k]["lateral_position_m"], float)
    flange = np.array(results["pulleys"][k]["flange_force_N"], float)
    idx = np.unique(np.round(np.linspace(0, t.size - 1, min(max_frames, t.size))).astype(int))
    rows = drive.flanges.table
    half = 1e3 * float(rows[rows[:, PULLEY] == k, HALF][0]) if rows.size else np.nan
    fig = plt.figure(figsize=(12.0, 4.6))
    grid = fig.add_gridspec(1, 3, width_ratios=(1.2, 1.1, 1.25), wspace=0.42, left=0.075,
                            right=0.925, top=0.84, bottom=0.2)
    top, hist = fig.add_subplot(grid[0, 0]), fig.add_subplot(grid[0, 2])
    faces = [fig.add_subplot(g) for g in grid[0, 1].subgridspec(1, 2, wspace=0.08)]
    _draw_layout(top, drive, desc, k)
    belt_top, = top.plot([], [], color="C0", lw=1.5)
    edges = [ax.plot([], [], color="C0", lw=2, zorder=3)[0] for ax in faces]
    for ax, sign in zip(faces, (-1, 1)):
        wall = sign * half
        ax.axvspan(wall, wall + sign * 10, color="0.3")
        ax.text(wall + sign * 0.9, 185, "flange", rotation=90, ha="center", va="top",
                color="w", fontsize=FONT_PT)
        ax.set_xlim(*sorted((wall - sign * ZOOM, wall + sign * 1.5)))
        ax.set_xticks(sorted((wall, wall - sign * 2)))  # the flange and 2 mm inside it
        ax.set_ylim(-10, 200)
        ax.tick_params(labelsize=FONT_PT)
    faces[1].tick_params(labelleft=False)
    faces[0].set_ylabel("round the pulley from entry [deg]")
    fig.text(0.5 * (faces[0].get_position().x0 + faces[1].get_position().x1), 0.09,
             "along the axis from mid-face, s [mm]", ha="center", fontsize=FONT_PT)
    faces[0].set_title(f"belt's edges on '{name}' near its flanges", fontsize=FONT_PT, loc="left")
    bands = []
    lat_line, = hist.plot([], [], color="C0", label="lateral position [mm]")
    hist.set(xlim=(0, t[-1]), ylim=_limits(lat[1:]), xlabel="t [s]", ylabel="lateral position [mm]")
    hist.xaxis.set_major_locator(MaxNLocator(4))
    hist.set_title(f"'{name}': walk and flange force", fontsize=FONT_PT)
    right = hist.twinx()
    force_line, = right.plot([], [], color="C3", label="flange force [N]")
    right.set(ylim=_limits(flange[1:]), ylabel="flange force on the belt [N]")
    hist.legend(handles=[lat_line, force_line], fontsize=FONT_PT, loc="upper right")
    for ax in (top, hist, right):
        ax.tick_params(labelsize=FONT_PT)
    tilt = desc.pulleys[k].params["axis_tilt_deg"]
    fig.suptitle(f"Plate belt walking on the tilted pulley '{name}' (axis tilted {tilt:g} deg), "
                 f"held by its flanges {2 * half:.0f} mm apart", fontsize=FONT_PT + 1)
    stamp = fig.text(0.06, 0.015, "", fontsize=FONT_PT, family="monospace")
    path.parent.mkdir(parents=True, exist_ok=True)
    writer = PillowWriter(fps=fps)
    x, v = np.asarray(res.q), np.asarray(res.v)
    with writer.saving(fig, str(path), dpi):
        for i in idx:
            r = post3d.line_sample(drive, x[i], v[i], y=0.5 * drive.spec.width,
                                   npts=PER_ELEMENT)["r"].reshape(-1, 3)
            belt_top.set_data(np.append(r[:, 0], r[0, 0]), np.append(r[:, 1], r[0, 1]))
            lo, hi = _face(drive, desc, k, x[i], v[i], float(t[i]))
            for band in bands:
                band.remove()
            bands = []
            for ax, line, (s, ang), inner in zip(faces, edges, (lo, hi), (half, -half)):
                line.set_data(s, ang)
                bands.append(ax.fill_betweenx(ang, s, np.full_like(s, inner), color="C0",
                                              alpha=0.35, lw=0))
            lat_line.set_data(t[:i + 1], lat[:i + 1])
            force_line.set_data(t[:i + 1], flange[:i + 1])
            stamp.set_text(f"t = {t[i]:.3f} s   lateral position {lat[i]:+.2f} mm   "
                           f"flange force {flange[i]:+.2f} N")
            writer.grab_frame()
    texts = figure_texts(fig, dpi)
    plt.close(fig)
    return {"frames": int(idx.size), "t1": float(t[idx[-1]]), "size": path.stat().st_size,
            "lateral_mm": (float(lat[1]), float(lat[-1])), "flange_N": float(flange[-1]),
            "times": tuple(float(x) for x in t[idx]), "texts": tuple(texts)}


def _limits(y) -> tuple:
    y = np.asarray(y, float)
    y = y[np.isfinite(y)]
    lo, hi = min(y.min(), 0.0), max(y.max(), 0.0)
    pad = 0.08 * (hi - lo or 1.0)
    return lo - pad, hi + pad


def _draw_layout(ax, drive, desc, k: int) -> None:
    """The drive along the pulley axes: rims and names (pulley k in red)."""
    for j, (q, R) in enumerate(zip(desc.pulleys, drive.radii)):
        a = np.linspace(0, 2 * np.pi, 90)
        c = q.centre
        colour = "C3" if j == k else "0.35"
        ax.plot(c[0] + R * np.cos(a), c[1] + R * np.sin(a), color=colour, lw=1.2)
        ax.text(c[0], c[1], q.name, ha="center", va="center", fontsize=FONT_PT, color=colour)
    ax.set(aspect="equal", xlabel="x [m]", ylabel="y [m]")
    ax.set_title("drive seen along the axes", fontsize=FONT_PT)
    ax.margins(0.08)


def run_example(path=EXAMPLE, overrides: dict | None = None) -> tuple:
    """(out, extra) of ``ancf run belt-drive --file PATH`` (with ``overrides``)."""
    from ancf.scenes import SCENES
    out, res = SCENES["belt-drive"].execute({"file": str(path), **(overrides or {})})
    if not out["converged"]:
        raise RuntimeError(f"walk animation: the run did not converge ({out['message']})")
    return out, res.extra


def report_walk_animation(root: Path | None = None, folder: str = "figures") -> list[str]:
    """Run ``examples/misaligned.toml``, write ``FOLDER/belt3d_walk.gif`` under the report
    folder and return the belt3d chapter's Markdown lines (heading, link, caption)."""
    if root is None and settings().quick:
        return ["## The belt walking on a tilted pulley\n",
                "Reduced configuration: the walk animation's run is skipped.\n"]
    progress("walk animation: examples/misaligned.toml")
    out, extra = run_example()
    root = Path(root) if root is not None else settings().root
    a = walk_animation(out, extra, root / folder / "belt3d_walk.gif")
    return ["## The belt walking on a tilted pulley\n",
            f"![the plate belt walking and held by flanges]({folder}/belt3d_walk.gif)\n",
            "*Animation: `ancf run belt-drive --file examples/misaligned.toml` (the driven "
            "pulley's axis tilted by 1 deg, flanges 40 mm apart on it; driver at 40 rad/s, "
            f"v = 2 m/s). {a['frames']} frames from t = 0 to {a['t1']:.3f} s: left, the drive "
            "along the pulley axes; middle, the belt's edges (shaded inside) on the tilted "
            "pulley's face developed flat, near each flange (grey); right, the belt's mean "
            "lateral position on that pulley and the flanges' force on it. The lateral "
            f"position goes from {a['lateral_mm'][0]:+.2f} mm (t = one output step) to "
            f"{a['lateral_mm'][1]:+.2f} mm, the flanges pushing {a['flange_N']:.2f} N at the "
            f"end. {a['size'] / 1e6:.2f} MB, {FPS} frames/s.*\n"]


if __name__ == "__main__":  # python -m ancf.reports.walk_animation [OUT.gif]
    import sys
    o, e = run_example()
    print(walk_animation(o, e, sys.argv[1] if len(sys.argv) > 1 else "belt3d_walk.gif"))
