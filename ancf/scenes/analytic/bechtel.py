"""``ancf analytic bechtel``: Bechtel et al.'s steady extensible belt on two pulleys."""
from __future__ import annotations

from analytic import bechtel
from ancf.scenes.base import Scene, SceneResult, field, nullable

#: its place in the list of references (ancf scenes, reports/schemas.md)
ORDER = 30


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
    "(thesis 4.1; Model 2).", bechtel.PARAMS, _bechtel, results=RESULTS)
