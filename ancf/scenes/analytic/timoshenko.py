"""``ancf analytic timoshenko``: the simply supported Timoshenko beam, midspan load
(SymPy-derived)."""
from __future__ import annotations

from analytic import timoshenko
from ancf.common.params import Param
from ancf.scenes.analytic.shared import SECTION, magnitudes
from ancf.scenes.base import Scene, SceneResult, nullable

#: its place in the list of references (ancf scenes, reports/schemas.md)
ORDER = 10


def _timoshenko(p):
    w = timoshenko.mid_deflection(p["E"], p["nu"], p["L"], p["h"], p["b"], p["F"], ks=p["ks"])
    return SceneResult(True, "closed form: " + timoshenko.closed_form_text(), {"mid_deflection_m": w})


RESULTS = {"mid_deflection_m": nullable("midspan deflection, m")}


REFERENCE = Scene(
    "timoshenko", "Simply supported Timoshenko beam, midspan load (SymPy-derived).",
    SECTION + (Param("F", -1000.0, float, "N", "vertical midspan force"),), _timoshenko,
    magnitudes(timoshenko.check_magnitudes, "E", "nu", "L", "h", "b", "F", "ks"), results=RESULTS)
