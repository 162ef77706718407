"""``ancf analytic reissner``: the geometrically exact (Reissner) cantilever, dead tip load."""
from __future__ import annotations

from analytic import reissner
from ancf.common.params import Param
from ancf.scenes.analytic.shared import SECTION, with_defaults
from ancf.scenes.base import Scene, SceneResult, nullable

#: its place in the list of references (ancf scenes, reports/schemas.md)
ORDER = 20


def _reissner(p):
    r = reissner.tip_position(p["E"], p["nu"], p["L"], p["h"], p["b"], p["F"], ks=p["ks"])
    return SceneResult(r.converged, r.message,
                       {"tip_x": r.tip_x, "tip_y": r.tip_y, "tip_rotation_rad": r.tip_rotation},
                       extra={"solution": r})


RESULTS = {"tip_x": nullable("tip x, m"), "tip_y": nullable("tip y, m"),
           "tip_rotation_rad": nullable("tip section rotation, rad")}


REFERENCE = Scene(
    "reissner", "Geometrically exact (Reissner) cantilever, dead tip load (BVP, scipy).",
    with_defaults(SECTION, nu=0.3) + (Param("F", lambda v: -5e8 * v["h"] ** 3, float, "N",
                                            "vertical tip force (default -5e8 h^3)"),),
    _reissner, results=RESULTS)
