"""``ancf analytic reissner``: the geometrically exact (Reissner) cantilever, dead tip load."""
from __future__ import annotations

import numpy as np

from analytic import reissner
from ancf.common.params import Param
from ancf.scenes.analytic.shared import (SECTION, SMALL_STRAIN, Bound, Validity, shear_factor,
                                         span_over_height, with_defaults)
from ancf.scenes.base import Scene, SceneResult, nullable

#: its place in the list of references (ancf scenes, reports/schemas.md)
ORDER = 20

#: bending fibre strain h |kappa| / 2 and shear strain of the exact kinematics with linear
#: laws M = E I kappa, V = ks G A gamma: these laws differ from a Green-strain (St
#: Venant-Kirchhoff) section's by terms of order strain^2 (the first order cancels across a
#: symmetric section): 4 % at 0.2; the papers' Model 2 (h = 0.5 m) bends to 0.13
MODERATE_STRAIN = 0.2


def _section(p) -> tuple:
    """E I (N m^2), E A (N), ks G A (N) of the rectangle b x h."""
    A = p["b"] * p["h"]
    return (p["E"] * A * p["h"] ** 2 / 12.0, p["E"] * A,
            p["ks"] * p["E"] / (2.0 * (1.0 + p["nu"])) * A)


def _fibre(p, r) -> float:
    """Largest bending fibre strain h |M| / (2 E I) along the rod."""
    return p["h"] * float(np.max(np.abs(r.extra["solution"].M))) / (2.0 * _section(p)[0])


def _axial(p, r) -> float:
    """Largest axial strain |N| / (E A), N = F sin(theta) of the dead vertical load."""
    return float(np.max(np.abs(p["F"] * np.sin(r.extra["solution"].theta)))) / _section(p)[1]


def _shear(p, r) -> float:
    """Largest shear strain |V| / (ks G A), V = F cos(theta)."""
    return float(np.max(np.abs(p["F"] * np.cos(r.extra["solution"].theta)))) / _section(p)[2]


#: the range of validity (issue 33): exact kinematics, linear laws of small or moderate
#: strains, a beam, a rectangle's shear factor
VALIDITY = Validity((
    Bound("the bending fibre strain h |kappa| / 2", _fibre,
          "the linear law M = E I kappa of moderate strains", hi=MODERATE_STRAIN),
    Bound("the axial strain |N| / (E A)", _axial,
          "the linear law N = E A eps of small strains", hi=SMALL_STRAIN),
    Bound("the shear strain |V| / (ks G A)", _shear,
          "the linear law V = ks G A gamma of moderate strains", hi=MODERATE_STRAIN),
    span_over_height(), shear_factor()))


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
    _reissner, results=RESULTS, warn=VALIDITY)
