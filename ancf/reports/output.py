"""Writing report artefacts: Markdown tables, CSV data, PNG figures, progress.

Where they go and how much is computed is one :class:`Settings` per report run
(:func:`configure`): ``root`` (default ``reports/``) and ``quick`` (the reduced
configuration of ``python -m ancf.reports --quick``, see each chapter).
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


def markdown_table(df: pd.DataFrame, digits: int = 6) -> str:
    head = "| " + " | ".join(map(str, df.columns)) + " |"
    sep = "|" + "|".join("---" for _ in df.columns) + "|"
    rows = ["| " + " | ".join(fmt(v, digits) for v in row) + " |" for row in df.itertuples(index=False)]
    return "\n".join([head, sep, *rows])


def write_csv(df: pd.DataFrame, name: str) -> Path:
    path = settings().root / "data" / f"{name}.csv"
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


def save_figure(fig, name: str) -> Path:
    path = settings().root / "figures" / f"{name}.png"
    path.parent.mkdir(parents=True, exist_ok=True)
    fig.savefig(path, dpi=110, bbox_inches="tight")
    import matplotlib.pyplot as plt
    plt.close(fig)
    return path


def progress(msg: str) -> None:
    print(f"[{time.strftime('%H:%M:%S')}] {msg}", file=sys.stderr, flush=True)


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
