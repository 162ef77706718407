"""Acceptance checks of the 3D belt drive (thesis 4.6, Table 4.1, Figs 4.10-4.18) as
plain data, shared by ``tests/checks/test_belt3d_checks.py`` and the report chapter ``belt3d``.

Runs go through the scene's public interface, cached per process
(:func:`ancf.checks.belt2d.run`).  Model 2 is the scene's default (20 plates, 81 contact
points, dt 1e-4 s, t_end 1.2 s: the driver and the torque reach their final values at
1.0 s); its steady window is the scene's ``steady_window`` (the last 0.1 s).  The
tension that closes the torque balance is the membrane's own axial force (results
``tensions.membrane``); the three strain measures give k eps with k = E h w, as the
thesis evaluates Fig. 4.12.
"""
from __future__ import annotations

import numpy as np

from analytic import bechtel
from ancf.checks.belt2d import Check, _relative, run_json
from ancf.scenes import SCENES

MODEL1_RAMP = (0.05, 0.6)     # s, Table 4.1 t0, t1 of Model 1
THESIS_SLIP = 0.10            # Fig. 4.16: "approximately 10 % lower"
THESIS_GREEN_TORQUE = 1.4     # N m, the thesis' Green-measure torque (text below Fig. 4.15)
#: limits tied to today's accuracy (reports/belt3d.md): the torque balance is 3.54 % off and
#: Bechtel's span tensions 2.95 %, each limit 1.25 x that (rounded up); the slip is 0.06
#: points from the thesis' "approximately 10 %", read to half a point
TORQUE_TOL, BECHTEL_TOL, SLIP_TOL = 0.045, 0.037, 0.005
#: Model 1 at t_end: the smaller span membrane force at least 0.85 of the quasi-static
#: pre-tension E h w 2 u0 / (4 pi R) = 31.8 N of the driver's 2.5 mm shift (today 1.085:
#: 34.5 N; a shift the wrong way gives 0.61), and after 0.8 s the driven pulley within
#: 1 % of the driver (today 0.80 %; a shift the wrong way: 1.8 %)
MODEL1_TENSION_FRACTION, MODEL1_FOLLOW = 0.85, 0.01
POINTS = (25, 49, 81)
ELEMENTS = (20, 30, 40)
MEASURES = ("green", "true", "almansi", "membrane")

#: the acceptance rows (also the names the quick report skips)
STEADY = "Belt3d Model 2: steady driven speed over the last 0.1 s (spread < 0.5 %)"
TORQUE = "Belt3d Model 2: (T_tight − T_slack)·R of the membrane force = T_a within 4.5 %"
FRICTION = "Belt3d Model 2: moment of the friction forces on the driven pulley = T_a within 2 %"
MEASURES_ROW = "Belt3d Model 2: k ε torques below T_a, Green > true > Almansi (thesis: Green 1.4 N m)"
SLIP = "Belt3d Model 2: driven slip vs the thesis' FE ≈ 10 % (Fig. 4.16) within 0.5 points"
BECHTEL = "Belt3d Model 2: span membrane tensions within 3.7 % of Bechtel (full)"
MODEL1 = ("Belt3d Model 1: the driven pulley lags during the acceleration and follows after it "
          "(Fig. 4.10); the driver's shift (Eq. 4.46) keeps both spans tensioned")
POINTS_ROW = "Belt3d Model 2: 49 vs 81 contact points: driven speed and span tensions within 1 %"
ELEMENTS_ROW = "Belt3d Model 2: span tensions of 20 and 30 plates within 2 % of 40"
CHECK_NAMES = (STEADY, TORQUE, FRICTION, MEASURES_ROW, SLIP, BECHTEL, MODEL1, POINTS_ROW, ELEMENTS_ROW)


#: the Model 1 run (Fig. 4.10): 1 s, the step of the thesis's Model 1
MODEL1_RUN = {"model": 1, "t_end": 1.0, "dt": 2.5e-4}


def model2(**overrides) -> dict:
    """Results of a Model 2 run (default: the scene's defaults)."""
    return run_json("belt3d", **overrides)["results"]


def bechtel_params(p: dict) -> dict:
    """Bechtel's parameters for a belt3d parameter set (k = E h w, rhoA = rho h w)."""
    return {"k": p["E"] * p["h"] * p["width"], "R": p["R"], "omega": p["omega_final"],
            "mu": p["mu"], "T_i": p["T_i"], "T_a": p["Ta_max"],
            "rhoA": p["rho"] * p["h"] * p["width"]}


def analytic(capstan: bool = False) -> dict:
    """Bechtel's steady belt for the default Model 2 (JSON keys of ``ancf analytic bechtel``)."""
    p = SCENES["belt3d"].resolve({})
    b, top = bechtel.steady(bechtel_params(p), capstan)
    return bechtel.summary(b, top)


def steady_drift(r: dict, window: float = 0.1) -> float:
    """Relative spread (max - min) / mean of omega_driven over the last ``window`` s."""
    t, w = np.asarray(r["times"]), np.asarray(r["omega_driven"])
    sel = w[t >= t[-1] - window - 1e-12]
    return float((sel.max() - sel.min()) / sel.mean())


def comparison() -> list:
    """Rows (quantity, FE, Bechtel full, capstan) of the Model 2 table."""
    r, full, cap = model2(), analytic(), analytic(capstan=True)
    tn = r["tensions"]["membrane"]
    rows = [("T_tight_N (membrane)", tn["tight"], "T_tight_N"),
            ("T_slack_N (membrane)", tn["slack"], "T_slack_N"),
            ("v_tight", r["v_tight"], "v_tight"), ("v_slack", r["v_slack"], "v_slack"),
            ("driven slip", r["slip_driven"], None)]
    out = []
    for name, fe, key in rows:
        a = (lambda d: 1 - d["omega_ratio"]) if key is None else (lambda d, k=key: d[k])
        out.append((name, fe, a(full), a(cap)))
    return out


# ------------------------------------------------------------------ checks

def steady_state() -> Check:
    drift = steady_drift(model2())
    return Check(STEADY,
                 drift, 0.0, drift, 5e-3, "-", "(max − min)/mean of ω_driven over t_end − 0.1 s … t_end")


def torque_balance() -> Check:
    r = model2()
    T = r["torques_from_tensions_Nm"]["membrane"]
    Ta = SCENES["belt3d"].resolve({})["Ta_max"]
    return Check(TORQUE,
                 T, Ta, _relative(T, Ta), TORQUE_TOL, "N m",
                 "span means of the membrane's axial force at t_end; relative difference")


def friction_moment() -> Check:
    r = model2()
    Ta = SCENES["belt3d"].resolve({})["Ta_max"]
    T = r["torque_from_friction_Nm"]
    return Check(FRICTION, T, Ta, _relative(T, Ta), 0.02, "N m",
                 "Eq. 4.45's friction integrated over the driven pulley's contact, times the "
                 "lever, at t_end; relative difference")


def strain_measure_torques() -> Check:
    """The thesis: the Green measure gives 1.4 N m, the others even less (T_a = 2 N m)."""
    t = model2()["torques_from_tensions_Nm"]
    ok = t["green"] > t["true"] > t["almansi"] and t["green"] < t["membrane"]
    return Check(MEASURES_ROW, t["green"], THESIS_GREEN_TORQUE,
                 0.0 if ok else 1.0, 0.5, "N m",
                 "order of the strain-measure torques (difference 0 when Green > true > Almansi "
                 "and all below the membrane's); value: Green, reference: the thesis' 1.4 N m")


def slip_vs_thesis() -> Check:
    s = model2()["slip_driven"]
    return Check(SLIP, s, THESIS_SLIP, abs(s - THESIS_SLIP), SLIP_TOL, "-",
                 "1 − mean ω_driven/ω_driver over the last 0.1 s; absolute difference")


def tensions_vs_bechtel() -> Check:
    tn, full = model2()["tensions"]["membrane"], analytic()
    d = max(_relative(tn[s], full[f"T_{s}_N"]) for s in ("tight", "slack"))
    return Check(BECHTEL,
                 tn["slack"], full["T_slack_N"], d, BECHTEL_TOL, "N",
                 "largest relative difference of the tight and slack span means; value and "
                 "reference: the slack span")


def model1_lag() -> tuple:
    """(mean lag rad/s over the ramp, relative steady error after 0.8 s, the smaller span
    membrane force at t_end N, the quasi-static pre-tension N) of Model 1."""
    out = run_json("belt3d", **MODEL1_RUN)
    p, r = out["params"], out["results"]
    t, wd, wn = (np.asarray(r[k]) for k in ("times", "omega_driver", "omega_driven"))
    ramp = (t > MODEL1_RAMP[0]) & (t <= MODEL1_RAMP[1])
    late = t >= 0.8
    pre = p["E"] * p["h"] * p["width"] * 2 * p["u0"] / (4 * np.pi * p["R"])
    return (float(np.mean(wd[ramp] - wn[ramp])), float(np.mean(np.abs(wn[late] - wd[late])) / 12.0),
            min(r["tensions"]["membrane"].values()), float(pre))


def model1_check() -> Check:
    lag, late, T_min, pre = model1_lag()
    ok = lag > 0 and late < MODEL1_FOLLOW and T_min > MODEL1_TENSION_FRACTION * pre
    return Check(MODEL1, lag, 0.0, 0.0 if ok else 1.0, 0.5,
                 "rad/s", f"mean ω_driver − ω_driven over 0.05-0.6 s (value); after 0.8 s the "
                          f"mean |difference| is {100 * late:.2g} % of 12 rad/s (limit "
                          f"{100 * MODEL1_FOLLOW:g} %); "
                          f"smaller span force at t_end {T_min:.3g} N (limit "
                          f"{MODEL1_TENSION_FRACTION * pre:.3g} N)")


def points_spread(points=(49, 81)) -> float:
    """Largest relative difference of ω_driven (steady mean) and the membrane span tensions."""
    rs = [model2(contact_points=n) for n in points]
    w = [np.mean(np.asarray(r["omega_driven"])[-20:]) for r in rs]
    d = [_relative(w[0], w[1])]
    d += [_relative(rs[0]["tensions"]["membrane"][s], rs[1]["tensions"]["membrane"][s])
          for s in ("tight", "slack")]
    return max(d)


def points_check() -> Check:
    d = points_spread()
    return Check(POINTS_ROW, d, 0.0, d, 0.01, "-",
                 "largest relative difference of the steady ω_driven and the two span tensions")


def elements_spread() -> float:
    """Largest relative difference of the membrane span tensions of 20 and 30 plates from 40."""
    rs = {n: model2(n_elements=n)["tensions"]["membrane"] for n in ELEMENTS}
    return max(_relative(rs[n][s], rs[ELEMENTS[-1]][s]) for n in ELEMENTS[:-1]
               for s in ("tight", "slack"))


def elements_check() -> Check:
    d = elements_spread()
    return Check(ELEMENTS_ROW, d, 0.0, d,
                 0.02, "-", "largest relative difference of the membrane span tensions")


CHEAP = (steady_state, torque_balance, friction_moment, strain_measure_torques, slip_vs_thesis,
         tensions_vs_bechtel, model1_check)
COSTLY = (points_check, elements_check)
