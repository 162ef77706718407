"""``ancf analytic rigid-pendulum``: the rigid compound pendulum released horizontally."""
from __future__ import annotations

import numpy as np

from analytic.dynamics_refs import rigid_pendulum
from ancf.common.inputs import check_sampling, following, intervals
from ancf.common.params import InputError, Param
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


#: most swings one command integrates; above it the run is refused before it starts
MAX_SWINGS = 10_000
#: CPU seconds per swing at rtol 1e-12 (2-core EPYC: 3660 swings in 17.7 s), for the message
SECONDS_PER_SWING = 5e-3
#: 4 K(sin(pi/4)): the period of a release from the horizontal is this over omega_0
K_HORIZONTAL = 7.4163


def swings(p) -> float:
    """Periods in t_end of the release from the horizontal (large-amplitude period
    4 K(1/sqrt 2) / omega_0, omega_0^2 = (g L / 2) / (L^2/3 + h^2/12), rad/s)."""
    omega0 = np.sqrt(p["g"]) * np.sqrt(p["L"] / 2 / (p["L"] ** 2 / 3 + p["h"] ** 2 / 12))
    return float(p["t_end"] * omega0 / K_HORIZONTAL)


def check(p) -> None:
    """The sampling (:func:`ancf.common.inputs.check_sampling`) and the cost: at most
    MAX_SWINGS periods of the swing in t_end."""
    check_sampling(p)
    n = swings(p)
    if n > MAX_SWINGS:
        raise InputError(f"t_end = {p['t_end']!r} is out of range: {n:.3g} swings of the pendulum "
                         f"(g = {p['g']:g} m/s^2, L = {p['L']:g} m), about {n * SECONDS_PER_SWING:.3g} s of "
                         f"integration; allowed: at most {MAX_SWINGS} swings, t_end <= "
                         f"{p['t_end'] * MAX_SWINGS / n:.4g} s")


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
    _rigid, check, results=RESULTS, warn=VALIDITY)
