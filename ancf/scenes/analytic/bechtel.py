"""``ancf analytic bechtel``: Bechtel et al.'s steady extensible belt on two pulleys."""
from __future__ import annotations

import math

from analytic import bechtel
from ancf.scenes.analytic.shared import (BELT_STRAIN, CREEP_SHARE, SPEED_OVER_WAVE, Bound,
                                         Validity, speed_over_wave)
from ancf.scenes.base import Scene, SceneResult, field, nullable

#: its place in the list of references (ancf scenes, reports/schemas.md)
ORDER = 30


def _slack_speed(p, r) -> float:
    """v / c of the slack span, the larger of the two (c falls with the tension)."""
    return speed_over_wave(r.results["v_slack"], r.results["T_slack_N"], p["k"], p["rhoA"])


#: the range of validity (issue 33): the small-strain law, a stick arc at each entry, a belt
#: that presses on its pulleys
VALIDITY = Validity((
    Bound("the belt strain T_tight / k", lambda p, r: r.results["T_tight_N"] / p["k"],
          "the linear law T = k (lambda - 1) of a belt", hi=BELT_STRAIN),
    Bound("the slip arc over the wrap phi / pi",
          lambda p, r: r.results["slip_arc_driver_rad"] / math.pi,
          "a stick arc at each entry sets the pulleys' speeds: near the whole wrap the belt "
          "slips (T_a near max_torque_Nm)", hi=CREEP_SHARE),
    Bound("the slack span's speed over its wave speed v / sqrt(T lambda / rhoA)", _slack_speed,
          "the belt presses on the pulleys with (T - rhoA v^2 / lambda) / R, which vanishes "
          "there: it lifts off", hi=SPEED_OVER_WAVE)))


def _bechtel(p):
    return SceneResult(True, "closed form per slip arc, installed mass by Brent's method "
                       f"(xtol {bechtel.XTOL_N:g} N)", bechtel.results(p))


#: the keys of the steady belt, with and without its inertia
STEADY = {
    "T_tight_N": nullable("tight-span tension, N"), "T_slack_N": nullable("slack-span tension, N"),
    "v_tight": nullable("tight-span speed (= omega R of the driver), m/s"),
    "v_slack": nullable("slack-span speed (= omega R of the driven pulley), m/s"),
    "slip_arc_driver_rad": nullable("slip arc on the driver, rad"),
    "slip_arc_driven_rad": nullable("slip arc on the driven pulley, rad"),
    "omega_ratio": nullable("omega_driven / omega_driver = v_slack / v_tight"),
    "max_torque_Nm": nullable("largest transmissible torque (slip over the whole wrap), N m")}

RESULTS = {**STEADY, "capstan": field("object", "the same keys with the belt's "
                                            "inertia neglected (capstan model)",
                                            keys=STEADY)}


REFERENCE = Scene(
    "bechtel", "Bechtel et al.'s steady extensible belt on two pulleys, stick and slip arcs "
    "(thesis 4.1; Model 2).", bechtel.PARAMS, _bechtel, results=RESULTS, warn=VALIDITY)
