"""Analytic references of the dynamic examples, exposed like scenes.

* ``spinning-extension``: steady axial extension of a beam spinning at omega_s about
  one end (thesis Eqs 2.36-2.37): ``u_x = l (tan(a l)/(a l) - 1)``,
  ``a = sqrt(rho A / (E A)) omega_s``; 1.09572e-4 m for the thesis data.  The
  thesis prints 1.09545e-4 m, which this formula gives (1.095456e-4) only when
  rho A uses Wu & Haug's tabulated A = 7.2968e-5 m^2 and E A uses b h =
  7.29855e-5 m^2; that variant is ``axial_extension_thesis_m``.
* ``rigid-pendulum``: rigid compound pendulum pinned at one end, released from
  rest horizontally: ``theta'' = -(g L/2) cos(theta) / (L^2/3 + h^2/12)``, i.e.
  ``-(3 g / (2 L)) cos(theta)`` for the slender rod (h = 0, the default); solved
  with DOP853 at rtol 1e-12; tip ``L (cos theta, sin theta)`` on the output grid.
"""
from __future__ import annotations

import math

import numpy as np
from scipy.integrate import solve_ivp

from ancf.inputs import check_sampling, following, intervals
from ancf.scenes.base import Param, Scene, SceneResult


def spinning_extension(L: float, E: float, rho: float, omega_s: float) -> float:
    """Eq. 2.36, m (0 at rest: tan(a l) / (a l) -> 1)."""
    al = math.sqrt(rho / E) * omega_s * L
    return L * (math.tan(al) / al - 1.0) if al else 0.0


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


def rigid_pendulum(L: float, g: float, t, h: float = 0.0):
    """(theta, tip_x, tip_y) at times t of the pendulum released horizontally."""
    c = 0.5 * g * L / (L * L / 3.0 + h * h / 12.0)
    t = np.asarray(t, dtype=float)
    sol = solve_ivp(lambda _, y: [y[1], -c * math.cos(y[0])], (0.0, float(t[-1])), [0.0, 0.0],
                    method="DOP853", t_eval=t, rtol=1e-12, atol=1e-14)
    if not sol.success:
        raise FloatingPointError(f"DOP853 failed: {sol.message}")
    th = sol.y[0]
    return th, L * np.cos(th), L * np.sin(th)


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
