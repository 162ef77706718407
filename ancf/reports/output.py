"""Writing report artefacts: Markdown tables, CSV data, PNG figures, progress.

Where they go and how much is computed is one :class:`Settings` per report run
(:func:`configure`): ``root`` (default ``reports/``) and ``quick`` (the reduced
configuration of ``python -m ancf.reports --quick``, see each chapter).

Timing is kept apart from results, so that regenerating the reports on one machine
changes nothing outside it: a column whose name starts with ``timing`` (:func:`is_timing`)
is left out of the chapter's Markdown tables and of ``data/NAME.csv``; the whole table
goes to ``data/timing/NAME.csv`` and, with every :func:`timing_note` and timing figure
(``figures/timing/``), to the chapter's timing page ``timing/CHAPTER.md`` ("varies per
run"), which :func:`take_timing` hands to the generator.
"""
from __future__ import annotations

import math
import sys
import time
from dataclasses import dataclass
from functools import lru_cache
from pathlib import Path

import pandas as pd

from ancf.common.paths import REPORTS

ROOT = REPORTS


@dataclass(frozen=True)
class Settings:
    root: Path = ROOT
    quick: bool = False


_SETTINGS = [Settings()]


def configure(root=None, quick: bool = False) -> Settings:
    """Set the output folder and the configuration of this report run."""
    _SETTINGS[0] = Settings(Path(root) if root is not None else ROOT, bool(quick))
    return _SETTINGS[0]


def settings() -> Settings:
    return _SETTINGS[0]


def fmt(v, digits=6) -> str:
    if v is None or (isinstance(v, float) and math.isnan(v)):
        return "—"
    if isinstance(v, bool):
        return "yes" if v else "no"
    if isinstance(v, float):
        return f"{v:.{digits}g}" if abs(v) >= 1e-3 or v == 0 else f"{v:.{digits - 2}e}"
    return str(v)


def is_timing(column) -> bool:
    """A timing column (CPU or wall time, machine): named ``timing...``."""
    return str(column).lower().startswith("timing")


_TIMING: list = []  # the timing page of the chapter being generated (Markdown parts)


def timing_note(title: str, *parts: str) -> None:
    """Add a section to the chapter's timing page (text that varies per run)."""
    _TIMING.extend([f"## {title}\n", *parts, ""])


def take_timing() -> list:
    """The timing page parts gathered since the last call (and forget them)."""
    parts = list(_TIMING)
    _TIMING.clear()
    return parts


def markdown_table(df: pd.DataFrame, digits: int = 6, timing: str | None = None) -> str:
    """The table without its timing columns; with any, the whole table goes to the
    chapter's timing page under the heading ``timing`` (required then)."""
    cols = [c for c in df.columns if is_timing(c)]
    if cols:
        if timing is None:
            raise ValueError(f"timing columns {cols} need the timing page's heading")
        timing_note(timing, _table(df, digits))
        df = df.drop(columns=cols)
    return _table(df, digits)


def _table(df: pd.DataFrame, digits: int) -> str:
    head = "| " + " | ".join(map(str, df.columns)) + " |"
    sep = "|" + "|".join("---" for _ in df.columns) + "|"
    rows = ["| " + " | ".join(fmt(v, digits) for v in row) + " |" for row in df.itertuples(index=False)]
    return "\n".join([head, sep, *rows])


def write_csv(df: pd.DataFrame, name: str) -> Path:
    """``data/NAME.csv`` without timing columns; with any, the whole table also goes to
    ``data/timing/NAME.csv``."""
    path = settings().root / "data" / f"{name}.csv"
    cols = [c for c in df.columns if is_timing(c)]
    if cols:
        full = path.parent / "timing" / path.name
        full.parent.mkdir(parents=True, exist_ok=True)
        df.to_csv(full, index=False)
        df = df.drop(columns=cols)
    path.parent.mkdir(parents=True, exist_ok=True)
    df.to_csv(path, index=False)
    return path


def checks_section(checks, status: dict, stem: str, tied: str) -> list:
    """The "Acceptance checks" section of a chapter: the checks of ``ancf/checks/{stem}.py``
    (each with name, value, reference, difference, tolerance, unit, measure) and their
    ``status``, written to ``data/{stem}_checks.csv``; ``tied``: which tests hold them."""
    df = pd.DataFrame([{"check": c.name, "value": c.value, "reference": c.reference,
                        "difference": c.difference, "tolerance": c.tolerance, "unit": c.unit,
                        "measure": c.measure, "status": status[c.name]} for c in checks])
    write_csv(df, f"{stem}_checks")
    return ["## Acceptance checks\n",
            f"Computed by `ancf/checks/{stem}.py`, each tied to {tied}.\n",
            markdown_table(df, 4), ""]


def count_axis(ax, counts) -> None:
    """Label a logarithmic x axis of element counts plainly at ``counts`` ("2, 4, 8",
    not "2×10⁰"), without minor labels."""
    from matplotlib.ticker import FixedFormatter, FixedLocator, NullFormatter
    values = sorted({int(v) for v in counts})
    ax.xaxis.set_major_locator(FixedLocator(values))
    ax.xaxis.set_major_formatter(FixedFormatter([str(v) for v in values]))
    ax.xaxis.set_minor_formatter(NullFormatter())


def save_figure(fig, name: str, timing: bool = False) -> Path:
    """``figures/NAME.png``; ``figures/timing/NAME.png`` for a figure with a time axis."""
    path = settings().root / "figures" / ("timing" if timing else "") / f"{name}.png"
    path.parent.mkdir(parents=True, exist_ok=True)
    fig.savefig(path, dpi=110, bbox_inches="tight")
    import matplotlib.pyplot as plt
    plt.close(fig)
    return path


def progress(msg: str) -> None:
    print(f"[{time.strftime('%H:%M:%S')}] {msg}", file=sys.stderr, flush=True)
    if _BEAT:
        try:
            _BEAT[0].stdin.write(msg.replace("\n", " ").encode() + b"\n")
            _BEAT[0].stdin.flush()
        except OSError:  # the heartbeat is gone: progress goes on without it
            _BEAT.clear()


_BEAT: list = []  # this process's heartbeat (a subprocess.Popen), once started

#: longest silence allowed on stderr while reports are generated (s)
HEARTBEAT_S = 20.0


def heartbeat(label: str, every: float = HEARTBEAT_S) -> None:
    """Start this process's heartbeat (:mod:`ancf.reports.heartbeat`): after ``every`` s
    without a progress line it prints what is running and for how long."""
    import subprocess
    if not _BEAT:
        _BEAT.append(subprocess.Popen([sys.executable, "-m", "ancf.reports.heartbeat", label,
                                       str(every)], stdin=subprocess.PIPE))


def heartbeat_stop() -> None:
    """End this process's heartbeat (its work is done; the process may live on idle, as a
    pool's worker does until the pool shuts down)."""
    if _BEAT:
        beat = _BEAT.pop()
        try:
            beat.stdin.close()
        except OSError:
            pass
        beat.wait()


@lru_cache(maxsize=None)
def _run_cached(registry: str, name: str, items: tuple):
    from ancf.scenes.analytic import REFERENCES
    from ancf.scenes import SCENES
    reg = SCENES if registry == "scene" else REFERENCES
    out, _ = reg[name].execute(dict(items))
    return out


def run(name: str, **overrides) -> dict:
    """Run a scene through its public interface (cached within one report run)."""
    return _run_cached("scene", name, tuple(sorted(overrides.items())))


def reference(name: str, **overrides) -> dict:
    return _run_cached("analytic", name, tuple(sorted(overrides.items())))
