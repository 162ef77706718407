"""``ancf analytic timoshenko``: the simply supported Timoshenko beam, midspan load
(SymPy-derived)."""
from __future__ import annotations

from analytic import timoshenko
from ancf.common.params import Param
from ancf.scenes.analytic.shared import (SECTION, Bound, Validity, magnitudes, shear_factor,
                                         span_over_height)
from ancf.scenes.base import Scene, SceneResult, nullable

#: its place in the list of references (ancf scenes, reports/schemas.md)
ORDER = 10

#: midspan deflection / span of the linear theory: its section rotations (3 |w| / L at the
#: supports in bending, 2 |w| / L in shear) stay within 0.15 rad, where sin(theta) ~ theta
#: and the chord's shortening theta^2 / 2 (1 %) are still small; the strains follow
#: (fibre 6 |w| h / L^2, shear 2 |w| / L)
MAX_W_OVER_L = 0.05


def _timoshenko(p):
    w = timoshenko.mid_deflection(p["E"], p["nu"], p["L"], p["h"], p["b"], p["F"], ks=p["ks"])
    return SceneResult(True, "closed form: " + timoshenko.closed_form_text(), {"mid_deflection_m": w})


#: the range of validity (issue 33): small rotations, a beam, a rectangle's shear factor
VALIDITY = Validity((
    Bound("the midspan deflection |w| / L",
          lambda p, r: abs(r.results["mid_deflection_m"]) / p["L"],
          "linear theory: small rotations, about 3 |w| / L rad", hi=MAX_W_OVER_L),
    span_over_height(), shear_factor()))

RESULTS = {"mid_deflection_m": nullable("midspan deflection, m")}


REFERENCE = Scene(
    "timoshenko", "Simply supported Timoshenko beam, midspan load (SymPy-derived).",
    SECTION + (Param("F", -1000.0, float, "N", "vertical midspan force"),), _timoshenko,
    magnitudes(timoshenko.check_magnitudes, "E", "nu", "L", "h", "b", "F", "ks"), results=RESULTS,
    warn=VALIDITY)
