"""Lateral walk of a flat belt on a pulley whose axis is tilted: the first-order kinematic
reference for the plate belt's tracking (ancf/belts/tracking3d.py, issue 36 item 4).

The rule (Shelton's "normal entry"; Swift).  Where the belt meets a pulley's surface it
moves with it, so it keeps the direction of travel it has there.  A pulley whose axis is
tilted by theta (rad) toward the entering span, in that span's plane, has at the tangent
point a surface velocity v (cos theta d - sin theta e_z): seen along the axis, a belt
arriving along d (square to the untilted axis) meets a surface that carries it axially, and
its entry point walks along the axis at

    dz/dt = v tan(theta)                 (free entering span; the classic rule)       (1)

(v the belt speed, m/s; z the entry point's offset along the axis, m, toward the end of the
face the entering belt reaches first; tan against tracking3d's sin: 1.5e-4 relative at 1
deg).  On a closed belt the entering span's other end is held laterally by the previous
pulley (its own entry rule keeps it there).  The span, a taut string of length L (m) with
no edgewise stiffness, then runs from offset 0 to offset z and so is inclined by z / L to
d, toward the side the entry point walked to: the belt meets the surface turned by that
angle against the tilt, and to first order in theta and z / L

    dz/dt = v (tan(theta) - z / L)                                                    (2)

In the belt's travelled distance x(t) = int v dt (m; any speed history, e.g. a ramp):

    z(x) = L tan(theta) (1 - exp(-x / L))                                             (3)
    e_lat(x) = dz/dx = tan(theta) exp(-x / L)                                         (4)

z walks at v tan(theta) at first (Eq. 1) and settles at the offset L tan(theta) over a
few span lengths of travel; e_lat is the entering belt's lateral direction component at
the entry measured in the pulley's frame.  Left out: the span's edgewise bending (its
in-plane stiffness against the tension spreads the turn over a length sqrt(EI_w / T) at
each end), the belt's slip on the wrap, the walk of the previous pulley's own entry point.
"""
from __future__ import annotations

import math

import numpy as np

from analytic import _checks

#: the largest |tilt| accepted, deg: the first-order model is for small misalignments
TILT_MAX_DEG = 10.0


def _tilt(tilt_deg) -> float:
    """tan(theta) of ``tilt_deg`` (deg), else ValueError naming it and its range."""
    a = _checks.finite("tilt_deg", tilt_deg)
    if abs(a) > TILT_MAX_DEG:
        raise ValueError(f"tilt_deg = {tilt_deg!r} is out of range; allowed: a number in "
                         f"[-{TILT_MAX_DEG:g}, {TILT_MAX_DEG:g}]")
    return math.tan(math.radians(a))


def _travel(travel_m) -> np.ndarray:
    """``travel_m`` as a float array of finite values >= 0, else ValueError naming it."""
    try:
        x = np.asarray(travel_m, dtype=float)
    except (TypeError, ValueError):
        raise ValueError(f"travel_m must be real numbers (got {travel_m!r})") from None
    if not np.all(np.isfinite(x)) or np.any(x < 0):
        raise ValueError(f"travel_m must be finite and >= 0 (got {travel_m!r})")
    return x


def _span(span_m) -> float:
    """``span_m`` as a float > 0 (math.inf allowed), else ValueError naming it."""
    if isinstance(span_m, (int, float)) and span_m == math.inf:
        return math.inf
    return _checks.positive("span_m", span_m)


def entry_offset(travel_m, span_m, tilt_deg):
    """z (m) of Eq. 3: the entry point's offset along the axis after the belt has travelled
    ``travel_m`` (m, >= 0; scalar or array) from z = 0, on a pulley tilted by ``tilt_deg``
    (deg, |.| <= 10) whose entering span is ``span_m`` long (m, > 0; math.inf: the free
    span of Eq. 1, z = x tan(theta))."""
    x, tan = _travel(travel_m), _tilt(tilt_deg)
    L = _span(span_m)
    if math.isinf(L):
        return x * tan
    return L * tan * -np.expm1(-x / L)


def entry_direction(travel_m, span_m, tilt_deg):
    """e_lat of Eq. 4: the entering belt's direction at the entry relative to the pulley's
    surface velocity, along the axis (rad, first order), after ``travel_m`` (m); the other
    arguments as :func:`entry_offset`."""
    x, tan = _travel(travel_m), _tilt(tilt_deg)
    return tan * np.exp(-x / _span(span_m))
