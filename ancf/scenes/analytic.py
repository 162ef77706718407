"""The analytic references (:mod:`analytic`) exposed like scenes: ``ancf analytic NAME``."""
from __future__ import annotations

import math

import numpy as np

from analytic import (beam_modes, bechtel, belt_steady, moving_string, navier_plate, plate_modes,
                      reissner, timoshenko)
from analytic.dynamics_refs import rigid_pendulum, spinning_extension
from ancf.common.inputs import check_sampling, following, intervals
from ancf.common.params import InputError, Param
from ancf.scenes.base import Scene, SceneResult

_SECTION = (
    Param("E", 2.07e11, float, "Pa", "Young's modulus", lo=0, lo_open=True),
    Param("nu", 0.0, float, "-", "Poisson's ratio", lo=0, hi=0.5, hi_open=True),
    Param("L", 2.0, float, "m", "beam length", lo=0, lo_open=True),
    Param("h", 0.1, float, "m", "section height", lo=0, lo_open=True),
    Param("b", 0.1, float, "m", "section width", lo=0, lo_open=True),
    Param("ks", 5.0 / 6.0, float, "-", "shear correction factor", lo=0, lo_open=True, hi=2),
)


def _timoshenko(p):
    w = timoshenko.mid_deflection(p["E"], p["nu"], p["L"], p["h"], p["b"], p["F"], ks=p["ks"])
    return SceneResult(True, "closed form: " + timoshenko.closed_form_text(), {"mid_deflection_m": w})


def _reissner(p):
    r = reissner.tip_position(p["E"], p["nu"], p["L"], p["h"], p["b"], p["F"], ks=p["ks"])
    return SceneResult(r.converged, r.message,
                       {"tip_x": r.tip_x, "tip_y": r.tip_y, "tip_rotation_rad": r.tip_rotation},
                       extra={"solution": r})


def _bechtel(p):
    return SceneResult(True, "closed form per slip arc, installed mass by Brent's method "
                       f"(xtol {bechtel.XTOL_N:g} N)", bechtel.results(p))


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


def _belt_steady(p):
    pulleys = _three_pulleys(p)
    L0 = belt_steady.path_length(pulleys) / (1.0 + p["T_i"] / p["EA"])
    return SceneResult(True, "closed form per creep arc, n_t by Brent's method (xtol "
                       f"{belt_steady.XTOL_N:g} N)" + (", the arm's moment balance by Brent's "
                       f"method (xtol {belt_steady.XTOL_PSI:g} rad)"
                       if p["law3"] == "tensioner" else ""),
                       belt_steady.solve(pulleys, EA=p["EA"], rhoA=p["rhoA"], L0=L0, mu=p["mu"]))


def _navier(p):
    w, N = navier_plate.centre_deflection(p["a"], p["b"], p["h"], p["E"], p["nu"], p["p"],
                                          rtol=p["rtol"])
    return SceneResult(True, f"Navier's double series summed in closed form over one index "
                       f"(Levy's single series): {N} term(s) of the correction series along the "
                       f"shorter side (tail bound below rtol = {p['rtol']:g})",
                       {"center_deflection_m": w, "terms": N})


def _beam_modes(p):
    I, A, G = beam_modes.section(p["E"], p["nu"], p["h"], p["b"])
    beam = dict(L=p["L"], E=p["E"], I=I, rho=p["rho"], A=A)
    f = beam_modes.timoshenko(p["support"], G=G, ks=p["ks"], count=p["count"], **beam)
    eb = beam_modes.euler_bernoulli(p["support"], count=p["count"], **beam)
    r2, e = beam_modes.groups(p["L"], p["E"], G, I, A, p["ks"])
    method = ("the determinant of the boundary conditions, scanned and refined by Brent's "
              "method" if p["support"] == "cantilever" else "the closed form per mode number")
    return SceneResult(True, f"Timoshenko: {method}; Euler-Bernoulli: roots of the frequency "
                       "equation (Brent's method)",
                       {"frequencies_hz": f.tolist(), "euler_bernoulli_hz": eb.tolist(),
                        "cutoff_hz": beam_modes.cutoff(r2, e) * beam_modes.scale(**beam)
                        / (2.0 * math.pi)})


def _plate_modes(p):
    f, mn = plate_modes.navier_frequencies(p["a"], p["b"], p["h"], p["E"], p["nu"], p["rho"],
                                           count=p["count"])
    return SceneResult(True, "Navier: omega_mn = pi^2 (m^2/a^2 + n^2/b^2) sqrt(D / (rho h))",
                       {"frequencies_hz": f.tolist(), "m": [m for m, _ in mn],
                        "n": [n for _, n in mn]})


def _moving_string(p):
    f = moving_string.span_frequencies(p["T"], p["rho_A"], p["v"], p["L"], count=p["count"])
    c = moving_string.wave_speed(p["T"], p["rho_A"], p["L"])
    return SceneResult(True, "f_n = n c (1 - v^2/c^2) / (2 L), c = sqrt(T / rho_A)",
                       {"frequencies_hz": f.tolist(), "wave_speed_m_s": c})


def _magnitudes(check, *fields):
    """A scene check: ``check(*p[fields])`` with its ValueError (a derived quantity out of
    double precision, the field named) as InputError."""
    def run(p):
        try:
            check(*(p[f] for f in fields))
        except ValueError as exc:
            raise InputError(str(exc)) from None
    return run


def _extension(p):
    al = math.sqrt(p["rho"] / p["E"]) * p["omega_s"] * p["L"]
    if al >= math.pi / 2:
        return SceneResult(False, f"a l = {al:.4g} >= pi/2: no steady state (resonance of the "
                           "axial mode)", {"axial_extension_m": None, "al": al,
                                           "axial_extension_thesis_m": None})
    u = spinning_extension(p["L"], p["E"], p["rho"], p["omega_s"])
    # the thesis's printed 1.09545e-4 m: rho A with Wu & Haug's tabulated area, E A with b h
    ut = spinning_extension(p["L"], p["E"], p["rho"] * p["A_mass"] / (p["b"] * p["h"]), p["omega_s"])
    return SceneResult(True, "closed form (thesis Eq. 2.36)",
                       {"axial_extension_m": u, "al": al, "axial_extension_thesis_m": ut})


def _rigid(p):
    n = intervals(p["t_end"], p["output_dt"])
    t = np.minimum(np.arange(n + 1) * p["output_dt"], p["t_end"])
    try:
        th, x, y = rigid_pendulum(p["L"], p["g"], t, p["h"])
    except FloatingPointError as exc:
        return SceneResult(False, str(exc), {"times": t.tolist(), "theta": None, "tip_x": None,
                                             "tip_y": None})
    return SceneResult(True, "theta'' = -(g L / 2) cos(theta) / (L^2/3 + h^2/12), DOP853 rtol 1e-12",
                       {"times": t.tolist(), "theta": th.tolist(), "tip_x": x.tolist(),
                        "tip_y": y.tolist()})


_NAVIER = (
    Param("a", 1.0, float, "m", "plate side along x", lo=0, lo_open=True, hi=1e3),
    Param("b", 1.0, float, "m", "plate side along y", lo=0, lo_open=True, hi=1e3),
    Param("h", 0.01, float, "m", "thickness", lo=0, lo_open=True, hi=1e2),
    Param("E", 2.1e11, float, "Pa", "Young's modulus", lo=0, lo_open=True),
    Param("nu", 0.3, float, "-", "Poisson's ratio", lo=0, hi=0.5, hi_open=True),
    Param("p", 1e3, float, "Pa", "uniform pressure (deflection positive along it)", lo=-1e12, hi=1e12),
    Param("rtol", 1e-10, float, "-", "relative truncation tolerance of the series", lo=1e-14, hi=1e-2),
)


def _count(default):
    return Param("count", default, int, "-", "number of frequencies (the lowest, ascending)",
                 lo=1, hi=100)


#: thesis Table 3.1 (as ancf.scenes.belt_common, not imported here: it loads the belt drive):
#: belt density (kg/m^3) and section (m), pulley radius (m), pulley centres at +-X_CENTRE (m)
_TABLE_3_1 = dict(rho=1036.0, h=0.01, b=0.01, R=0.08125, X_CENTRE=0.191441)
_STRING = (
    Param("T", 100.0, float, "N", "span tension", lo=0, lo_open=True),
    Param("rho_A", _TABLE_3_1["rho"] * _TABLE_3_1["h"] * _TABLE_3_1["b"], float, "kg/m",
          "mass per unit length (default: the thesis's belt, Table 3.1)", lo=0, lo_open=True),
    Param("v", 120.0 * _TABLE_3_1["R"], float, "m/s", "belt speed (default: 120 rad/s on the "
          "driver, thesis Figs 3.10-3.20); |v| below the wave speed sqrt(T / rho_A)"),
    Param("L", 2.0 * _TABLE_3_1["X_CENTRE"], float, "m", "span length (default: the centre "
          "distance of the thesis's equal pulleys)", lo=0, lo_open=True),
    _count(3),
)

_M = dict(lo=-10.0, hi=10.0)  # m, a layout's coordinates
_BELT_STEADY = (
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


def _with(params, **defaults):
    return tuple(Param(p.name, defaults.get(p.name, p.default), p.kind, p.unit, p.doc, p.lo, p.hi,
                       p.lo_open, p.hi_open, p.choices) for p in params)


REFERENCES = {
    "timoshenko": Scene(
        "timoshenko", "Simply supported Timoshenko beam, midspan load (SymPy-derived).",
        _SECTION + (Param("F", -1000.0, float, "N", "vertical midspan force"),), _timoshenko,
        _magnitudes(timoshenko.check_magnitudes, "E", "nu", "L", "h", "b", "F", "ks")),
    "reissner": Scene(
        "reissner", "Geometrically exact (Reissner) cantilever, dead tip load (BVP, scipy).",
        _with(_SECTION, nu=0.3) + (Param("F", lambda v: -5e8 * v["h"] ** 3, float, "N",
                                         "vertical tip force (default -5e8 h^3)"),), _reissner),
    "bechtel": Scene(
        "bechtel", "Bechtel et al.'s steady extensible belt on two pulleys, stick and slip arcs "
        "(thesis 4.1; Model 2).", bechtel.PARAMS, _bechtel),
    "belt-steady": Scene(
        "belt-steady", "Steady extensible belt (Bechtel's model) on N pulleys, here three: a "
        "driver, an idler or tensioner on its slack span and a driven pulley; span tensions "
        "and speeds, per pulley creep and stick arcs, slip, torque and a tensioner's angle "
        "(any layout: analytic.belt_steady.solve).", _BELT_STEADY, _belt_steady),
    "navier-plate": Scene(
        "navier-plate", "Simply supported Kirchhoff plate under uniform pressure: Navier series "
        "centre deflection, summed as Levy's single series; 'terms' counts its correction "
        "terms (D = E h^3 / (12 (1 - nu^2))).", _NAVIER, _navier,
        _magnitudes(navier_plate.check_magnitudes, "a", "b", "h", "E", "nu", "p")),
    "beam-modes": Scene(
        "beam-modes", "Natural frequencies of a uniform beam, Timoshenko (both spectra) and "
        "Euler-Bernoulli, cantilever or simply supported; rectangular section h x b, "
        "G = E / (2 (1 + nu)).",
        (Param("support", "cantilever", str, doc="clamped-free or pinned-pinned",
               choices=beam_modes.SUPPORTS),)
        + _with(_SECTION, nu=0.3)
        + (Param("rho", 7850.0, float, "kg/m^3", "density", lo=0, lo_open=True), _count(3)),
        _beam_modes,
        _magnitudes(beam_modes.check_section, "E", "nu", "L", "h", "b", "rho", "ks")),
    "plate-modes": Scene(
        "plate-modes", "Natural frequencies of the simply supported Kirchhoff plate (Navier), "
        "with their half-wave numbers m (along a) and n (along b).",
        tuple(p for p in _NAVIER if p.name not in ("p", "rtol"))
        + (Param("rho", 7850.0, float, "kg/m^3", "density", lo=0, lo_open=True), _count(4)),
        _plate_modes,
        _magnitudes(plate_modes.check_magnitudes, "a", "b", "h", "E", "nu", "rho")),
    "moving-string": Scene(
        "moving-string", "Transverse frequencies of an axially moving string span between "
        "fixed guides (the belt's free span).", _STRING, _moving_string,
        _magnitudes(moving_string.check_speed, "T", "rho_A", "v", "L")),
}

DYNAMIC_REFERENCES = {
    "spinning-extension": Scene(
        "spinning-extension", "Steady axial extension of a spinning beam (thesis Eq. 2.36).",
        (Param("L", 8.0, float, "m", "beam length", lo=0, lo_open=True),
         Param("E", 6.895e10, float, "Pa", "Young's modulus", lo=0, lo_open=True),
         Param("rho", 2766.67, float, "kg/m^3", "density", lo=0, lo_open=True),
         Param("omega_s", 4.0, float, "rad/s", "steady angular velocity", lo=0),
         Param("b", 1.986e-3, float, "m", "section width (thesis)", lo=0, lo_open=True),
         Param("h", 3.675e-2, float, "m", "section height (thesis)", lo=0, lo_open=True),
         Param("A_mass", 7.2968e-5, float, "m^2",
               "area in rho A of the thesis variant (Wu & Haug's tabulated A)", lo=0, lo_open=True)),
        _extension),
    "rigid-pendulum": Scene(
        "rigid-pendulum", "Rigid compound pendulum released horizontally (numerical, rtol 1e-12).",
        (Param("L", 2.0, float, "m", "length", lo=0, lo_open=True),
         Param("g", 9.81, float, "m/s^2", "gravitational acceleration", lo=0),
         Param("h", 0.0, float, "m", "section height (0: slender rod, the stated reference)", lo=0),
         Param("t_end", 1.0, float, "s", "simulated time", lo=0, lo_open=True, hi=1e4),
         Param("output_dt", following(0.01, "t_end"), float, "s",
               "sampling interval (default 0.01 s, at most t_end)", lo=0, lo_open=True, hi=10)),
        _rigid, check_sampling),
}

REFERENCES.update(DYNAMIC_REFERENCES)
