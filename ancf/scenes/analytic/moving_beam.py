"""``ancf analytic moving-beam``: the transverse frequencies of an axially moving tensioned
beam span (the moving string with bending stiffness EI)."""
from __future__ import annotations

from dataclasses import replace

from analytic import moving_beam
from ancf.common.params import Param
from ancf.scenes.analytic.moving_string import _TABLE_3_1 as _STRING_TABLE
from ancf.scenes.analytic.moving_string import PARAMS as STRING_PARAMS
from ancf.scenes.analytic.shared import SPEED_OVER_WAVE, Bound, Validity, magnitudes
from ancf.scenes.base import NUM, Scene, SceneResult, field, nullable

#: its place in the list of references (ancf scenes, reports/schemas.md): after moving-string
ORDER = 82


#: thesis Table 3.1 (as ancf.scenes.belt_common, not imported here: it loads the belt drive):
#: moving-string's belt and pulleys, Young's modulus E (Pa) and the bending stiffness
#: parameter alpha2 (-) of Dufva's belt element, whose bending energy is E alpha2 I kappa^2 / 2
#: (analytic/dufva_belt.py, k1): the thesis belt bends with EI = alpha2 E b h^3 / 12
TABLE_3_1 = dict(_STRING_TABLE, E=1e8, alpha2=0.01)
#: the thesis belt's bending stiffness alpha2 E b h^3 / 12, N m^2 (8.33e-4)
EI_BELT = TABLE_3_1["alpha2"] * TABLE_3_1["E"] * TABLE_3_1["b"] * TABLE_3_1["h"] ** 3 / 12.0

_STRING = {p.name: p for p in STRING_PARAMS}
#: moving-string's T, rho_A, v (below v_c here), L, then EI, the ends, and count
PARAMS = (
    _STRING["T"], _STRING["rho_A"],
    replace(_STRING["v"], doc="belt speed (default: 120 rad/s on the driver, thesis Figs "
            "3.10-3.20); |v| below the critical speed v_c (critical_speed_m_s)"),
    _STRING["L"],
    Param("EI", EI_BELT, float, "N m^2", "bending stiffness (default: the thesis's belt, "
          "alpha2 E b h^3 / 12 of Table 3.1)", lo=0, lo_open=True),
    Param("ends", "clamped", str, doc="both ends pinned (w = w_xx = 0) or clamped (w = w_x = "
          "0); default clamped: the belt leaves and reaches its pulleys along the span, with "
          "no kink", choices=tuple(moving_beam.ENDS)),
    _STRING["count"])


def _check_speed(T, rho_A, v, L, EI, ends) -> float:
    """v_c (m/s, eq. (5) of analytic/moving_beam.py), or ValueError naming v when |v| >= v_c
    (the span diverges: no free vibration)."""
    v_c = moving_beam.critical_speed(T, rho_A, L, EI, ends)
    if abs(v) >= v_c:
        raise ValueError(f"v = {v!r} is out of range: allowed |v| < v_c = {v_c:.6g} m/s, the "
                         f"critical speed of the {ends} span (rho_A v_c^2 = T + the Euler load)")
    return v_c


#: the range of validity (issue 33): a beam span, well below its critical speed
VALIDITY = Validity((
    Bound("the speed over the critical speed |v| / v_c", lambda p, r: abs(p["v"]) / r.results[
        "critical_speed_m_s"], "near v_c its frequencies vanish and what the reference "
        "neglects (a guide's compliance, the pulleys' inertia) decides them",
        hi=SPEED_OVER_WAVE),))


def _moving_beam(p):
    f = moving_beam.span_frequencies(p["T"], p["rho_A"], p["v"], p["L"], p["EI"],
                                     count=p["count"], ends=p["ends"])
    v_c = moving_beam.critical_speed(p["T"], p["rho_A"], p["L"], p["EI"], p["ends"])
    return SceneResult(True, "roots of the boundary determinant of rho_A (w_tt + 2 v w_xt + "
                       "v^2 w_xx) - T w_xx + EI w_xxxx = 0 (Brent's method)",
                       {"frequencies_hz": f.tolist(), "critical_speed_m_s": v_c})


RESULTS = {
    "frequencies_hz": field("array", "transverse span frequencies, exact roots of the boundary "
                            "determinant, ascending, Hz", items=NUM),
    "critical_speed_m_s": nullable("v_c = sqrt((T + (1 + d)^2 pi^2 EI / L^2) / rho_A), d = 0 "
                                   "pinned, 1 clamped, m/s")}


REFERENCE = Scene(
    "moving-beam", "Transverse frequencies of an axially moving tensioned beam span, pinned "
    "or clamped ends (the belt's free span with its bending stiffness).", PARAMS, _moving_beam,
    magnitudes(_check_speed, "T", "rho_A", "v", "L", "EI", "ends"), results=RESULTS,
    warn=VALIDITY)
