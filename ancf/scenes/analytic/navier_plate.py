"""``ancf analytic navier-plate``: the simply supported Kirchhoff plate under pressure (Navier)."""
from __future__ import annotations

from analytic import navier_plate
from ancf.scenes.analytic.shared import (NAVIER, SHEAR_SHARE, Bound, Validity,
                                         kirchhoff_shear_share, magnitudes)
from ancf.scenes.base import INT, Scene, SceneResult, field, nullable

#: its place in the list of references (ancf scenes, reports/schemas.md)
ORDER = 50

#: centre deflection / thickness of the linear (Kirchhoff) plate: membrane action adds
#: about (w / h)^2 / 2 to the stiffness of a plate held at its edges, 5 % at 0.3 h (the
#: plate-square scene's bound, ancf.scenes.sense.THIN_PLATE_W_OVER_H)
MAX_W_OVER_H = 0.3


def _shear_share(p, r) -> float:
    """Mindlin's first-order correction of the deflection's fundamental term, (k h)^2 /
    (6 kappa (1 - nu)) with k^2 = pi^2 (1 / a^2 + 1 / b^2): shear adds about this share."""
    return kirchhoff_shear_share(p["a"], p["b"], p["h"], p["nu"])


#: the range of validity (issue 33): small deflection against the thickness, a thin plate
VALIDITY = Validity((
    Bound("the centre deflection |w| / h", lambda p, r: abs(r.results["center_deflection_m"])
          / p["h"], "linear plate theory: no membrane stretching", hi=MAX_W_OVER_H),
    Bound("the Kirchhoff shear share (k h)^2 / (6 kappa (1 - nu))", _shear_share,
          "Kirchhoff's thin plate neglects shear: h small against the sides", hi=SHEAR_SHARE)))


def _navier(p):
    w, N = navier_plate.centre_deflection(p["a"], p["b"], p["h"], p["E"], p["nu"], p["p"],
                                          rtol=p["rtol"])
    return SceneResult(True, f"Navier's double series summed in closed form over one index "
                       f"(Levy's single series): {N} term(s) of the correction series along the "
                       f"shorter side (tail bound below rtol = {p['rtol']:g})",
                       {"center_deflection_m": w, "terms": N})


RESULTS = {"center_deflection_m": nullable("centre deflection along the pressure, m"),
           "terms": field(INT, "largest odd series index summed")}


REFERENCE = Scene(
    "navier-plate", "Simply supported Kirchhoff plate under uniform pressure: Navier series "
    "centre deflection, summed as Levy's single series; 'terms' counts its correction "
    "terms (D = E h^3 / (12 (1 - nu^2))).", NAVIER, _navier,
    magnitudes(navier_plate.check_magnitudes, "a", "b", "h", "E", "nu", "p"), results=RESULTS,
    warn=VALIDITY)
