"""Picking "the cheapest" run so that timing noise does not decide it.

CPU times of one sweep scatter by 10-20 % from run to run on a shared machine, and many
configurations of the small static scenes cost the same within that noise.  A pick by
the smallest time alone would then flip between equivalent models from one report to
the next.  Runs within ``COST_TIE`` of the cheapest time count as equally cheap; among
them the smallest model wins (global coordinates), then the smallest error.
"""
from __future__ import annotations

import numpy as np
import pandas as pd

#: relative CPU-time band treated as a tie (one sweep's timing scatter)
COST_TIE = 0.25


def model_size(row) -> float:
    """Global coordinates of the run's mesh: (n_elements + 1) nodes x coordinates per
    node of its element; n_elements alone for elements of other families."""
    from ancf.scenes.beam_static import ELEMENTS
    n = float(row["n_elements"])
    el = ELEMENTS.get(str(row.get("element")))
    return (n + 1) * 2 * len(el.slots) if el is not None else n


def cheapest_first(df: pd.DataFrame, err: str = "error", band: float = COST_TIE) -> pd.DataFrame:
    """``df`` ordered cheapest first: the runs within ``band`` of the least CPU time,
    by model size then error, followed by the rest by CPU time."""
    if not len(df):
        return df
    cost = df["cpu_time_s"].astype(float)
    tied = cost <= (1.0 + band) * cost.min()
    size = np.array([model_size(r) for _, r in df.iterrows()])
    keys = pd.DataFrame({"tied": ~tied.to_numpy(), "size": np.where(tied, size, 0.0),
                         "err": np.where(tied, df[err].astype(float), 0.0),
                         "cost": cost.to_numpy()}, index=df.index)
    order = keys.sort_values(["tied", "size", "err", "cost"], kind="stable").index
    return df.loc[order]
