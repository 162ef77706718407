"""The wrapped path of an open belt around two pulleys, and a belt laid on it.

Two pulleys (centres ``O1``, ``O2`` in m, radii ``R1``, ``R2`` in m, pulley 1 the
driver on the left in the thesis, Fig. 3.6) and the belt's centreline wrapped
around them on the outside: two arcs and the two external common tangents (the
spans).  With ``u`` the unit vector O1 -> O2, ``D = |O2 - O1|`` and
``c = (R1 - R2) / D``, the tangent points of a span lie along the outward unit
normal ``m = cos(a) u + sin(a) Ĩu`` with ``cos(a) = c`` (a < 0 below, a > 0 above),
because the span ``O2 + R2 m - O1 - R1 m`` must be perpendicular to ``m``.  Then

    span length  l_s = sqrt(D^2 - (R1 - R2)^2)
    wrap angles  theta1 = 2 pi - 2 acos(c),  theta2 = 2 acos(c)
    path length  P = 2 l_s + R1 theta1 + R2 theta2

(Table 3.1: l_s = 0.382882 m, P = 1.27627 m).  The path is traversed counter-
clockwise, starting at the point of pulley 1 farthest from pulley 2 (point A of
Fig. 3.4): around pulley 1's underside, along the lower span, around pulley 2,
back along the upper span.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np


def _turn(v):
    """Ĩ v: v turned by +90 degrees (Eq. 3.6); v (..., 2)."""
    return np.stack([-v[..., 1], v[..., 0]], -1)


@dataclass(frozen=True)
class TwoPulleyPath:
    """Open belt path around pulleys (O1, R1) and (O2, R2); lengths in m."""

    O1: tuple
    R1: float
    O2: tuple
    R2: float

    def __post_init__(self):
        D = self.centre_distance
        if D <= self.R1 + self.R2:
            raise ValueError(f"pulleys overlap: centre distance {D:g} m must exceed "
                             f"R1 + R2 = {self.R1 + self.R2:g} m")

    @property
    def centre_distance(self) -> float:
        return float(np.hypot(self.O2[0] - self.O1[0], self.O2[1] - self.O1[1]))

    @property
    def _frame(self):
        o1, o2 = np.asarray(self.O1, float), np.asarray(self.O2, float)
        u = (o2 - o1) / self.centre_distance
        return o1, o2, u, _turn(u)

    @property
    def span(self) -> float:
        """l_s, m."""
        return math.sqrt(self.centre_distance**2 - (self.R1 - self.R2) ** 2)

    @property
    def wrap(self) -> tuple:
        """Wrap angles (theta1, theta2), rad."""
        a = math.acos((self.R1 - self.R2) / self.centre_distance)
        return 2 * math.pi - 2 * a, 2 * a

    @property
    def length(self) -> float:
        """P, m."""
        t1, t2 = self.wrap
        return 2 * self.span + self.R1 * t1 + self.R2 * t2

    def _segments(self):
        """(kind, length, data) of the five pieces in traversal order."""
        o1, o2, u, w = self._frame
        a = math.acos((self.R1 - self.R2) / self.centre_distance)
        phi = math.atan2(u[1], u[0])
        m_low = math.cos(a) * u - math.sin(a) * w
        m_up = math.cos(a) * u + math.sin(a) * w
        t1, t2 = self.wrap
        half = math.pi - a  # from the far point of pulley 1 to either tangent point
        return [("arc", self.R1 * half, (o1, self.R1, phi + math.pi)),
                ("line", self.span, (o1 + self.R1 * m_low, o2 + self.R2 * m_low)),
                ("arc", self.R2 * t2, (o2, self.R2, phi - a)),
                ("line", self.span, (o2 + self.R2 * m_up, o1 + self.R1 * m_up)),
                ("arc", self.R1 * half, (o1, self.R1, phi + a))]

    def __call__(self, s):
        """Positions (n, 2) and unit tangents (n, 2) at arc lengths s (m, taken modulo P)."""
        s = np.mod(np.atleast_1d(np.asarray(s, dtype=float)), self.length)
        r, t = np.zeros((s.size, 2)), np.zeros((s.size, 2))
        start = 0.0
        for kind, length, data in self._segments():
            sel = (s >= start) & (s <= start + length + 1e-15)
            sl = s[sel] - start
            if kind == "arc":
                o, R, ang0 = data
                ang = ang0 + sl / R
                r[sel] = o + R * np.stack([np.cos(ang), np.sin(ang)], -1)
                t[sel] = np.stack([-np.sin(ang), np.cos(ang)], -1)
            else:
                p, q = data
                d = (q - p) / length
                r[sel] = p + sl[:, None] * d
                t[sel] = d
            start += length
        return r, t

    def pieces(self) -> list:
        """[(name, start arc length, end arc length)] of the pieces, m."""
        names = ("pulley 1", "lower span", "pulley 2", "upper span", "pulley 1")
        out, start = [], 0.0
        for name, (_, length, _) in zip(names, self._segments()):
            out.append((name, start, start + length))
            start += length
        return out


def laid_belt(path: TwoPulleyPath, L0: float, n_elements: int) -> np.ndarray:
    """Nodal coordinates (n_elements, 3, 2) = (r, r_x, r_y) of a closed belt of
    reference length ``L0`` (m) laid on ``path``: nodes at equal arc spacing P/n,
    r_x = t P / L0 (the stretch P/L0 of the straight reference elements, so a belt
    shorter than the path starts pre-tensioned), r_y = Ĩ t (unit, no shear)."""
    s = np.arange(n_elements) * path.length / n_elements
    r, t = path(s)
    return np.stack([r, t * (path.length / L0), _turn(t)], 1)
