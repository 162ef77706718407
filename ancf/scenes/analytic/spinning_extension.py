"""``ancf analytic spinning-extension``: the steady axial extension of a spinning beam
(thesis Eq. 2.36)."""
from __future__ import annotations

import math

from analytic.dynamics_refs import spinning_extension
from ancf.common.params import Param
from ancf.scenes.analytic.shared import SMALL_STRAIN, Bound, Validity
from ancf.scenes.base import Scene, SceneResult, nullable

#: its place in the list of references (ancf scenes, reports/schemas.md)
ORDER = 90
#: a reference the dynamic scenes are measured against (DYNAMIC_REFERENCES)
DYNAMIC = True


#: the range of validity (issue 33): Eq. 2.36 is linear elasticity; its strain u' =
#: cos(a x) / cos(a L) - 1 is largest at the axis, 1 / cos(a L) - 1
VALIDITY = Validity((
    Bound("the strain at the axis 1 / cos(a L) - 1", lambda p, r: 1.0 / math.cos(r.results["al"])
          - 1.0, "Eq. 2.36 is linear elasticity, small strains", hi=SMALL_STRAIN),))


def _extension(p):
    al = math.sqrt(p["rho"] / p["E"]) * p["omega_s"] * p["L"]
    if al >= math.pi / 2:
        return SceneResult(False, f"a l = {al:.4g} >= pi/2: no steady state (resonance of the "
                           "axial mode)", {"axial_extension_m": None, "al": al,
                                           "axial_extension_thesis_m": None})
    u = spinning_extension(p["L"], p["E"], p["rho"], p["omega_s"])
    # the thesis's printed 1.09545e-4 m: rho A with Wu & Haug's tabulated area, E A with b h
    ut = spinning_extension(p["L"], p["E"], p["rho"] * p["A_mass"] / (p["b"] * p["h"]), p["omega_s"])
    return SceneResult(True, "closed form (thesis Eq. 2.36)",
                       {"axial_extension_m": u, "al": al, "axial_extension_thesis_m": ut})


RESULTS = {
    "axial_extension_m": nullable("steady axial extension (Eq. 2.36), m"),
    "al": nullable("the parameter a L of Eq. 2.36"),
    "axial_extension_thesis_m": nullable("the same as printed in the thesis, m")}


REFERENCE = Scene(
    "spinning-extension", "Steady axial extension of a spinning beam (thesis Eq. 2.36).",
    (Param("L", 8.0, float, "m", "beam length", lo=0, lo_open=True),
     Param("E", 6.895e10, float, "Pa", "Young's modulus", lo=0, lo_open=True),
     Param("rho", 2766.67, float, "kg/m^3", "density", lo=0, lo_open=True),
     Param("omega_s", 4.0, float, "rad/s", "steady angular velocity", lo=0),
     Param("b", 1.986e-3, float, "m", "section width (thesis)", lo=0, lo_open=True),
     Param("h", 3.675e-2, float, "m", "section height (thesis)", lo=0, lo_open=True),
     Param("A_mass", 7.2968e-5, float, "m^2",
           "area in rho A of the thesis variant (Wu & Haug's tabulated A)", lo=0, lo_open=True)),
    _extension, results=RESULTS, warn=VALIDITY)
