"""The wrapped belt path around N pulleys (ancf.belts.path): Table 3.1's numbers, the
two-pulley path bit for bit against the formulas it had before it became the N = 2 case,
three- and four-pulley layouts against independent geometry (chords, tangent points,
continuity, closed-form wraps and lengths), an idler on the belt's back, and every
layout that cannot be wrapped."""
from __future__ import annotations

import math

import numpy as np
import pytest

from ancf.belts.path import Pulley, PulleyPath, TwoPulleyPath, laid_belt
from ancf.scenes import SCENES
from ancf.scenes import belt3d
from ancf.scenes import belt_common

X, R = belt_common.X_CENTRE, belt_common.R1  # Table 3.1


class OldTwoPulleyPath:
    """The two-pulley path's formulas as they were before PulleyPath (commit 0a73990),
    kept as the reference the N = 2 case must equal bit for bit."""

    def __init__(self, O1, R1, O2, R2):
        self.O1, self.R1, self.O2, self.R2 = O1, R1, O2, R2
        self.D = float(np.hypot(O2[0] - O1[0], O2[1] - O1[1]))
        self.a = math.acos((R1 - R2) / self.D)
        self.span = math.sqrt(self.D**2 - (R1 - R2) ** 2)
        self.wrap = (2 * math.pi - 2 * self.a, 2 * self.a)
        self.length = 2 * self.span + R1 * self.wrap[0] + R2 * self.wrap[1]

    def segments(self):
        o1, o2 = np.asarray(self.O1, float), np.asarray(self.O2, float)
        u = (o2 - o1) / self.D
        w = np.array([-u[1], u[0]])
        a, phi = self.a, math.atan2(u[1], u[0])
        m_low = math.cos(a) * u - math.sin(a) * w
        m_up = math.cos(a) * u + math.sin(a) * w
        half = math.pi - a
        return [("arc", self.R1 * half, (o1, self.R1, phi + math.pi)),
                ("line", self.span, (o1 + self.R1 * m_low, o2 + self.R2 * m_low)),
                ("arc", self.R2 * self.wrap[1], (o2, self.R2, phi - a)),
                ("line", self.span, (o2 + self.R2 * m_up, o1 + self.R1 * m_up)),
                ("arc", self.R1 * half, (o1, self.R1, phi + a))]

    def __call__(self, s):
        s = np.mod(np.atleast_1d(np.asarray(s, dtype=float)), self.length)
        r, t = np.zeros((s.size, 2)), np.zeros((s.size, 2))
        start = 0.0
        for kind, length, data in self.segments():
            sel = (s >= start) & (s <= start + length + 1e-15)
            sl = s[sel] - start
            if kind == "arc":
                o, Rk, ang0 = data
                ang = ang0 + sl / Rk
                r[sel] = o + Rk * np.stack([np.cos(ang), np.sin(ang)], -1)
                t[sel] = np.stack([-np.sin(ang), np.cos(ang)], -1)
            else:
                p, q = data
                d = (q - p) / length
                r[sel] = p + sl[:, None] * d
                t[sel] = d
            start += length
        return r, t

    def ends(self):
        return np.cumsum([seg[1] for seg in self.segments()])


def _two_pulley_layouts():
    """The thesis drives' geometries (belt2d: Table 3.1, R2 = 0.1218 m of Fig. 3.21 and a
    smaller one; belt3d's defaults) and random ones at any angle."""
    belt3d_p = SCENES["belt3d"].resolve({})
    p3 = belt3d.path_of(belt3d_p)
    out = [((-X, 0.0), R, (X, 0.0), R2) for R2 in (R, 0.1218, 0.05)]
    out.append((p3.O1, p3.R1, p3.O2, p3.R2))
    rng = np.random.default_rng(7)
    for _ in range(200):
        o1, o2 = tuple(rng.uniform(-1, 1, 2)), tuple(rng.uniform(-1, 1, 2))
        D = math.hypot(o2[0] - o1[0], o2[1] - o1[1])
        out.append((o1, float(rng.uniform(0.01, 0.49) * D), o2, float(rng.uniform(0.01, 0.49) * D)))
    return out


def test_table_3_1_span_and_path_length():
    path = PulleyPath([Pulley("driver", (-X, 0.0), R), Pulley("driven", (X, 0.0), R)])
    assert round(path.spans[0].length, 6) == round(path.spans[1].length, 6) == 0.382882
    assert round(path.length, 5) == 1.27627
    assert path.wraps == pytest.approx((math.pi, math.pi), abs=1e-15)


def test_two_pulley_path_equals_its_old_formulas_bit_for_bit():
    """TwoPulleyPath is PulleyPath's N = 2 case; on the thesis geometries (what belt2d and
    belt3d lay their belts on) and 200 random ones every number is the old one's to the
    last bit: span, wraps, length, piece ends, positions, tangents and the laid belt."""
    for layout in _two_pulley_layouts():
        new, old = TwoPulleyPath(*layout), OldTwoPulleyPath(*layout)
        assert (new.span, new.wrap, new.length) == (old.span, old.wrap, old.length), layout
        assert [p[2] for p in new.pieces()] == list(old.ends()), layout
        s = np.linspace(-0.1, 1.1 * old.length, 1001)
        for a, b in zip(new(s), old(s)):
            assert a.tobytes() == b.tobytes(), layout
        for n in (20, 33):
            L0 = 0.997 * old.length
            r, t = old(np.arange(n) * old.length / n)
            want = np.stack([r, t * (old.length / L0), np.stack([-t[:, 1], t[:, 0]], -1)], 1)
            assert laid_belt(new, L0, n).tobytes() == want.tobytes(), layout


def _chord_length(path, n):
    r, _ = path(np.arange(n + 1) * path.length / n)
    return float(np.linalg.norm(np.diff(r, axis=0), axis=1).sum())


# a triangle of unequal pulleys, a serpentine-like loop with a back-side idler
TRIANGLE = [Pulley("a", (0.0, 0.0), 0.1), Pulley("b", (1.0, 0.1), 0.06),
            Pulley("c", (0.4, 0.8), 0.15)]
FOUR = [Pulley("crank", (0.0, 0.0), 0.12), Pulley("alternator", (0.45, 0.05), 0.05),
        Pulley("idler", (0.3, 0.3), 0.04, -1), Pulley("pump", (0.25, 0.55), 0.07)]


@pytest.mark.parametrize("pulleys", [TRIANGLE, FOUR], ids=["triangle", "four"])
def test_polygon_through_the_path_converges_to_its_length(pulleys):
    """Chords of n equal arcs fall short of P by O(1/n^2) (an arc of length h and radius r
    by h^3 / 24 r^2): the gap shrinks 16-fold from n = 500 to 2000, and the chord sums
    extrapolated to n -> infinity (Richardson) give P a hundred times closer than n = 2000
    (what is left: the curvature's jumps where arcs meet spans)."""
    path = PulleyPath(pulleys)
    c500, c2000 = _chord_length(path, 500), _chord_length(path, 2000)
    assert (path.length - c500) / (path.length - c2000) == pytest.approx(16, rel=0.05)
    assert abs(c2000 + (c2000 - c500) / 15 - path.length) < 0.01 * (path.length - c2000)


@pytest.mark.parametrize("pulleys", [TRIANGLE, FOUR], ids=["triangle", "four"])
def test_spans_touch_their_pulleys_perpendicular_to_the_radius(pulleys):
    path = PulleyPath(pulleys)
    N = len(pulleys)
    for k, sp in enumerate(path.spans):
        d = (sp.end - sp.start) / sp.length
        for pt, p in ((sp.start, pulleys[k]), (sp.end, pulleys[(k + 1) % N])):
            radial = pt - np.asarray(p.centre)
            assert np.linalg.norm(radial) == pytest.approx(p.radius, rel=1e-12)
            assert abs(radial @ d) < 1e-12
            # the pulley lies left of the running direction on the inner side, right on the back
            assert np.sign(d[0] * -radial[1] - d[1] * -radial[0]) == p.side


@pytest.mark.parametrize("pulleys", [TRIANGLE, FOUR], ids=["triangle", "four"])
def test_position_and_tangent_are_continuous_and_consistent(pulleys):
    """At every junction of pieces r and t agree from both sides, t is the unit derivative
    of r everywhere (central differences), and the path closes."""
    path = PulleyPath(pulleys)
    ends = np.array([p[2] for p in path.pieces()])
    assert ends[-1] == pytest.approx(path.length, rel=1e-15)
    r_a, t_a = path(ends - 1e-9)
    r_b, t_b = path(ends + 1e-9)
    assert np.abs(r_a - r_b).max() < 1e-8 and np.abs(t_a - t_b).max() < 1e-6
    s = np.linspace(0.0, path.length, 3001)[:-1] + 1e-4
    h = 1e-6
    (rp, _), (rm, _), (_, t) = path(s + h), path(s - h), path(s)
    assert np.abs((rp - rm) / (2 * h) - t).max() < 1e-6
    assert np.allclose(np.linalg.norm(t, axis=1), 1.0, atol=1e-14)


def test_equal_pulleys_on_a_triangle_wrap_its_exterior_angles():
    """Equal radii: each span parallels a side of the centres' triangle, each wrap is the
    triangle's exterior angle and P = perimeter + 2 pi r."""
    c = np.array([[0.0, 0.0], [1.0, 0.1], [0.4, 0.8]])
    path = PulleyPath([Pulley(str(k), tuple(c[k]), 0.09) for k in range(3)])
    sides = [c[(k + 1) % 3] - c[k] for k in range(3)]
    cross = [sides[k - 1][0] * sides[k][1] - sides[k - 1][1] * sides[k][0] for k in range(3)]
    exterior = [math.atan2(cross[k], sides[k - 1] @ sides[k]) for k in range(3)]
    assert path.wraps == pytest.approx(exterior, abs=1e-14)
    assert path.length == pytest.approx(sum(np.linalg.norm(s) for s in sides)
                                        + 2 * math.pi * 0.09, rel=1e-14)


def test_idler_on_the_belts_back_against_closed_form():
    """Pulleys A, B (radius R, centres (-/+d, 0)) and an idler of radius r on the belt's
    back at (0, y), pressing the upper span down: internal tangents of angle
    psi = asin((R + r)/D) - atan2(y, d), D = |(d, y)|, from the horizontal; the idler
    wraps 2 psi, A and B pi + psi each, P = 2 d + 2 sqrt(D^2 - (R + r)^2) + 2 R (pi + psi)
    + 2 r psi."""
    d, Rb, r, y = 0.3, 0.1, 0.03, 0.1
    path = PulleyPath([Pulley("A", (-d, 0.0), Rb), Pulley("B", (d, 0.0), Rb),
                       Pulley("idler", (0.0, y), r, -1)])
    D = math.hypot(d, y)
    psi = math.asin((Rb + r) / D) - math.atan2(y, d)
    assert psi > 0
    assert path.wraps == pytest.approx((math.pi + psi, math.pi + psi, 2 * psi), abs=1e-14)
    assert path.length == pytest.approx(2 * d + 2 * math.sqrt(D**2 - (Rb + r) ** 2)
                                        + 2 * Rb * (math.pi + psi) + 2 * r * psi, rel=1e-14)
    pts = path(np.linspace(0, path.length, 20001))[0]
    under = pts[(np.abs(pts[:, 0]) < 0.01) & (pts[:, 1] > 0)]
    assert under[:, 1].min() == pytest.approx(y - r, abs=1e-6)  # round the idler's bottom


A, B = Pulley("A", (-0.3, 0.0), 0.1), Pulley("B", (0.3, 0.0), 0.1)


@pytest.mark.parametrize("pulleys, message", [
    ([Pulley("A", (0.0, 0.0), 0.1)], "a belt path needs at least 2 pulleys, got 1"),
    ([A, B, Pulley("I", (0.2, 0.05), 0.03, -1)],
     "pulleys 'B' and 'I' overlap: centre distance 0.111803 m; allowed: more than the sum of "
     "their radii 0.13 m"),
    ([A, B, Pulley("I", (0.0, 0.13), 0.03, -1)],
     "pulley 'I' is not wrapped: the belt passes it in a straight line; allowed: a wrap angle > 0"),
    ([TRIANGLE[0], TRIANGLE[2], TRIANGLE[1]],  # listed clockwise
     "cannot be wrapped: the belt would turn .* deg around it and 2 times around the loop; "
     "allowed: one counter-clockwise turn"),
    ([A, B, Pulley("I", (0.0, 0.3), 0.03, -1)],
     "pulley 'I' cannot be wrapped: the belt would turn 305.7 deg around it and 0 times"),
    ([Pulley("0", (0.2, 0.9), 0.1), Pulley("1", (0.6, 0.9), 0.12),  # 1 lies between 3 and 0
      Pulley("2", (1.0, 0.5), 0.11, -1), Pulley("3", (1.0, 0.9), 0.12)],
     "span '3'-'0' passes through pulley '1': 0.11 m from its centre; allowed: at least its "
     "radius 0.12 m"),
    ([Pulley("0", (0.5, 0.9), 0.11), Pulley("1", (0.1, 0.4), 0.11, -1),
      Pulley("2", (0.7, 0.6), 0.06), Pulley("3", (0.1, 0.8), 0.16)],
     "spans '0'-'1' and '2'-'3' cross; allowed: a belt that does not cross itself"),
    ([Pulley("A", (0.0, 0.0), 0.1), Pulley("B", (1.0, 0.0), 0.1, 2)],
     "pulley 'B': radius 0.1 m and side 2; allowed: a radius > 0 and a side of 1 or -1"),
], ids=["one", "overlap", "straight", "clockwise", "idler-outside", "through", "cross", "side"])
def test_layouts_that_cannot_be_wrapped_are_refused_naming_the_pulleys(pulleys, message):
    with pytest.raises(ValueError, match=message):
        PulleyPath(pulleys)
