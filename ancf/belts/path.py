"""The wrapped path of a closed belt around an ordered sequence of pulleys, and a belt
laid on it.

Pulley k has centre c_k (m), radius r_k (m) and a side s_k: +1 when the belt's inner
side runs on it (the pulley inside the loop), -1 when the belt's back does (an idler
pressing on the loop from outside).  The belt runs counter-clockwise through the pulleys
in their order, wrapping each counter-clockwise (s = +1) or clockwise (s = -1); with the
signed radius rho_k = s_k r_k every tangent point is c_k + rho_k n, n the unit normal of
the span to the right of the running direction.

The span from pulley i to the next one j is their common tangent: external when
s_i = s_j, internal when the sides differ.  With lo, hi the lower and the higher of the
two indices, u the unit vector c_lo -> c_hi (polar angle phi), D = |c_hi - c_lo|,
c = (rho_lo - rho_hi) / D and a = acos(c), the span c_j + rho_j n - c_i - rho_i n must
be perpendicular to n, which gives

    n = cos(a) u + sigma sin(a) Ĩu,   sigma = -1 from lo to hi, +1 from hi to lo
    span length  l = sqrt(D^2 - (rho_lo - rho_hi)^2)

(Ĩ turns by +90 degrees, Eq. 3.6).  The polar angle of n is phi + sigma a; the wrap
angle of pulley k between its incoming and outgoing spans is

    theta_k = s_k ((phi_out - phi_in) + (sigma_out a_out - sigma_in a_in))  mod 2 pi

and the path length P = sum l + sum r_k theta_k.  The path starts in the middle of
pulley 0's wrap (for two pulleys the point of pulley 1 farthest from pulley 2, point A of
Fig. 3.4), runs along span 0 -> 1, around pulley 1, ..., along span N-1 -> 0 and back
over the other half of pulley 0.  For two pulleys on the inner side (Fig. 3.6, Table
3.1: l = 0.382882 m, P = 1.27627 m) this is the arithmetic of the thesis drive's path,
bit for bit (tests/belts/test_pulley_path.py).

A layout can be wrapped when it has at least two pulleys, no two of them overlap, the
belt wraps every pulley (theta_k > 0), the wraps turn the belt once counter-clockwise
(sum s_k theta_k = 2 pi: pulleys listed clockwise, or a back-side pulley that does not
press into the loop, turn it otherwise), no span passes through another pulley and no
two spans cross; otherwise the path raises a ValueError naming the pulley(s) and the
limit.
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import NamedTuple

import numpy as np

TWO_PI = 2 * math.pi
WRAP_TOL = 1e-9  # rad: a wrap angle or a turn this close to 0 (mod 2 pi) is one


def _turn(v):
    """Ĩ v: v turned by +90 degrees (Eq. 3.6); v (..., 2)."""
    return np.stack([-v[..., 1], v[..., 0]], -1)


@dataclass(frozen=True)
class Pulley:
    """A pulley of a belt path: centre (m), radius (m), side (+1: the belt's inner side on
    it, -1: the belt's back)."""

    name: str
    centre: tuple
    radius: float
    side: int = 1

    @property
    def rho(self) -> float:
        """Signed radius s r, m."""
        return self.side * self.radius


class Span(NamedTuple):
    """A span: tangent points where it leaves and reaches its pulleys (m), its length (m),
    the polar angle phi of its frame c_lo -> c_hi and the angle sigma a of its normal from
    that frame (rad)."""

    start: np.ndarray
    end: np.ndarray
    length: float
    phi: float
    turn: float


def _span(p: Pulley, q: Pulley, forward: bool) -> Span:
    """The span from p to q; ``forward``: p has the lower index."""
    lo, hi = (p, q) if forward else (q, p)
    o_lo, o_hi = np.asarray(lo.centre, float), np.asarray(hi.centre, float)
    D = float(np.hypot(hi.centre[0] - lo.centre[0], hi.centre[1] - lo.centre[1]))
    u = (o_hi - o_lo) / D
    a = math.acos((lo.rho - hi.rho) / D)
    sigma = -1.0 if forward else 1.0
    n = math.cos(a) * u + sigma * math.sin(a) * _turn(u)
    o_p, o_q = (o_lo, o_hi) if forward else (o_hi, o_lo)
    return Span(o_p + p.rho * n, o_q + q.rho * n, math.sqrt(D**2 - (lo.rho - hi.rho) ** 2),
                math.atan2(u[1], u[0]), sigma * a)


def _check_pulleys(pulleys) -> None:
    """At least two pulleys, each with a positive radius and a side of +-1, none
    overlapping another."""
    if len(pulleys) < 2:
        raise ValueError(f"a belt path needs at least 2 pulleys, got {len(pulleys)}")
    for p in pulleys:
        if not (p.radius > 0 and math.isfinite(p.radius)) or p.side not in (1, -1):
            raise ValueError(f"pulley {p.name!r}: radius {p.radius!r} m and side {p.side!r}; "
                             "allowed: a radius > 0 and a side of 1 or -1")
    for i, p in enumerate(pulleys):
        for q in pulleys[i + 1:]:
            D = math.hypot(q.centre[0] - p.centre[0], q.centre[1] - p.centre[1])
            if not D > p.radius + q.radius:
                raise ValueError(f"pulleys {p.name!r} and {q.name!r} overlap: centre distance "
                                 f"{D:.6g} m; allowed: more than the sum of their radii "
                                 f"{p.radius + q.radius:.6g} m")


def _check_wraps(pulleys, wraps) -> None:
    """Every pulley wrapped, the belt turned once counter-clockwise."""
    for p, theta in zip(pulleys, wraps):
        if theta <= WRAP_TOL or theta >= TWO_PI - WRAP_TOL:
            raise ValueError(f"pulley {p.name!r} is not wrapped: the belt passes it in a "
                             "straight line; allowed: a wrap angle > 0 (move it into the belt)")
    turns = sum(p.side * theta for p, theta in zip(pulleys, wraps)) / TWO_PI
    if abs(turns - 1.0) > WRAP_TOL:
        k = int(np.argmax(wraps))
        raise ValueError(
            f"pulley {pulleys[k].name!r} cannot be wrapped: the belt would turn "
            f"{math.degrees(wraps[k]):.4g} deg around it and {turns:.3g} times around the loop; "
            "allowed: one counter-clockwise turn (list the pulleys in the belt's "
            "counter-clockwise running order; side -1 only for a pulley pressing on the "
            "belt's back from outside the loop)")


def _check_clearance(pulleys, spans) -> None:
    """No span passes through a pulley other than its two ends."""
    N = len(pulleys)
    for k, sp in enumerate(spans):
        d = sp.end - sp.start
        for m, p in enumerate(pulleys):
            if m in (k, (k + 1) % N):
                continue
            c = np.asarray(p.centre, float)
            lam = np.clip((c - sp.start) @ d / (d @ d), 0.0, 1.0)
            gap = float(np.linalg.norm(sp.start + lam * d - c))
            if gap < p.radius:
                raise ValueError(
                    f"span {pulleys[k].name!r}-{pulleys[(k + 1) % N].name!r} passes through "
                    f"pulley {p.name!r}: {gap:.6g} m from its centre; allowed: at least its "
                    f"radius {p.radius:.6g} m (reorder the pulleys or change its side)")


def _side(a, b, c) -> float:
    """Sign of the turn a -> b -> c (+1 counter-clockwise)."""
    return np.sign((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]))


def _check_crossings(pulleys, spans) -> None:
    """No two spans without a common pulley cross."""
    N = len(pulleys)
    label = lambda k: f"{pulleys[k].name!r}-{pulleys[(k + 1) % N].name!r}"  # noqa: E731
    for i, a in enumerate(spans):
        for j in range(i + 2, N - (i == 0)):
            b = spans[j]
            if (_side(a.start, a.end, b.start) * _side(a.start, a.end, b.end) < 0
                    and _side(b.start, b.end, a.start) * _side(b.start, b.end, a.end) < 0):
                raise ValueError(f"spans {label(i)} and {label(j)} cross; allowed: a belt that "
                                 "does not cross itself (reorder the pulleys or change a side)")


class PulleyPath:
    """Closed belt path around ``pulleys`` (a sequence of :class:`Pulley`, N >= 2) in the
    belt's counter-clockwise running order (module docstring); lengths in m."""

    def __init__(self, pulleys):
        self.pulleys = tuple(pulleys)
        _check_pulleys(self.pulleys)
        N = len(self.pulleys)
        #: spans k -> k+1 (the last one N-1 -> 0)
        self.spans = tuple(_span(self.pulleys[k], self.pulleys[(k + 1) % N], k + 1 < N)
                           for k in range(N))
        #: wrap angle of each pulley, rad
        self.wraps = tuple(self._wrap(k) for k in range(N))
        _check_wraps(self.pulleys, self.wraps)
        _check_clearance(self.pulleys, self.spans)
        _check_crossings(self.pulleys, self.spans)
        total = 0.0  # summed in this order (not sum(): its rounding depends on the Python)
        for sp in self.spans:
            total += sp.length
        for p, theta in zip(self.pulleys, self.wraps):
            total += p.radius * theta
        #: P, m
        self.length = total

    def _wrap(self, k: int) -> float:
        into, out = self.spans[k - 1], self.spans[k]
        turn = (out.phi - into.phi) + (out.turn - into.turn)
        return (self.pulleys[k].side * turn) % TWO_PI

    def _arc(self, k: int, span: Span, extra: float, length: float):
        """("arc", length, (centre, radius, start angle, side)) on pulley k from the end of
        ``span`` and ``extra`` rad further along the wrap."""
        p = self.pulleys[k]
        back = 0.0 if p.side > 0 else math.pi
        return ("arc", length, (np.asarray(p.centre, float), p.radius,
                                span.phi + (span.turn + p.side * extra + back), p.side))

    def _segments(self):
        """(kind, length, data) of the 2 N + 1 pieces in running order."""
        N, p0 = len(self.pulleys), self.pulleys[0]
        half = self.wraps[0] / 2
        out = [self._arc(0, self.spans[-1], half, p0.radius * half)]
        for k, sp in enumerate(self.spans):
            out.append(("line", sp.length, (sp.start, sp.end)))
            if k + 1 < N:
                R = self.pulleys[k + 1].radius
                out.append(self._arc(k + 1, sp, 0.0, R * self.wraps[k + 1]))
        out.append(self._arc(0, self.spans[-1], 0.0, p0.radius * half))
        return out

    def __call__(self, s):
        """Positions (n, 2) and unit tangents (n, 2) at arc lengths s (m, taken modulo P)."""
        s = np.mod(np.atleast_1d(np.asarray(s, dtype=float)), self.length)
        r, t = np.zeros((s.size, 2)), np.zeros((s.size, 2))
        start = 0.0
        for kind, length, data in self._segments():
            sel = (s >= start) & (s <= start + length + 1e-15)
            sl = s[sel] - start
            if kind == "arc":
                o, R, ang0, side = data
                ang = ang0 + side * sl / R
                r[sel] = o + R * np.stack([np.cos(ang), np.sin(ang)], -1)
                t[sel] = side * np.stack([-np.sin(ang), np.cos(ang)], -1)
            else:
                p, q = data
                d = (q - p) / length
                r[sel] = p + sl[:, None] * d
                t[sel] = d
            start += length
        return r, t

    def names(self) -> list:
        """Names of the 2 N + 1 pieces in running order."""
        N, ps = len(self.pulleys), self.pulleys
        out = [f"pulley {ps[0].name}"]
        for k in range(N):
            out.append(f"span {ps[k].name}-{ps[(k + 1) % N].name}")
            out.append(f"pulley {ps[(k + 1) % N].name}")
        return out

    def pieces(self) -> list:
        """[(name, start arc length, end arc length)] of the pieces, m."""
        out, start = [], 0.0
        for name, (_, length, _) in zip(self.names(), self._segments()):
            out.append((name, start, start + length))
            start += length
        return out


@dataclass(frozen=True)
class TwoPulleyPath:
    """The thesis drive's path (Fig. 3.6): :class:`PulleyPath` around pulleys (O1, R1)
    and (O2, R2), both on the belt's inner side, pulley 1 the driver on the left; lengths
    in m."""

    O1: tuple
    R1: float
    O2: tuple
    R2: float

    def __post_init__(self):
        object.__setattr__(self, "path", PulleyPath((Pulley("1", self.O1, self.R1),
                                                     Pulley("2", self.O2, self.R2))))

    @property
    def centre_distance(self) -> float:
        return float(np.hypot(self.O2[0] - self.O1[0], self.O2[1] - self.O1[1]))

    @property
    def span(self) -> float:
        """l_s, m."""
        return self.path.spans[0].length

    @property
    def wrap(self) -> tuple:
        """Wrap angles (theta1, theta2), rad."""
        return self.path.wraps

    @property
    def length(self) -> float:
        """P, m."""
        return self.path.length

    def __call__(self, s):
        return self.path(s)

    def pieces(self) -> list:
        """[(name, start arc length, end arc length)] of the pieces: pulley 1 (from point
        A), the lower span, pulley 2, the upper span, pulley 1; m."""
        names = ("pulley 1", "lower span", "pulley 2", "upper span", "pulley 1")
        return [(name, a, b) for name, (_, a, b) in zip(names, self.path.pieces())]


def laid_belt(path, L0: float, n_elements: int) -> np.ndarray:
    """Nodal coordinates (n_elements, 3, 2) = (r, r_x, r_y) of a closed belt of
    reference length ``L0`` (m) laid on ``path`` (a :class:`PulleyPath` or
    :class:`TwoPulleyPath`): nodes at equal arc spacing P/n, r_x = t P / L0 (the stretch
    P/L0 of the straight reference elements, so a belt shorter than the path starts
    pre-tensioned), r_y = Ĩ t (unit, no shear)."""
    s = np.arange(n_elements) * path.length / n_elements
    r, t = path(s)
    return np.stack([r, t * (path.length / L0), _turn(t)], 1)
