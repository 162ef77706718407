"""``ancf analytic rigid-pendulum``: the rigid compound pendulum released horizontally."""
from __future__ import annotations

import numpy as np

from analytic.dynamics_refs import rigid_pendulum
from ancf.common.inputs import check_sampling, following, intervals
from ancf.common.params import Param
from ancf.scenes.analytic.shared import Bound, Validity
from ancf.scenes.base import Scene, SceneResult, series

#: its place in the list of references (ancf scenes, reports/schemas.md)
ORDER = 100
#: a reference the dynamic scenes are measured against (DYNAMIC_REFERENCES)
DYNAMIC = True


#: largest swing between two samples, rad: the tip's path drawn through the samples cuts the
#: arc by L (1 - cos(dtheta / 2)) ~ L dtheta^2 / 8, 1 % of L at 0.28 rad
MAX_SAMPLE_SWING = 0.28

#: the range of validity (issue 33): a history that resolves the swing
VALIDITY = Validity((
    Bound("the swing between samples max |d theta|", lambda p, r: float(np.max(np.abs(np.diff(
        r.results["theta"])), initial=0.0)), "a sampled history that resolves the swing: a "
        "smaller output_dt", hi=MAX_SAMPLE_SWING),))


def _rigid(p):
    n = intervals(p["t_end"], p["output_dt"])
    t = np.minimum(np.arange(n + 1) * p["output_dt"], p["t_end"])
    try:
        th, x, y = rigid_pendulum(p["L"], p["g"], t, p["h"])
    except FloatingPointError as exc:
        return SceneResult(False, str(exc), {"times": t.tolist(), "theta": None, "tip_x": None,
                                             "tip_y": None})
    return SceneResult(True, "theta'' = -(g L / 2) cos(theta) / (L^2/3 + h^2/12), DOP853 rtol 1e-12",
                       {"times": t.tolist(), "theta": th.tolist(), "tip_x": x.tolist(),
                        "tip_y": y.tolist()})


RESULTS = {"times": series("sample times, s"),
           "theta": series("angle, rad (null when the integration failed)", True),
           "tip_x": series("tip x, m (null when the integration failed)", True),
           "tip_y": series("tip y, m (null when the integration failed)", True)}


REFERENCE = Scene(
    "rigid-pendulum", "Rigid compound pendulum released horizontally (numerical, rtol 1e-12).",
    (Param("L", 2.0, float, "m", "length", lo=0, lo_open=True),
     Param("g", 9.81, float, "m/s^2", "gravitational acceleration", lo=0),
     Param("h", 0.0, float, "m", "section height (0: slender rod, the stated reference)", lo=0),
     Param("t_end", 1.0, float, "s", "simulated time", lo=0, lo_open=True, hi=1e4),
     Param("output_dt", following(0.01, "t_end"), float, "s",
           "sampling interval (default 0.01 s, at most t_end)", lo=0, lo_open=True, hi=10)),
    _rigid, check_sampling, results=RESULTS, warn=VALIDITY)
