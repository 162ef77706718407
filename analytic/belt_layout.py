"""The wrapped path of a flat belt around N pulleys in belt order, for the steady
reference :mod:`analytic.belt_steady` (written apart from ``ancf.belts``, which it checks).

Pulley i has a centre c_i (m), a radius r_i (m) and a side sigma_i: +1 when the belt's
inner side runs on it, -1 for an idler on the belt's back.  The belt runs from pulley i
to pulley i + 1 (the last to the first).  Traversed with orientation o (+1 counter-
clockwise), pulley i turns with sense s_i = o sigma_i (+1 counter-clockwise).  With d the
belt's unit direction on a span and m = -Ĩ d its right-hand normal (Ĩ: a turn by +90
degrees), the belt touches pulley i at c_i + r_i s_i m, so the span from pulley i to
pulley k is the common tangent with

    Delta . m = rho,   rho = s_i r_i - s_k r_k,   Delta = c_k - c_i,   D = |Delta|,
    m = (rho / D) u - sqrt(1 - rho^2 / D^2) Ĩ u,   u = Delta / D,   d = Ĩ m,

of length l = sqrt(D^2 - rho^2): the external tangent where the senses agree, the internal
one (crossing the centre line) where they differ.  The wrap angle theta_i (rad) is the turn
from the entry normal to the exit normal in the sense s_i, in [0, 2 pi).  The orientation o
is given (the driver's sense of rotation sets it: the same pulleys and sides may close
either way).  The belt closes when its turns add up to one revolution, sum sigma_i theta_i
= 2 pi, and is simple when no span cuts a pulley or crosses another span.  Path length
P = sum l + sum r theta.  Crossed belts (a figure eight, turning number 0) are not such a
loop.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ancf.common.params import InputError

#: relative tolerance of the one-revolution test and of a span grazing a pulley
GEOMETRY_RTOL = 1e-9


def turn(v: np.ndarray) -> np.ndarray:
    """Ĩ v: v turned by +90 degrees; v (2,)."""
    return np.array([-v[1], v[0]])


@dataclass(frozen=True)
class Layout:
    """The wrapped path: per span j (pulley j to j + 1) the direction ``d[j]``, length
    ``span[j]`` (m), end points ``start[j]``, ``end[j]`` (m); per pulley the sense
    ``sense[i]`` (+1 counter-clockwise) and wrap ``wrap[i]`` (rad)."""

    centres: np.ndarray
    radii: np.ndarray
    sense: np.ndarray
    d: np.ndarray
    span: np.ndarray
    start: np.ndarray
    end: np.ndarray
    wrap: np.ndarray

    @property
    def length(self) -> float:
        """Path length P, m."""
        return float(self.span.sum() + self.radii @ self.wrap)


def _tangents(c, r, s):
    """(m, span length) of every span for the senses s."""
    N = len(r)
    m, span = np.zeros((N, 2)), np.zeros(N)
    for j in range(N):
        k = (j + 1) % N
        delta = c[k] - c[j]
        D = math.hypot(*delta)
        u, rho = delta / D, s[j] * r[j] - s[k] * r[k]
        m[j] = (rho / D) * u - math.sqrt(1.0 - (rho / D) ** 2) * turn(u)
        span[j] = math.sqrt(D * D - rho * rho)
    return m, span


def _wraps(m, s):
    """theta_i in [0, 2 pi): the turn from m[i - 1] to m[i] in the sense s_i, rad."""
    m_in = np.roll(m, 1, axis=0)
    ang = np.arctan2(m_in[:, 0] * m[:, 1] - m_in[:, 1] * m[:, 0], np.sum(m_in * m, axis=1))
    return np.mod(s * ang, 2 * math.pi)


def _check_overlaps(c, r, names):
    for i in range(len(r)):
        for k in range(i + 1, len(r)):
            D = math.hypot(*(c[k] - c[i]))
            if D <= r[i] + r[k]:
                raise InputError(f"pulleys {names[i]!r} and {names[k]!r} overlap: centre "
                                 f"distance {D:.6g} m; allowed: more than the sum of their "
                                 f"radii, {r[i] + r[k]:.6g} m")


def _negative_wrap(lay: Layout, sides, names) -> InputError | None:
    """The pulley whose wrap, taken negative (theta - 2 pi), would close the path."""
    excess = sides @ lay.wrap - 2 * math.pi
    for i in np.argsort(2 * math.pi - lay.wrap):  # the smallest negative wrap first
        if abs(excess - sides[i] * 2 * math.pi) <= GEOMETRY_RTOL * 2 * math.pi:
            return InputError(
                f"pulley {names[i]!r} cannot be wrapped: the belt would turn the other way "
                f"round it (wrap {lay.wrap[i] - 2 * math.pi:.6g} rad); allowed: a wrap > 0 "
                "(move it, or change its side)")
    return None


def _cross(a, b, p, q) -> bool:
    """Segments ab and pq cross (each one's ends strictly on either side of the other)."""
    def side(u, v, w):  # the sign of (v - u) x (w - u)
        return (v[0] - u[0]) * (w[1] - u[1]) - (v[1] - u[1]) * (w[0] - u[0])
    return side(a, b, p) * side(a, b, q) < 0 and side(p, q, a) * side(p, q, b) < 0


def _not_simple(lay: Layout, names) -> InputError | None:
    """A span through a pulley other than its two ends, or two spans that cross."""
    N = len(names)
    for j in range(N):
        for q in set(range(N)) - {j, (j + 1) % N}:
            t = np.clip((lay.centres[q] - lay.start[j]) @ lay.d[j], 0.0, lay.span[j])
            gap = math.hypot(*(lay.start[j] + t * lay.d[j] - lay.centres[q]))
            if gap < lay.radii[q] * (1 - GEOMETRY_RTOL):
                return InputError(f"pulley {names[q]!r} cuts the span from {names[j]!r} to "
                                  f"{names[(j + 1) % N]!r} (its centre {gap:.6g} m from the "
                                  f"span, radius {lay.radii[q]:.6g} m); allowed: pulleys clear "
                                  "of the spans, in belt order")
        for k in range(j + 2, N - (j == 0)):
            if _cross(lay.start[j], lay.end[j], lay.start[k], lay.end[k]):
                return InputError(f"the spans from {names[j]!r} and from {names[k]!r} cross; "
                                  "allowed: a belt that does not cross itself, pulleys in belt "
                                  "order")
    return None


def wrap(centres, radii, sides, names, o: int) -> Layout:
    """The wrapped path of pulleys (centres (N, 2) m, radii (N,) m, sides +1 / -1) in belt
    order, traversed with orientation o (+1 counter-clockwise); InputError naming the
    pulley for overlaps, an unwrappable pulley, a span through a pulley or crossing spans."""
    c, r = np.asarray(centres, float), np.asarray(radii, float)
    sides = np.asarray(sides, float)
    _check_overlaps(c, r, names)
    s = o * sides
    m, span = _tangents(c, r, s)
    start = c + (r * s)[:, None] * m
    end = np.roll(c, -1, axis=0) + np.roll(r * s, -1)[:, None] * m
    lay = Layout(c, r, s, np.stack([turn(v) for v in m]), span, start, end, _wraps(m, s))
    if abs(sides @ lay.wrap - 2 * math.pi) > GEOMETRY_RTOL * 2 * math.pi:
        raise _negative_wrap(lay, sides, names) or InputError(
            "pulleys: the belt does not form a simple loop through the pulleys in this order "
            "with these sides and the driver's sense (crossed belts are not supported)")
    bad = _not_simple(lay, names)
    if bad:
        raise bad
    return lay
