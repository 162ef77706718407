"""Analytic references exposed like scenes (``ancf analytic NAME``)."""
from __future__ import annotations

from analytic import bechtel, navier_plate, reissner, timoshenko
from ancf.scenes.base import Param, Scene, SceneResult

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


def _navier(p):
    w, N = navier_plate.centre_deflection(p["a"], p["b"], p["h"], p["E"], p["nu"], p["p"],
                                          rtol=p["rtol"])
    return SceneResult(True, f"Navier double series, odd indices up to {N} (tail bound below "
                       f"rtol = {p['rtol']:g})", {"center_deflection_m": w, "terms": N})


_NAVIER = (
    Param("a", 1.0, float, "m", "plate side along x", lo=0, lo_open=True, hi=1e3),
    Param("b", 1.0, float, "m", "plate side along y", lo=0, lo_open=True, hi=1e3),
    Param("h", 0.01, float, "m", "thickness", lo=0, lo_open=True, hi=1e2),
    Param("E", 2.1e11, float, "Pa", "Young's modulus", lo=0, lo_open=True),
    Param("nu", 0.3, float, "-", "Poisson's ratio", lo=0, hi=0.5, hi_open=True),
    Param("p", 1e3, float, "Pa", "uniform pressure (deflection positive along it)", lo=-1e12, hi=1e12),
    Param("rtol", 1e-10, float, "-", "relative truncation tolerance of the series", lo=1e-14, hi=1e-2),
)


def _with(params, **defaults):
    return tuple(Param(p.name, defaults.get(p.name, p.default), p.kind, p.unit, p.doc, p.lo, p.hi,
                       p.lo_open, p.hi_open, p.choices) for p in params)


REFERENCES = {
    "timoshenko": Scene(
        "timoshenko", "Simply supported Timoshenko beam, midspan load (SymPy-derived).",
        _SECTION + (Param("F", -1000.0, float, "N", "vertical midspan force"),), _timoshenko),
    "reissner": Scene(
        "reissner", "Geometrically exact (Reissner) cantilever, dead tip load (BVP, scipy).",
        _with(_SECTION, nu=0.3) + (Param("F", lambda v: -5e8 * v["h"] ** 3, float, "N",
                                         "vertical tip force (default -5e8 h^3)"),), _reissner),
    "bechtel": Scene(
        "bechtel", "Bechtel et al.'s steady extensible belt on two pulleys, stick and slip arcs "
        "(thesis 4.1; Model 2).", bechtel.PARAMS, _bechtel),
    "navier-plate": Scene(
        "navier-plate", "Simply supported Kirchhoff plate under uniform pressure: Navier series "
        "centre deflection (D = E h^3 / (12 (1 - nu^2))).", _NAVIER, _navier),
}

from analytic.dynamics_refs import DYNAMIC_REFERENCES  # noqa: E402  (imports Scene from above)

REFERENCES.update(DYNAMIC_REFERENCES)
