"""``ancf analytic reissner``: the geometrically exact (Reissner) cantilever, dead tip load."""
from __future__ import annotations

import numpy as np

from analytic import reissner
from ancf.common.params import Param
from ancf.scenes.analytic.shared import (SECTION, Bound, Validity, shear_factor, span_over_height,
                                         with_defaults)
from ancf.scenes.base import Scene, SceneResult, nullable

#: its place in the list of references (ancf scenes, reports/schemas.md)
ORDER = 20

#: bending fibre strain h |kappa| / 2 of the exact kinematics with the linear law M = E I
#: kappa: it differs from a Green-strain (St Venant-Kirchhoff) section's by terms of order
#: strain^2 (the first order cancels across a symmetric section), 4 % at 0.2; the papers'
#: Model 2 (h = 0.5 m) bends to 0.13.  It bounds the other strains: the axial one at the
#: tip, F sin(theta_tip) / (E A), is its square / 6 (the rod's first integral M_root^2 = 2 E I
#: F sin(theta_tip)), 0.0067 at 0.2; the shear one at the root, |F| / (ks G A), stays below
#: it while the tip is more than h ahead of the root (ks >= 0.5, nu <= 0.5)
MODERATE_STRAIN = 0.2


def _fibre(p, r) -> float:
    """Largest bending fibre strain h |M| / (2 E I) along the rod, I = b h^3 / 12."""
    EI = p["E"] * p["b"] * p["h"] ** 3 / 12.0
    return p["h"] * float(np.max(np.abs(r.extra["solution"].M))) / (2.0 * EI)


#: the range of validity (issue 33): exact kinematics with the linear laws of moderate
#: strains, a beam, a rectangle's shear factor
VALIDITY = Validity((
    Bound("the bending fibre strain h |kappa| / 2", _fibre,
          "the linear law M = E I kappa of moderate strains", hi=MODERATE_STRAIN),
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
