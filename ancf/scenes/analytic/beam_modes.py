"""``ancf analytic beam-modes``: a uniform beam's natural frequencies (Timoshenko and
Euler-Bernoulli)."""
from __future__ import annotations

import math

from analytic import beam_modes
from ancf.common.params import Param
from ancf.scenes.analytic.shared import SECTION, count_param, magnitudes, with_defaults
from ancf.scenes.base import NUM, Scene, SceneResult, field, nullable

#: its place in the list of references (ancf scenes, reports/schemas.md)
ORDER = 60


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
    magnitudes(beam_modes.check_section, "E", "nu", "L", "h", "b", "rho", "ks"), results=RESULTS)
