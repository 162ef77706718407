"""``ancf analytic belt-steady``: the steady extensible belt on N pulleys (here three)."""
from __future__ import annotations

from analytic import belt_steady
from ancf.common.params import Param
from ancf.scenes.analytic.shared import (BELT_STRAIN, CREEP_SHARE, SPEED_OVER_WAVE, Bound,
                                         Validity, speed_over_wave)
from ancf.scenes.base import NUM, STR, Scene, SceneResult, field, nullable

#: its place in the list of references (ancf scenes, reports/schemas.md)
ORDER = 40


_M = dict(lo=-10.0, hi=10.0)  # m, a layout's coordinates
PARAMS = (
    Param("EA", 1e5, float, "N", "axial stiffness", lo=0, lo_open=True, hi=1e12),
    Param("rhoA", 0.1, float, "kg/m", "mass per unstretched length", lo=0, hi=1e3),
    Param("mu", 0.5, float, "-", "Coulomb friction coefficient", lo=1e-6, hi=10),
    Param("T_i", 300.0, float, "N", "installation tension: L0 = nominal path / (1 + T_i / EA)",
          lo=0, lo_open=True, hi=1e9),
    Param("omega", 100.0, float, "rad/s", "driver speed, counter-clockwise", lo=0, lo_open=True,
          hi=1e5),
    Param("R1", 0.08, float, "m", "driver radius (centre at the origin)", lo=0, lo_open=True,
          hi=10),
    Param("x2", 0.28, float, "m", "driven pulley centre x", **_M),
    Param("y2", 0.15, float, "m", "driven pulley centre y", **_M),
    Param("R2", 0.06, float, "m", "driven pulley radius", lo=0, lo_open=True, hi=10),
    Param("torque", 5.0, float, "N m", "load torque on the driven pulley", lo=-1e9, hi=1e9),
    Param("law3", "tensioner", str, "", "third pulley, on the driver's exit span: idler or "
          "tensioner", choices=("idler", "tensioner")),
    Param("x3", 0.16, float, "m", "third pulley's (nominal) centre x", **_M),
    Param("y3", 0.0, float, "m", "third pulley's (nominal) centre y", **_M),
    Param("R3", 0.035, float, "m", "third pulley radius", lo=0, lo_open=True, hi=10),
    Param("side3", -1, int, "-", "third pulley's side: 1 the belt's inner side, -1 its back",
          choices=(-1, 1)),
    Param("pivot_x", 0.24, float, "m", "tensioner arm pivot x", **_M),
    Param("pivot_y", -0.01, float, "m", "tensioner arm pivot y", **_M),
    Param("stiffness", 20.0, float, "N m/rad", "tensioner spring stiffness", lo=0, hi=1e9),
    Param("preload", 8.0, float, "N m", "tensioner spring moment into the belt at the nominal "
          "centre", lo=-1e9, hi=1e9),
)


def _three_pulleys(p) -> list:
    """The scene's layout as :func:`analytic.belt_steady.solve` takes it: the driver at the
    origin, the third pulley on its exit (slack) span, then the driven pulley."""
    third = {"name": p["law3"], "centre": (p["x3"], p["y3"]), "radius": p["R3"],
             "side": p["side3"], "law": p["law3"]}
    if p["law3"] == "tensioner":
        third.update(pivot=(p["pivot_x"], p["pivot_y"]), stiffness=p["stiffness"],
                     preload=p["preload"])
    return [{"name": "driver", "centre": (0.0, 0.0), "radius": p["R1"], "side": 1,
             "law": "prescribed", "omega": p["omega"]}, third,
            {"name": "driven", "centre": (p["x2"], p["y2"]), "radius": p["R2"], "side": 1,
             "law": "driven", "torque": p["torque"]}]


def _strain(p, r) -> float:
    """Largest span strain T / EA."""
    return max(s["tension_N"] for s in r.results["spans"]) / p["EA"]


def _creep_share(p, r) -> float:
    """Largest creep arc / wrap over the pulleys."""
    return max(q["creep_arc_rad"] / q["wrap_rad"] for q in r.results["pulleys"])


def _span_speed(p, r) -> float:
    """Largest v / c over the spans (:func:`speed_over_wave`)."""
    return max(speed_over_wave(s["speed"], s["tension_N"], p["EA"], p["rhoA"])
               for s in r.results["spans"])


#: the range of validity (issue 33): Bechtel's (:mod:`ancf.scenes.analytic.bechtel`) on
#: every span and pulley
VALIDITY = Validity((
    Bound("the belt strain max T / EA", _strain, "the linear law T = EA (lambda - 1) of a belt",
          hi=BELT_STRAIN),
    Bound("the creep arc over the wrap max creep / wrap", _creep_share, "a stick arc at each "
          "entry sets the pulleys' speeds: near the whole wrap the belt slips", hi=CREEP_SHARE),
    Bound("a span's speed over its wave speed max v / sqrt(T lambda / rhoA)", _span_speed,
          "the belt presses on the pulleys with (T - rhoA v^2 / lambda) / R, which vanishes "
          "there: it lifts off", hi=SPEED_OVER_WAVE)))


def _belt_steady(p):
    pulleys = _three_pulleys(p)
    L0 = belt_steady.path_length(pulleys) / (1.0 + p["T_i"] / p["EA"])
    return SceneResult(True, "closed form per creep arc, n_t by Brent's method (xtol "
                       f"{belt_steady.XTOL_N:g} N)" + (", the arm's moment balance by Brent's "
                       f"method (xtol {belt_steady.XTOL_PSI:g} rad)"
                       if p["law3"] == "tensioner" else ""),
                       belt_steady.solve(pulleys, EA=p["EA"], rhoA=p["rhoA"], L0=L0, mu=p["mu"]))


RESULTS = {
    "path_length_m": field(NUM, "length of the wrapped path at the tensioner's equilibrium, m"),
    "L0_m": field(NUM, "stress-free belt length used, m"),
    "spans": field("array", "per span, in belt order", items="object", keys={
        "from": field(STR, "pulley the span leaves"), "to": field(STR, "pulley it reaches"),
        "length_m": field(NUM, "span length (common tangent), m"),
        "tension_N": field(NUM, "tension T, N"), "speed": field(NUM, "belt speed, m/s")}),
    "pulleys": field("array", "per pulley, in belt order", items="object", keys={
        "name": field(STR, "pulley name"), "law": field(STR, "prescribed, driven, idler or "
                                                        "tensioner"),
        "wrap_rad": field(NUM, "wrap angle, rad"),
        "stick_arc_rad": field(NUM, "stick arc (from the entry), rad"),
        "creep_arc_rad": field(NUM, "creep arc (at the exit), rad"),
        "omega": field(NUM, "angular speed, positive counter-clockwise, rad/s"),
        "torque_Nm": field(NUM, "the belt's moment on it along its rotation (the driver's: "
                                "minus its driving torque), N m"),
        "slip": field(NUM, "1 - its rim speed / the driver's"),
        "arm_angle_rad": nullable("a tensioner's arm angle at equilibrium, pivot to "
                                  "centre, counter-clockwise from x, rad (null: no arm)")})}


REFERENCE = Scene(
    "belt-steady", "Steady extensible belt (Bechtel's model) on N pulleys, here three: a "
    "driver, an idler or tensioner on its slack span and a driven pulley; span tensions "
    "and speeds, per pulley creep and stick arcs, slip, torque and a tensioner's angle "
    "(any layout: analytic.belt_steady.solve).", PARAMS, _belt_steady, results=RESULTS,
    warn=VALIDITY)
