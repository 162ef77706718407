"""``ancf analytic navier-plate``: the simply supported Kirchhoff plate under pressure (Navier)."""
from __future__ import annotations

from analytic import navier_plate
from ancf.scenes.analytic.shared import NAVIER, magnitudes
from ancf.scenes.base import INT, Scene, SceneResult, field, nullable

#: its place in the list of references (ancf scenes, reports/schemas.md)
ORDER = 50


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
    magnitudes(navier_plate.check_magnitudes, "a", "b", "h", "E", "nu", "p"), results=RESULTS)
