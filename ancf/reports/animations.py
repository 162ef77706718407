"""Animations of the belt drives: GIFs (matplotlib's ``PillowWriter``) of a finished run
of ``belt2d``, ``belt3d`` or ``belt-drive`` from rest (frame 0 at t = 0) to its end.

:func:`animate` takes a run (an ``ancf.run`` :class:`~ancf.result.Result`, or the scene's name
and its ``SceneResult.extra``) and writes one GIF: the belt coloured by its axial force
(N; the belt points of :func:`ancf.scenes.frames.frames`, the same as ``--vtk`` writes;
one colour scale for the whole animation), every pulley with a spoke so that its rotation
shows and its name from the drive (``rig.names``: the preset's or the drive file's) next
to it, a tensioner's arm, and the time stamp (the frame's output time, s, and the
driver's turn, rev).  The frames are the output steps from the first (t = 0, the run
starts from rest) to the last, thinned evenly to at most ``max_frames``
(:func:`from_rest`); the colour scale spans the 1st to the 99th percentile of the axial
force over them (the contact entries' spikes beyond).  Every text (title, time stamp,
axis and colour-bar labels, tick labels, pulley names) is at least :data:`FONT_PT` pt,
saved at :data:`DPI` pixels per inch: at least ``FONT_PT * DPI / 72`` px high in the GIF.

:func:`report_animations` runs the report's three cases (:data:`CASES`; the 3D belt as a
short run of one driver revolution from rest) and writes ``reports/animations/*.gif``;
its Markdown lines (a link and a caption stating the run's settings) are what the belt
pages show.  Pillow writes the same bytes for the same frames, so a rerun on one
machine reproduces the files; see ``tests/reports/test_animations.py``.
"""
from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from matplotlib.animation import PillowWriter  # noqa: E402
from matplotlib.collections import LineCollection  # noqa: E402

from ancf.belts.arm2d import PIVOT_X, PIVOT_Y, PULLEY  # noqa: E402
from ancf.common.paths import REPORTS  # noqa: E402
from ancf.reports.output import progress, settings  # noqa: E402
from ancf.scenes.frames import frames as frames_of  # noqa: E402

FPS = 15            # frames per second of the GIF
DPI = 80            # pixels per inch (a 6.4 in wide figure: 512 px)
FONT_PT = 11        # every text's size, pt (the floor; titles one larger): 12.2 px at DPI
MIN_FONT_PX = 11    # the floor in the GIF's pixels: FONT_PT * dpi / 72 must reach it
MAX_FRAMES = 80
SUBSTEPS = 16       # trapezoid sub-intervals per output step of the driver's angle
CMAP = "viridis"
CLIP = (1, 99)      # percentiles of the axial force over the frames: the colour scale's ends
#: matplotlib's sizes inside an animation (pt): none below FONT_PT
FONTS = {"font.size": FONT_PT, "axes.titlesize": FONT_PT + 1, "axes.labelsize": FONT_PT,
         "xtick.labelsize": FONT_PT, "ytick.labelsize": FONT_PT, "legend.fontsize": FONT_PT,
         "figure.titlesize": FONT_PT + 1}


@dataclass
class Animation:
    """What :func:`animate` wrote: ``path``, the number of ``frames``, the time span
    ``t0``-``t1`` (s), the driver's turn over it (rad), the file size (bytes), every
    frame's time ``times`` (s, as its stamp says) and the figure's ``texts`` (pairs of a
    visible text and its size in the GIF, px, read from the figure after the last frame)."""

    path: Path
    frames: int
    t0: float
    t1: float
    driver_turn: float
    size: int
    times: tuple = ()
    texts: tuple = ()


def _drive(extra: dict):
    if "drive" not in extra or "result" not in extra:
        raise ValueError("an animation needs a belt drive's run (belt2d, belt3d or belt-drive)")
    return extra["drive"], extra["result"]


def pulley_angles(drive, res) -> np.ndarray:
    """Every pulley's rotation (nt, np) at the output times, rad, counter-clockwise about
    the pulley axis: a free pulley's coordinate, a prescribed one's speed law integrated
    from t = 0 (trapezoid, :data:`SUBSTEPS` per output step)."""
    t = np.asarray(res.t, float)
    npul = drive.radii.size
    knots = np.concatenate([[0.0], t]) if t[0] > 0 else t
    fine = np.concatenate([np.linspace(a, b, SUBSTEPS, endpoint=False)
                           for a, b in zip(knots[:-1], knots[1:])] + [knots[-1:]])
    w = drive.laws(fine)[:npul]
    turned = np.concatenate([np.zeros((npul, 1)),
                             np.cumsum(0.5 * (w[:, 1:] + w[:, :-1]) * np.diff(fine), axis=1)], 1)
    out = turned[:, np.searchsorted(fine, t)].T
    free = drive.rig.free
    x = np.asarray(res.q, float)
    for p in np.flatnonzero(free >= 0):
        out[:, p] = x[:, drive.n + free[p]]
    return out


def pulley_centres(drive, x, v, t: float) -> np.ndarray:
    """The pulley centres (np, 3) at a state, m: the 3D driver moved by its shift, a
    tensioner's on its arm."""
    if hasattr(drive, "pulley_centres"):
        return np.asarray(drive.pulley_centres(t), float)
    o = drive.moved(x, v)[0]
    return np.concatenate([o, np.zeros((o.shape[0], 1))], 1)


def driver(drive) -> int:
    """The driver: the first pulley turned by its law."""
    return int(np.flatnonzero(drive.rig.free < 0)[0])


def from_rest(n: int, max_frames: int) -> np.ndarray:
    """Indices of the output steps shown: all ``n`` of them from the first (t = 0) to the
    last, thinned evenly to at most ``max_frames`` (both ends kept)."""
    idx = np.arange(n)
    if n > max_frames:
        idx = np.unique(np.round(np.linspace(0, n - 1, max_frames)).astype(int))
    return idx


def figure_texts(fig, dpi: float) -> list:
    """Every visible, non-empty text of ``fig``: (text, size in px at ``dpi``)."""
    from matplotlib.text import Text
    return [(t.get_text(), t.get_fontsize() * dpi / 72.0) for t in fig.findobj(Text)
            if t.get_visible() and t.get_text().strip()]


# --- drawing ---------------------------------------------------------------------------

def _circle(c, R, z=None, n=72):
    a = np.linspace(0, 2 * np.pi, n)
    pts = [c[0] + R * np.cos(a), c[1] + R * np.sin(a)]
    return pts if z is None else pts + [np.full(n, z)]


def _segments(points):
    """Closed polyline -> (m, 2, dim) segments."""
    return np.stack([points, np.roll(points, -1, axis=0)], 1)


def _outward(centres) -> np.ndarray:
    """Unit vectors (np, 2) from the pulley centres' mean to each centre (+y for one there):
    the side of each pulley its name goes on."""
    u = centres[:, :2] - centres[:, :2].mean(axis=0)
    n = np.linalg.norm(u, axis=1)
    far = n > 1e-9 * max(n.max(), 1e-300)
    u[far] /= n[far, None]
    u[~far] = (0.0, 1.0)
    return u


def _names(ax, drive, centres, gap, three=False) -> tuple:
    """Every pulley's name (``drive.rig.names``) as a text just outside its rim, ``gap`` m
    beyond it on the side away from the other pulleys, aligned away from the rim:
    (texts, the sides (np, 2), gap)."""
    u = _outward(np.asarray(centres, float))
    texts = []
    for name, v in zip(drive.rig.names, u):
        ha = "left" if v[0] > 0.38 else "right" if v[0] < -0.38 else "center"
        va = "bottom" if v[1] > 0.38 else "top" if v[1] < -0.38 else "center"
        kw = dict(ha=ha, va=va, fontsize=FONT_PT, color="0.1", zorder=6,
                  bbox=dict(boxstyle="round,pad=0.15", fc="white", ec="none", alpha=0.75))
        texts.append(ax.text(0, 0, 0, str(name), **kw) if three else ax.text(0, 0, str(name), **kw))
    return texts, u, gap


def _place_names(names, centres, radii, z=None):
    """Move the name texts to their pulleys' centres (np, 2 or 3), m."""
    texts, u, gap = names
    for k, (text, c, R) in enumerate(zip(texts, centres, radii)):
        xy = np.asarray(c[:2], float) + (R + gap) * u[k]
        if z is None:
            text.set_position(xy)
        else:
            text.set_position_3d((xy[0], xy[1], c[2] + z))


class _Scene2D:
    """Artists of a planar drive: the belt (LineCollection), pulley rims, spokes, names, arms."""

    def __init__(self, ax, drive, norm, extent, centres):
        self.ax, self.drive = ax, drive
        self.belt = LineCollection([], cmap=CMAP, norm=norm, lw=2.5, zorder=3)
        ax.add_collection(self.belt)
        npul = drive.radii.size
        self.rims = [ax.plot([], [], color="0.35", lw=1.0, zorder=2)[0] for _ in range(npul)]
        self.spokes = [ax.plot([], [], color="C3", lw=2.0, marker="o", ms=2.5, markevery=[0],
                               zorder=4)[0] for _ in range(npul)]
        self.arms = [ax.plot([], [], color="0.2", lw=2.0, zorder=1)[0]
                     for _ in range(drive.rig.arms.shape[0])]
        (x0, x1), (y0, y1) = extent
        self.names = _names(ax, drive, centres, 0.03 * max(x1 - x0, y1 - y0))
        _place_names(self.names, centres, drive.radii)
        ax.set(xlim=(x0, x1), ylim=(y0, y1), aspect="equal", xlabel="x [m]", ylabel="y [m]")

    def fit(self, fig):
        """Widen the axes' limits until every name lies inside them (draws ``fig``)."""
        ax = self.ax
        for _ in range(3):
            fig.canvas.draw()
            inv = ax.transData.inverted()
            pts = np.concatenate([inv.transform(t.get_window_extent().get_points())
                                  for t in self.names[0]])
            (x0, x1), (y0, y1) = ax.get_xlim(), ax.get_ylim()
            pad = 0.02 * max(x1 - x0, y1 - y0)
            lo = np.minimum([x0, y0], pts.min(axis=0) - pad)
            hi = np.maximum([x1, y1], pts.max(axis=0) + pad)
            if np.allclose([lo, hi], [[x0, y0], [x1, y1]]):
                return
            ax.set(xlim=(lo[0], hi[0]), ylim=(lo[1], hi[1]))

    def update(self, frame, centres, angles):
        self.belt.set_segments(_segments(frame.points[:, :2]))
        self.belt.set_array(_segment_values(frame.point_data["axial_force_N"]))
        for p, (c, R, th) in enumerate(zip(centres, self.drive.radii, angles)):
            self.rims[p].set_data(*_circle(c, R))
            self.spokes[p].set_data([c[0], c[0] + R * np.cos(th)], [c[1], c[1] + R * np.sin(th)])
        _place_names(self.names, centres, self.drive.radii)
        for a, row in enumerate(self.drive.rig.arms):
            c = centres[int(row[PULLEY])]
            self.arms[a].set_data([row[PIVOT_X], c[0]], [row[PIVOT_Y], c[1]])


class _Scene3D:
    """Artists of the 3D belt: the mid-surface quads, both faces of every pulley, names."""

    def __init__(self, ax, drive, norm, extent, width, centres):
        from matplotlib.ticker import MaxNLocator
        from mpl_toolkits.mplot3d.art3d import Poly3DCollection
        self.ax, self.drive, self.norm, self.width = ax, drive, norm, width
        self.cmap = plt.get_cmap(CMAP)
        self.belt = Poly3DCollection([], edgecolor="none", zorder=3)
        ax.add_collection3d(self.belt)
        npul = drive.radii.size
        self.rims = [[ax.plot([], [], [], color="0.35", lw=0.8)[0] for _ in range(2)]
                     for _ in range(npul)]
        self.spokes = [ax.plot([], [], [], color="C3", lw=1.5)[0] for _ in range(npul)]
        (x0, x1), (y0, y1) = extent
        self.names = _names(ax, drive, centres, 0.03 * max(x1 - x0, y1 - y0), three=True)
        _place_names(self.names, centres, drive.radii, z=width)
        ax.set(xlim=(x0, x1), ylim=(y0, y1), zlim=(-0.5 * width, 1.5 * width),
               xlabel="x [m]", ylabel="y [m]", zticks=[0.0, width])
        ax.set_box_aspect((x1 - x0, y1 - y0, 2 * width))
        ax.view_init(elev=28, azim=-62)
        ax.xaxis.set_major_locator(MaxNLocator(4))
        ax.yaxis.set_major_locator(MaxNLocator(3))
        ax.tick_params(labelsize=FONT_PT)
        ax.xaxis.labelpad = ax.yaxis.labelpad = 12  # clear of the FONT_PT tick labels

    def fit(self, fig):
        """Nothing to widen: the 3D axes' margins hold the names."""

    def update(self, frame, centres, angles):
        quads = frame.cells[0][1]
        self.belt.set_verts(frame.points[quads])
        force = frame.point_data["axial_force_N"][quads].mean(axis=1)
        self.belt.set_facecolor(self.cmap(self.norm(force)))
        for p, (c, R, th) in enumerate(zip(centres, self.drive.radii, angles)):
            for k, z in enumerate((0.0, self.width)):
                x, y, zz = _circle(c, R, c[2] + z)
                self.rims[p][k].set_data_3d(x, y, zz)
            tip = c[:2] + R * np.array([np.cos(th), np.sin(th)])
            self.spokes[p].set_data_3d([c[0], tip[0]], [c[1], tip[1]], [c[2] + self.width] * 2)
        _place_names(self.names, centres, self.drive.radii, z=self.width)


def _segment_values(values):
    """Point values of a closed polyline -> one value per segment (the mean of its ends)."""
    return 0.5 * (values + np.roll(values, -1))


def _extent(points, centres, radii, margin=0.1):
    """(x range, y range) holding the belt and every pulley, with a margin."""
    lo = np.minimum(points.min(axis=0)[:2], (centres[:, :2] - radii[:, None]).min(axis=0))
    hi = np.maximum(points.max(axis=0)[:2], (centres[:, :2] + radii[:, None]).max(axis=0))
    pad = margin * (hi - lo).max()
    return (lo[0] - pad, hi[0] + pad), (lo[1] - pad, hi[1] + pad)


@dataclass
class _Plan:
    """The frames :func:`animate` shows: output-step indices ``idx``, their belt frames
    ``shown``, pulley centres (m) and angles (rad, every step), the output times ``t`` (s)."""

    drive: object
    idx: np.ndarray
    shown: list
    centres: list
    angles: np.ndarray
    t: np.ndarray


def _plan(scene, extra, max_frames, per_element) -> _Plan:
    drive, res = _drive(extra)
    t = np.asarray(res.t, float)
    idx = from_rest(t.size, max_frames)
    allframes = frames_of(scene, extra, per_element)
    x, v = np.asarray(res.q), np.asarray(res.v)
    return _Plan(drive, idx, [allframes[i] for i in idx],
                 [pulley_centres(drive, x[i], v[i], float(t[i])) for i in idx],
                 pulley_angles(drive, res), t)


def _figure(plan: _Plan, title: str):
    """The figure of an animation, laid out once: (fig, scene artists, time stamp)."""
    drive, shown, centres = plan.drive, plan.shown, plan.centres
    forces = np.concatenate([f.point_data["axial_force_N"] for f in shown])
    norm = matplotlib.colors.Normalize(*np.percentile(forces, CLIP))
    extent = _extent(np.concatenate([f.points for f in shown]), np.concatenate(centres),
                     np.tile(drive.radii, len(centres)))
    three = hasattr(drive, "axes")
    (x0, x1), (y0, y1) = extent
    height = 4.8 if three else float(np.clip(4.4 * (y1 - y0) / (x1 - x0) + 1.3, 2.6, 6.0))
    fig = plt.figure(figsize=(6.4, height), layout="constrained")
    ax = fig.add_subplot(projection="3d" if three else None)
    art = _Scene3D(ax, drive, norm, extent, drive.spec.width, centres[0]) if three else \
        _Scene2D(ax, drive, norm, extent, centres[0])
    fig.colorbar(matplotlib.cm.ScalarMappable(norm=norm, cmap=CMAP), ax=ax,
                 shrink=0.75 if three else 0.9,
                 label="axial force [N]", extend="both")
    fig.suptitle(title, fontsize=FONT_PT + 1, x=0.02, ha="left")
    stamp = ax.set_title(_stamp(0.0, 0.0), loc="left", family="monospace", fontsize=FONT_PT)
    art.fit(fig)
    fig.canvas.draw()
    fig.set_layout_engine("none")  # laid out once: every frame the same axes
    return fig, art, stamp


def _stamp(t: float, turn: float) -> str:
    """The time stamp of a frame at ``t`` s, the driver turned ``turn`` rad."""
    return f"t = {t:.3f} s, driver {turn / (2 * np.pi):.2f} rev"


def animate(run, path, extra: dict | None = None, *, title: str = "", max_frames: int = MAX_FRAMES,
            fps: int = FPS, dpi: int = DPI, per_element: int = 8) -> Animation:
    """Write the GIF of a belt drive's run to ``path``: ``run`` an ``ancf.run`` result (or
    the scene's name, with its ``SceneResult.extra`` as ``extra``); see the module doc."""
    scene, extra = (run, extra) if isinstance(run, str) else (run.scene, run.extra)
    with plt.rc_context(FONTS):
        plan = _plan(scene, extra, max_frames, per_element)
        fig, art, stamp = _figure(plan, title or scene)
        path = Path(path)
        path.parent.mkdir(parents=True, exist_ok=True)
        writer = PillowWriter(fps=fps)
        d, t = driver(plan.drive), plan.t
        with writer.saving(fig, str(path), dpi):
            for f, i, c in zip(plan.shown, plan.idx, plan.centres):
                art.update(f, c, plan.angles[i])
                stamp.set_text(_stamp(t[i], plan.angles[i, d]))
                writer.grab_frame()
        texts = figure_texts(fig, dpi)
        plt.close(fig)
    idx = plan.idx
    turn = plan.angles[idx[-1], d] - plan.angles[idx[0], d]
    return Animation(path, len(idx), float(t[idx[0]]), float(t[idx[-1]]), float(turn),
                     path.stat().st_size, tuple(float(x) for x in t[idx]), tuple(texts))


# --- the report's animations ---------------------------------------------------------------

#: name -> (scene, overrides, what the caption says of the run)
CASES = {
    "belt2d": ("belt2d", {},
               "`ancf run belt2d` with its defaults (the thesis drive, Table 3.1: driver ramp "
               "to 12 rad/s over 0.05–0.6 s, t_end = 1 s, dt = 2.5e-4 s, output every 5 ms)"),
    "belt3d": ("belt3d", {"t_end": 0.21, "output_dt": 0.0015},
               "`ancf run belt3d --set t_end=0.21 --set output_dt=0.0015` (Model 2 of Table 4.1, "
               "20 plates, dt = 1e-4 s: a short run from rest; the driver's ramp to 500 rad/s "
               "over 0.05–1 s has turned it once by 0.21 s, so this is its first revolution, "
               "not the steady state of the 1.2 s run)"),
    "serpentine": ("belt-drive", {"file": "examples/serpentine.toml", "belt.damping_axial": 0,
                                  "run.output_dt": 0.002},
                   "`ancf run belt-drive --file examples/serpentine.toml --set "
                   "belt.damping_axial=0 --set run.output_dt=0.002` (five pulleys, crank at "
                   "40 rad/s, a spring-loaded tensioner; t_end = 1 s, dt = 1e-4 s)"),
}


def _run_case(name: str):
    from ancf.scenes import SCENES
    scene, overrides, _ = CASES[name]
    out, res = SCENES[scene].execute(dict(overrides))
    if not out["converged"]:
        raise RuntimeError(f"animation {name}: the run did not converge ({out['message']})")
    return scene, res.extra


def report_animation(name: str, root: Path | None = None) -> list[str]:
    """Run the case ``name`` of :data:`CASES`, write ``animations/NAME.gif`` under the
    report folder and return the Markdown lines (heading, link and caption) of a belt page
    (in the reduced configuration, ``--quick``, a line saying it is skipped)."""
    if root is None and settings().quick:
        return ["## Animation\n", "Reduced configuration: the animation's run is skipped.\n"]
    progress(f"animation {name}: {CASES[name][0]} run")
    scene, extra = _run_case(name)
    root = Path(root) if root is not None else settings().root
    a = animate(scene, root / "animations" / f"{name}.gif", extra, title=_title(name))
    return ["## Animation\n", f"![{name} animation](animations/{name}.gif)\n",
            f"*Animation: {CASES[name][2]}. Shown: {a.frames} output steps from t = {a.t0:.3f} s "
            f"to {a.t1:.3f} s, the driver turning {a.driver_turn / (2 * np.pi):.2f} revolutions; "
            "the belt coloured by its axial force (one scale for the whole animation, from the 1st "
            "to the 99th percentile of its values), a red spoke on every pulley"
            + (", the tensioner's arm in black" if "belt-drive" == CASES[name][0] else "")
            + f". {a.size / 1e6:.2f} MB, {FPS} frames/s.*\n"]


def _title(name: str) -> str:
    return {"belt2d": "belt2d: the thesis two-pulley drive",
            "belt3d": "belt3d Model 2: thin-plate belt, first revolution",
            "serpentine": "belt-drive: examples/serpentine.toml"}[name]


def report_animations(root: Path | None = None) -> dict:
    """Every case of :data:`CASES`: {name: Markdown lines}."""
    return {name: report_animation(name, root) for name in CASES}


if __name__ == "__main__":  # python -m ancf.reports.animations [NAME ...]
    import sys
    for name in sys.argv[1:] or list(CASES):
        print("".join(report_animation(name, REPORTS)))
