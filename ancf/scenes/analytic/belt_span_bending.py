"""``ancf analytic belt-span-bending``: the steady free span of a moving belt with bending
stiffness between two pulleys (Kong & Parker 2005, :mod:`analytic.belt_span_bending`).

The pulleys sit at (-D/2, 0) (pulley 1, radius r1) and (D/2, 0) (pulley 2, r2), both turning
counter-clockwise: the span is the lower one, run from pulley 1 to pulley 2.  With EI > 0
the belt leaves pulley 1 earlier and reaches pulley 2 later than a string would, by the
shifts ``departure_shift_rad`` and ``arrival_shift_rad``.
"""
from __future__ import annotations

from analytic import belt_span_bending
from ancf.common.params import InputError, Param
from ancf.scenes.analytic.moving_beam import EI_BELT, TABLE_3_1
from ancf.scenes.analytic.shared import (BELT_STRAIN, SPEED_OVER_WAVE, Bound, Validity,
                                         magnitudes, speed_over_wave)
from ancf.scenes.base import Scene, SceneResult, nullable

#: its place in the list of references (ancf scenes, reports/schemas.md): after moving-beam
ORDER = 84

#: thesis Table 3.1 (ancf.scenes.analytic.moving_beam): pulley radius R (m), centre distance
#: 2 X_CENTRE (m), belt section b x h (m), density rho (kg/m^3), E (Pa); axial stiffness
#: parameter alpha1 = 1 of Dufva's belt element: EA = alpha1 E b h (1e4 N)
_T = TABLE_3_1
PARAMS = (
    Param("r1", _T["R"], float, "m", "radius of pulley 1, the span's start (default: the "
          "thesis's pulleys, Table 3.1)", lo=0, lo_open=True),
    Param("r2", _T["R"], float, "m", "radius of pulley 2, the span's end", lo=0, lo_open=True),
    Param("D", 2.0 * _T["X_CENTRE"], float, "m", "centre distance along x, pulleys at "
          "(-D/2, 0) and (D/2, 0); more than r1 + r2", lo=0, lo_open=True),
    Param("N1", 100.0, float, "N", "axial force where the belt leaves pulley 1 (default: "
          "moving-string's span tension T)", lo=0, lo_open=True),
    Param("EI", EI_BELT, float, "N m^2", "bending stiffness (default: the thesis's belt, "
          "alpha2 E b h^3 / 12 of Table 3.1)", lo=0, lo_open=True),
    Param("rhoA", _T["rho"] * _T["b"] * _T["h"], float, "kg/m", "mass per unstretched length "
          "(default: the thesis's belt)", lo=0),
    Param("v", 120.0 * _T["R"], float, "m/s", "belt speed at the rims (default: 120 rad/s on "
          "the driver); |v| below sqrt(N1 (1 + N1 / EA) / rhoA)"),
    Param("EA", _T["E"] * _T["b"] * _T["h"], float, "N", "axial stiffness (default: the "
          "thesis's belt, alpha1 E b h with alpha1 = 1)", lo=0, lo_open=True),
)
_ARGS = ("r1", "r2", "D", "N1", "EI", "rhoA", "v", "EA")


def _check(r1, r2, D, N1, EI, rhoA, v, EA) -> None:
    """ValueError naming D when the pulleys overlap, v when the effective tension P1 <= 0."""
    if D <= r1 + r2:
        raise ValueError(f"D = {D!r} is out of range: the pulleys overlap; allowed D > r1 + r2 "
                         f"= {r1 + r2:.6g} m")
    belt_span_bending.effective_tension(N1, rhoA, v, EA)


def _span(p) -> dict:
    """analytic.belt_span_bending.span on the pulleys of the module doc; its ValueError (EI
    beyond a span it solves) as InputError."""
    c1, c2 = (-0.5 * p["D"], 0.0), (0.5 * p["D"], 0.0)
    try:
        return belt_span_bending.span(c1, p["r1"], c2, p["r2"], p["N1"], p["EI"], p["rhoA"],
                                      p["v"], p["EA"])
    except ValueError as exc:
        raise InputError(str(exc)) from None


#: the range of validity (issue 33): a belt held straight by its effective tension, a
#: linear axial law
VALIDITY = Validity((
    Bound("the speed over the wave speed |v| / sqrt(N1 lambda / rhoA)", lambda p, r:
          speed_over_wave(p["v"], p["N1"], p["EA"], p["rhoA"]), "the effective tension P1 = "
          "N1 - rhoA v^2 / lambda vanishes there and the bending length sqrt(EI / P1) with it: "
          "the span sags out to the pulleys", hi=SPEED_OVER_WAVE),
    Bound("the belt strain tension_mean_N / EA", lambda p, r: r.results["tension_mean_N"]
          / p["EA"], "the linear law N = EA (lambda - 1) of a belt", hi=BELT_STRAIN)))


def _belt_span(p):
    s = _span(p)
    return SceneResult(True, "solve_bvp on the steady elastica with the centrifugal term "
                       f"(tol {belt_span_bending.BVP_TOL:g})",
                       {k: float(s[k]) for k in RESULTS})


RESULTS = {
    "departure_shift_rad": nullable("angle by which the belt leaves pulley 1 before the "
                                    "string's tangent point, rad"),
    "arrival_shift_rad": nullable("angle by which the belt reaches pulley 2 after the "
                                  "string's tangent point, rad"),
    "length_m": nullable("deformed arclength of the free span, m"),
    "tension_mean_N": nullable("mean axial force over the middle third of the span, N")}


REFERENCE = Scene(
    "belt-span-bending", "Steady free span of a moving belt with bending stiffness between two "
    "pulleys: where it leaves and reaches them, its length and tension (Kong & Parker).",
    PARAMS, _belt_span, magnitudes(_check, *_ARGS), results=RESULTS, warn=VALIDITY)
