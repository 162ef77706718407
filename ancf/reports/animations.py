"""Animations of the belt drives: GIFs (matplotlib's ``PillowWriter``) of a finished run
of ``belt2d``, ``belt3d`` or ``belt-drive`` over one revolution of the driver.

:func:`animate` takes a run (an ``ancf.run`` :class:`~ancf.api.Result`, or the scene's name
and its ``SceneResult.extra``) and writes one GIF: the belt coloured by its axial force
(N; the belt points of :func:`ancf.scenes.frames.frames`, the same as ``--vtk`` writes;
one colour scale for the whole animation), every pulley with a spoke so that its rotation
shows, a tensioner's arm, and the time stamp.  The frames are the output steps of the
last revolution of the driver (its angle, the integral of its speed law, within 2 pi of
the final one), thinned evenly to at most ``max_frames``; the colour scale spans the 1st to
the 99th percentile of the axial force over them (the contact entries' spikes beyond).

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
DPI = 72            # pixels per inch (a 6 x 4.6 in figure: 432 x 331 px)
MAX_FRAMES = 80
SUBSTEPS = 16       # trapezoid sub-intervals per output step of the driver's angle
CMAP = "viridis"
CLIP = (1, 99)      # percentiles of the axial force over the frames: the colour scale's ends


@dataclass
class Animation:
    """What :func:`animate` wrote: ``path``, the number of ``frames``, the time span
    ``t0``-``t1`` (s), the driver's turn over it (rad) and the file size (bytes)."""

    path: Path
    frames: int
    t0: float
    t1: float
    driver_turn: float
    size: int


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


def last_revolution(turn: np.ndarray, max_frames: int) -> np.ndarray:
    """Indices of the output steps over the driver's last revolution (its angle within
    2 pi of the final one; all of them if it turned less), thinned evenly to at most
    ``max_frames``."""
    idx = np.flatnonzero(turn >= turn[-1] - 2 * np.pi)
    idx = np.arange(idx[0] - 1 if idx[0] > 0 else 0, turn.size)
    if idx.size > max_frames:
        idx = idx[np.unique(np.round(np.linspace(0, idx.size - 1, max_frames)).astype(int))]
    return idx


# --- drawing ---------------------------------------------------------------------------

def _circle(c, R, z=None, n=72):
    a = np.linspace(0, 2 * np.pi, n)
    pts = [c[0] + R * np.cos(a), c[1] + R * np.sin(a)]
    return pts if z is None else pts + [np.full(n, z)]


def _segments(points):
    """Closed polyline -> (m, 2, dim) segments."""
    return np.stack([points, np.roll(points, -1, axis=0)], 1)


class _Scene2D:
    """Artists of a planar drive: the belt (LineCollection), pulley rims, spokes, arms."""

    def __init__(self, ax, drive, norm, extent):
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
        ax.set(xlim=(x0, x1), ylim=(y0, y1), aspect="equal", xlabel="x [m]", ylabel="y [m]")

    def update(self, frame, centres, angles):
        self.belt.set_segments(_segments(frame.points[:, :2]))
        self.belt.set_array(_segment_values(frame.point_data["axial_force_N"]))
        for p, (c, R, th) in enumerate(zip(centres, self.drive.radii, angles)):
            self.rims[p].set_data(*_circle(c, R))
            self.spokes[p].set_data([c[0], c[0] + R * np.cos(th)], [c[1], c[1] + R * np.sin(th)])
        for a, row in enumerate(self.drive.rig.arms):
            c = centres[int(row[PULLEY])]
            self.arms[a].set_data([row[PIVOT_X], c[0]], [row[PIVOT_Y], c[1]])


class _Scene3D:
    """Artists of the 3D belt: the mid-surface quads and both faces of every pulley."""

    def __init__(self, ax, drive, norm, extent, width):
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
        ax.set(xlim=(x0, x1), ylim=(y0, y1), zlim=(-0.5 * width, 1.5 * width),
               xlabel="x [m]", ylabel="y [m]", zlabel="z [m]")
        ax.set_box_aspect((x1 - x0, y1 - y0, 2 * width))
        ax.view_init(elev=28, azim=-62)
        ax.tick_params(labelsize=6)

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


def _segment_values(values):
    """Point values of a closed polyline -> one value per segment (the mean of its ends)."""
    return 0.5 * (values + np.roll(values, -1))


def _extent(points, centres, radii, margin=0.1):
    """(x range, y range) holding the belt and every pulley, with a margin."""
    lo = np.minimum(points.min(axis=0)[:2], (centres[:, :2] - radii[:, None]).min(axis=0))
    hi = np.maximum(points.max(axis=0)[:2], (centres[:, :2] + radii[:, None]).max(axis=0))
    pad = margin * (hi - lo).max()
    return (lo[0] - pad, hi[0] + pad), (lo[1] - pad, hi[1] + pad)


def animate(run, path, extra: dict | None = None, *, title: str = "", max_frames: int = MAX_FRAMES,
            fps: int = FPS, dpi: int = DPI, per_element: int = 8) -> Animation:
    """Write the GIF of a belt drive's run to ``path``: ``run`` an ``ancf.run`` result (or
    the scene's name, with its ``SceneResult.extra`` as ``extra``); see the module doc."""
    scene, extra = (run, extra) if isinstance(run, str) else (run.scene, run.extra)
    drive, res = _drive(extra)
    angles = pulley_angles(drive, res)
    idx = last_revolution(angles[:, driver(drive)], max_frames)
    allframes = frames_of(scene, extra, per_element)
    shown = [allframes[i] for i in idx]
    x, v, t = np.asarray(res.q), np.asarray(res.v), np.asarray(res.t, float)
    centres = [pulley_centres(drive, x[i], v[i], float(t[i])) for i in idx]
    forces = np.concatenate([f.point_data["axial_force_N"] for f in shown])
    norm = matplotlib.colors.Normalize(*np.percentile(forces, CLIP))
    extent = _extent(np.concatenate([f.points for f in shown]), np.concatenate(centres),
                     np.tile(drive.radii, len(centres)))
    three = hasattr(drive, "axes")
    (x0, x1), (y0, y1) = extent
    height = 4.4 if three else float(np.clip(5.2 * (y1 - y0) / (x1 - x0) + 0.9, 2.6, 5.6))
    fig = plt.figure(figsize=(6.4, height), layout="constrained")
    ax = fig.add_subplot(projection="3d" if three else None)
    art = _Scene3D(ax, drive, norm, extent, drive.spec.width) if three else \
        _Scene2D(ax, drive, norm, extent)
    fig.colorbar(matplotlib.cm.ScalarMappable(norm=norm, cmap=CMAP), ax=ax, shrink=0.9,
                 label="axial force [N]", extend="both")
    ax.set_title(title or scene, fontsize=9, loc="left")
    stamp = fig.text(0.005, 0.005, "t = 0.000 s, driver 0.00 rev", fontsize=8,
                     family="monospace", va="bottom")
    fig.canvas.draw()
    fig.set_layout_engine("none")  # laid out once: every frame the same axes
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    writer = PillowWriter(fps=fps)
    with writer.saving(fig, str(path), dpi):
        for f, i, c in zip(shown, idx, centres):
            art.update(f, c, angles[i])
            turns = angles[i, driver(drive)] / (2 * np.pi)
            stamp.set_text(f"t = {t[i]:.3f} s, driver {turns:.2f} rev")
            writer.grab_frame()
    plt.close(fig)
    turn = angles[idx[-1], driver(drive)] - angles[idx[0], driver(drive)]
    return Animation(path, len(idx), float(t[idx[0]]), float(t[idx[-1]]), float(turn),
                     path.stat().st_size)


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
