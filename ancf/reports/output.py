"""Writing report artefacts: Markdown tables, CSV data, PNG figures, progress."""
from __future__ import annotations

import math
import sys
import time
from functools import lru_cache
from pathlib import Path

import pandas as pd

ROOT = Path(__file__).resolve().parents[2] / "reports"


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
    path = ROOT / "data" / f"{name}.csv"
    path.parent.mkdir(parents=True, exist_ok=True)
    df.to_csv(path, index=False)
    return path


def save_figure(fig, name: str) -> Path:
    path = ROOT / "figures" / f"{name}.png"
    path.parent.mkdir(parents=True, exist_ok=True)
    fig.savefig(path, dpi=110, bbox_inches="tight")
    import matplotlib.pyplot as plt
    plt.close(fig)
    return path


def progress(msg: str) -> None:
    print(f"[{time.strftime('%H:%M:%S')}] {msg}", file=sys.stderr, flush=True)


@lru_cache(maxsize=None)
def _run_cached(registry: str, name: str, items: tuple):
    from analytic.references import REFERENCES
    from ancf.scenes import SCENES
    reg = SCENES if registry == "scene" else REFERENCES
    out, _ = reg[name].execute(dict(items))
    return out


def run(name: str, **overrides) -> dict:
    """Run a scene through its public interface (cached within one report run)."""
    return _run_cached("scene", name, tuple(sorted(overrides.items())))


def reference(name: str, **overrides) -> dict:
    return _run_cached("analytic", name, tuple(sorted(overrides.items())))
