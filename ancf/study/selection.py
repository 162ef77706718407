"""Picking "the cheapest" run reproducibly: by counted work, never by measured time, and
robust to the machine-to-machine scatter of the counts.

Measured CPU times scatter by 10-60 % between identical runs and shift between machines,
so a pick by time flips between equivalent models from one report to the next (issue 15,
item 11).  The rank here uses ``work`` from :mod:`ancf.study.cost`: the run's counted
iterations, evaluations, factorisations and steps, weighted by a fixed model, identical on
every repeat on one machine.  Across machines (another CPU, BLAS or compiler) round-off
can steer Newton, and counted work differs by up to ``WORK_SCATTER`` (about 10 %, contact
runs; issue 23), so the ratio of two runs' work can move by a factor 1.1 / 0.9 = 1.22.

The rule (issue 23).  A fixed band around the least work (runs within 10 % tie) has an
edge: a candidate just inside or outside it moves with that scatter.  Instead:

1. Tie group, by gaps: sort the runs by work; the group starts at the least work and
   takes the next run while its work is less than ``1 + WORK_TIE`` times the previous
   one's (single linkage).  ``WORK_TIE`` = 0.4 exceeds the 22 % a ratio can move, so two
   runs of equal work are always in one group, and the group changes only when a gap of
   about 1.4 (between 1.15 and 1.71 after the scatter) appears or closes.
2. Inside the group the order uses no counted work: the least nominal work
   (:func:`nominal_work`: kernel points of one tangent evaluation x steps taken, the size
   of the computation without the iteration counts that round-off steers), then the
   smallest model (global coordinates), then the smallest error to two significant digits,
   then the fewest departures from the scene's defaults, then the input order.
3. The runs outside the group follow by work (uncounted runs last).

Because the order inside the group follows the nominal work, which tracks the counted
work, a run that enters or leaves the group at its far end is rarely the preferred one,
so the pick rarely depends on where the group ends.  Guarantee and limit: on every
committed speed-accuracy sweep (``reports/data/speed_accuracy_*.csv``, every error level
the reports tabulate, both references), the pick is unchanged when every run's work is
independently scaled by a factor in [0.9, 1.1] (``tests/study/test_selection.py``, 200 seeded
draws); this holds for the committed data, not for every conceivable sweep: a future sweep
with a gap near 1.4 between runs whose order matters could still flip, and that test fails
when such data are committed.  The picks stay within 12 % of the least counted work on
those sweeps.
"""
from __future__ import annotations

import numpy as np
import pandas as pd

from ancf.study.cost import counts, with_work

#: relative gap that separates two runs' work: smaller gaps chain the runs into one tie group
WORK_TIE = 0.4

#: relative scatter of a run's counted work between machines (round-off steering Newton)
WORK_SCATTER = 0.1


def tie_group(work, band: float = WORK_TIE) -> np.ndarray:
    """Mask of the runs chained to the least ``work`` by gaps below ``1 + band`` (NaN: out)."""
    w = np.asarray(work, dtype=float)
    order = np.argsort(np.where(np.isfinite(w), w, np.inf), kind="stable")
    ws = w[order]
    stop = np.nonzero(~(ws[1:] < (1.0 + band) * ws[:-1]))[0]
    size = (stop[0] + 1 if len(stop) else len(w)) if len(w) and np.isfinite(ws[0]) else 0
    tied = np.zeros(len(w), dtype=bool)
    tied[order[:size]] = True
    return tied


def model_size(row) -> float:
    """Global coordinates of the run's mesh: (n_elements + 1) nodes x coordinates per
    node of its element; n_elements alone for elements of other families."""
    from ancf.elements.catalogue import ELEMENTS, coordinates_per_node
    n, name = float(row["n_elements"]), str(row.get("element"))
    return (n + 1) * coordinates_per_node(name) if name in ELEMENTS else n


def nominal_work(row) -> float:
    """Kernel points of one tangent evaluation (coordinates^2 x elements x quadrature
    points, :func:`ancf.study.cost.counts`) times the steps the run took (time or load
    steps; 1 without): a deterministic measure of the computation's size, without the
    Newton iteration counts."""
    c = counts(row, {"tangent_evaluations": 1, "factorizations": 1})
    steps = pd.to_numeric(pd.Series([row.get("steps")]), errors="coerce").iloc[0]
    return float(c["kernel_points"]) * (float(steps) if steps > 0 else 1.0)


def _departures(df: pd.DataFrame, defaults: dict | None) -> np.ndarray:
    """Per row, how many of the ``defaults`` keys it sets to another value."""
    if not defaults:
        return np.zeros(len(df))
    keys = [k for k in defaults if k in df]
    return np.array([sum(r[k] != defaults[k] for k in keys) for _, r in df[keys].iterrows()],
                    dtype=float)


def tie_keys(df: pd.DataFrame, err: str = "error", defaults: dict | None = None) -> pd.DataFrame:
    """The order inside a tie group (no counted work): nominal work, model size, error to
    2 significant digits, departures from ``defaults``."""
    return pd.DataFrame({"nominal": [nominal_work(r) for _, r in df.iterrows()],
                         "size": [model_size(r) for _, r in df.iterrows()],
                         "err": [float(f"{e:.2g}") for e in df[err].astype(float)],
                         "dep": _departures(df, defaults)}, index=df.index)


def rank(keys: pd.DataFrame, work, band: float = WORK_TIE) -> pd.Index:
    """Index of ``keys`` cheapest first: the tie group of ``work`` by ``keys`` (then input
    order), then the rest by ``work`` (NaN last)."""
    w = np.asarray(work, dtype=float)
    tied = tie_group(w, band)
    k = np.where(tied[:, None], keys.to_numpy(dtype=float), 0.0)
    cost = np.where(tied, 0.0, np.where(np.isfinite(w), w, np.inf))
    return keys.index[np.lexsort((np.arange(len(w)), cost, *k.T[::-1], ~tied))]


def cheapest_first(df: pd.DataFrame, err: str = "error", band: float = WORK_TIE,
                   defaults: dict | None = None) -> pd.DataFrame:
    """``df`` ordered cheapest first (see the module doc).  Adds ``work`` when missing."""
    if not len(df):
        return df
    if "work" not in df:
        df = with_work(df)
    return df.loc[rank(tie_keys(df, err, defaults), df["work"], band)]
