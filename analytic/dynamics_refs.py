"""Analytic references of the dynamic examples (``ancf analytic`` exposes them:
:mod:`ancf.scenes.analytic`).

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


def spinning_extension(L: float, E: float, rho: float, omega_s: float) -> float:
    """Eq. 2.36, m (0 at rest: tan(a l) / (a l) -> 1)."""
    al = math.sqrt(rho / E) * omega_s * L
    return L * (math.tan(al) / al - 1.0) if al else 0.0


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
