"""Picking "the cheapest" run reproducibly: by counted work, never by measured time.

Measured CPU times scatter by 10-60 % between identical runs and shift between machines,
so a pick by time (or by time with a tie band) flips between equivalent models from one
report to the next (issue 15, item 11).  The rank here uses ``work`` from
:mod:`ancf.study.cost`: the run's counted iterations, evaluations, factorisations and steps,
weighted by a fixed model, identical on every machine and every repeat.  The timing
columns stay in the tables but do not decide.

The cost model describes measured seconds to about 5-20 % (its calibration is reported
next to the tables), so runs within ``WORK_TIE`` of the least work count as equally
cheap; among them the smallest model wins (global coordinates), then the smallest error
(to two significant digits: quadrature variants that agree to print precision are
equivalent), then the run closest to the scene's defaults, then the least work.  Every
key is a deterministic function of the runs' parameters and counts.
"""
from __future__ import annotations

import numpy as np
import pandas as pd

from ancf.study.cost import with_work

#: relative band of work treated as a tie (the cost model's typical scatter)
WORK_TIE = 0.1


def tie_limit(least: float, band: float = WORK_TIE) -> float:
    """Work up to which a run ties with the cheapest one (``least`` work units)."""
    return (1.0 + band) * least


def model_size(row) -> float:
    """Global coordinates of the run's mesh: (n_elements + 1) nodes x coordinates per
    node of its element; n_elements alone for elements of other families."""
    from ancf.elements.catalogue import ELEMENTS, coordinates_per_node
    n, name = float(row["n_elements"]), str(row.get("element"))
    return (n + 1) * coordinates_per_node(name) if name in ELEMENTS else n


def _departures(df: pd.DataFrame, defaults: dict | None) -> np.ndarray:
    """Per row, how many of the ``defaults`` keys it sets to another value."""
    if not defaults:
        return np.zeros(len(df))
    keys = [k for k in defaults if k in df]
    return np.array([sum(r[k] != defaults[k] for k in keys) for _, r in df[keys].iterrows()],
                    dtype=float)


def cheapest_first(df: pd.DataFrame, err: str = "error", band: float = WORK_TIE,
                   defaults: dict | None = None) -> pd.DataFrame:
    """``df`` ordered cheapest first: the runs within ``tie_limit`` of the least work, by
    model size, error (2 significant digits), departures from ``defaults`` and work,
    followed by the rest by work (uncounted runs last).  Adds ``work`` when missing."""
    if not len(df):
        return df
    if "work" not in df:
        df = with_work(df)
    cost = df["work"].astype(float)
    tied = (cost <= tie_limit(cost.min(), band)).to_numpy()
    size = np.array([model_size(r) for _, r in df.iterrows()])
    error = np.array([float(f"{e:.2g}") for e in df[err].astype(float)])
    keys = pd.DataFrame({"tied": ~tied, "size": np.where(tied, size, 0.0),
                         "err": np.where(tied, error, 0.0),
                         "dep": np.where(tied, _departures(df, defaults), 0.0),
                         "cost": cost.fillna(np.inf).to_numpy()}, index=df.index)
    order = keys.sort_values(["tied", "size", "err", "dep", "cost"], kind="stable").index
    return df.loc[order]
