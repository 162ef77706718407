"""``ancf analytic beam-modes``: a uniform beam's natural frequencies (Timoshenko and
Euler-Bernoulli)."""
from __future__ import annotations

import math

from analytic import beam_modes
from ancf.common.params import Param
from ancf.scenes.analytic.shared import (MIN_LENGTH_OVER_HEIGHT, SECTION, SHEAR_SHARE, Bound,
                                         Validity, count_param, magnitudes, shear_factor,
                                         with_defaults)
from ancf.scenes.base import NUM, Scene, SceneResult, field, nullable

#: its place in the list of references (ancf scenes, reports/schemas.md)
ORDER = 60


def _beta_h(p, r) -> float:
    """beta_n h of the highest mode n computed: its Euler-Bernoulli wave number beta_n
    (1/m, (beta_n L)^2 = omega_n / omega_0) times the section height."""
    I, A, _ = beam_modes.section(p["E"], p["nu"], p["h"], p["b"])
    w0 = beam_modes.scale(p["L"], p["E"], I, p["rho"], A)
    return math.sqrt(2.0 * math.pi * r.results["euler_bernoulli_hz"][-1] / w0) * p["h"] / p["L"]


def _eb_share(p, r) -> float:
    """First-order share of shear and rotary inertia in the highest mode, (beta_n h)^2
    (1 + E / (ks G)) / 24: Euler-Bernoulli's frequency above Timoshenko's by about it."""
    return _beta_h(p, r) ** 2 * (1.0 + 2.0 * (1.0 + p["nu"]) / p["ks"]) / 24.0


#: the range of validity (issue 33): Euler-Bernoulli's slenderness, Timoshenko's plane
#: sections over a half-wave, a rectangle's shear factor
VALIDITY = Validity((
    Bound("the Euler-Bernoulli shear and rotary-inertia share (beta_n h)^2 (1 + E / (ks G)) "
          "/ 24", _eb_share, "euler_bernoulli_hz neglects them: a slender beam", hi=SHEAR_SHARE),
    Bound("the highest mode's half-wave over the height pi / (beta_n h)",
          lambda p, r: math.pi / _beta_h(p, r), "plane sections over a half-wave, for "
          "frequencies_hz too", lo=MIN_LENGTH_OVER_HEIGHT),
    shear_factor()))


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


RESULTS = {
    "frequencies_hz": field("array", "Timoshenko natural frequencies (both spectra), "
                            "ascending, Hz", items=NUM),
    "euler_bernoulli_hz": field("array", "Euler-Bernoulli natural frequencies, ascending, Hz",
                                items=NUM),
    "cutoff_hz": nullable("the second spectrum's cut-off sqrt(ks G A / (rho I)) / (2 pi), "
                          "Hz")}


REFERENCE = Scene(
    "beam-modes", "Natural frequencies of a uniform beam, Timoshenko (both spectra) and "
    "Euler-Bernoulli, cantilever or simply supported; rectangular section h x b, "
    "G = E / (2 (1 + nu)).",
    (Param("support", "cantilever", str, doc="clamped-free or pinned-pinned",
           choices=beam_modes.SUPPORTS),)
    + with_defaults(SECTION, nu=0.3)
    + (Param("rho", 7850.0, float, "kg/m^3", "density", lo=0, lo_open=True), count_param(3)),
    _beam_modes,
    magnitudes(beam_modes.check_section, "E", "nu", "L", "h", "b", "rho", "ks"), results=RESULTS,
    warn=VALIDITY)
