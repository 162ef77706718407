"""``ancf analytic moving-string``: the transverse frequencies of an axially moving string span."""
from __future__ import annotations

from analytic import moving_string
from ancf.common.params import Param
from ancf.scenes.analytic.shared import SPEED_OVER_WAVE, Bound, Validity, count_param, magnitudes
from ancf.scenes.base import NUM, Scene, SceneResult, field, nullable

#: its place in the list of references (ancf scenes, reports/schemas.md)
ORDER = 80


#: thesis Table 3.1 (as ancf.scenes.belt_common, not imported here: it loads the belt drive):
#: belt density (kg/m^3) and section (m), pulley radius (m), pulley centres at +-X_CENTRE (m)
_TABLE_3_1 = dict(rho=1036.0, h=0.01, b=0.01, R=0.08125, X_CENTRE=0.191441)
PARAMS = (
    Param("T", 100.0, float, "N", "span tension", lo=0, lo_open=True),
    Param("rho_A", _TABLE_3_1["rho"] * _TABLE_3_1["h"] * _TABLE_3_1["b"], float, "kg/m",
          "mass per unit length (default: the thesis's belt, Table 3.1)", lo=0, lo_open=True),
    Param("v", 120.0 * _TABLE_3_1["R"], float, "m/s", "belt speed (default: 120 rad/s on the "
          "driver, thesis Figs 3.10-3.20); |v| below the wave speed sqrt(T / rho_A)"),
    Param("L", 2.0 * _TABLE_3_1["X_CENTRE"], float, "m", "span length (default: the centre "
          "distance of the thesis's equal pulleys)", lo=0, lo_open=True),
    count_param(3),
)


#: the range of validity (issue 33): a string, well below its critical speed
VALIDITY = Validity((
    Bound("the speed over the wave speed |v| / c", lambda p, r: abs(p["v"]) / r.results[
        "wave_speed_m_s"], "a string: near c its frequencies vanish as 1 - v^2 / c^2 and the "
        "neglected bending stiffness decides them", hi=SPEED_OVER_WAVE),))


def _moving_string(p):
    f = moving_string.span_frequencies(p["T"], p["rho_A"], p["v"], p["L"], count=p["count"])
    c = moving_string.wave_speed(p["T"], p["rho_A"], p["L"])
    return SceneResult(True, "f_n = n c (1 - v^2/c^2) / (2 L), c = sqrt(T / rho_A)",
                       {"frequencies_hz": f.tolist(), "wave_speed_m_s": c})


RESULTS = {
    "frequencies_hz": field("array", "transverse span frequencies n c (1 - v^2/c^2) / (2 L), "
                            "ascending, Hz", items=NUM),
    "wave_speed_m_s": nullable("c = sqrt(T / rho_A), m/s")}


REFERENCE = Scene(
    "moving-string", "Transverse frequencies of an axially moving string span between "
    "fixed guides (the belt's free span).", PARAMS, _moving_string,
    magnitudes(moving_string.check_speed, "T", "rho_A", "v", "L"), results=RESULTS,
    warn=VALIDITY)
