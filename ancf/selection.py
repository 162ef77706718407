"""Picking "the cheapest" run so that timing noise does not decide it.

CPU times of one sweep scatter by 10-20 % from run to run on a shared machine, and many
configurations of the small static scenes cost the same within that noise.  A pick by
the smallest time alone would then flip between equivalent models from one report to
the next.  Runs within ``COST_TIE`` of the cheapest time, or within ``COST_TIE_ABS_S`` of it
for millisecond-scale runs (whichever band is wider), count as equally cheap; among
them the smallest model wins (global coordinates), then the smallest error (to two
significant digits: quadrature variants that agree to print precision are equivalent),
then the run closest to the scene's defaults, then the least time.
"""
from __future__ import annotations

import numpy as np
import pandas as pd

#: relative CPU-time band treated as a tie (one sweep's timing scatter)
COST_TIE = 0.25
#: absolute band (s): the same static solve (same element, mesh and iterations, two rtol
#: values) measured 0.7 ms apart at the median and 1.9 ms at worst in one sweep of
#: reports/data/speed_accuracy_simply_supported.csv, i.e. up to 30-60 % of a 3-5 ms run
COST_TIE_ABS_S = 2e-3


def tie_limit(least: float, band: float = COST_TIE, abs_band: float = COST_TIE_ABS_S) -> float:
    """CPU time (s) up to which a run ties with the cheapest one (``least`` s)."""
    return max((1.0 + band) * least, least + abs_band)


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


def cheapest_first(df: pd.DataFrame, err: str = "error", band: float = COST_TIE,
                   defaults: dict | None = None, abs_band: float = COST_TIE_ABS_S) -> pd.DataFrame:
    """``df`` ordered cheapest first: the runs within ``tie_limit`` of the least CPU time, by
    model size, error (2 significant digits), departures from ``defaults`` and time,
    followed by the rest by CPU time."""
    if not len(df):
        return df
    cost = df["cpu_time_s"].astype(float)
    tied = (cost <= tie_limit(cost.min(), band, abs_band)).to_numpy()
    size = np.array([model_size(r) for _, r in df.iterrows()])
    error = np.array([float(f"{e:.2g}") for e in df[err].astype(float)])
    keys = pd.DataFrame({"tied": ~tied, "size": np.where(tied, size, 0.0),
                         "err": np.where(tied, error, 0.0),
                         "dep": np.where(tied, _departures(df, defaults), 0.0),
                         "cost": cost.to_numpy()}, index=df.index)
    order = keys.sort_values(["tied", "size", "err", "dep", "cost"], kind="stable").index
    return df.loc[order]
