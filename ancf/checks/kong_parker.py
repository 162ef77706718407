"""Our steady solve (``ancf steady belt-drive``) against Kong & Parker's bending belt
(:mod:`analytic.belt_bending_steady`) on the thesis drive at 120 rad/s
(``examples/thesis_table_3_1.toml`` with :data:`ancf.checks.belt2d.CASE_120`, as
:func:`ancf.checks.running_drives.steady` runs it), at the file's EI and at 10x EI
(``belt.alpha2`` x 10; EI = E alpha2 b h^3 / 12).

The penalty contact (k_p N/m^2, on the centreline) lets the belt sink delta = p / k_p into the
rim (p = n / R, 2-3 mm here): the reference runs on pulleys of radius R - delta (delta from the
string's span n, fixed point), else its path is 2 pi delta too long and its tensions ~1000 N
too high.  Departure point: the rim angle where the belt's centreline, leaving the wrap, gets
farther than R - delta + F delta from the pulley's centre (F = 1/4; linear between samples for
ours): on both solutions alike, a geometric lift-off that the penalty's smear (EI / k_p)^(1/4)
of the pressure does not move as the pressure's end does.  A pressure-weighted end would not
do: the BVP's point reaction at departure, Q = n eps / R, carries the force of the arc eps it
shortened, so that end is the string's tangent point at any EI.  Rows: (quantity, ours, BVP,
relative difference): span tensions (ours: the true tension over the middle third,
:func:`ancf.checks.running_drives._true`), departure points (difference over the wrap pi).

Status (measured): the 1 % target is not met.  EI: tensions +24.7 % / +15.8 %, departure
points -4.0 % / -5.7 % of the wrap; 10x EI the same within 0.1 %.  The loop closure makes the
tensions hinge on delta (1 mm of rim = 2 pi mm of path = 500 N here): a uniform delta from
the span's n is too crude; the reference needs the penalty's penetration n(theta) / (R k_p)
along each wrap in its stretch integral.
"""
from __future__ import annotations

import math

import numpy as np

from analytic import belt_bending_steady as bb
from ancf.checks.belt2d import CASE_120
from ancf.checks.running_drives import THESIS, _true, steady
from ancf.checks.span_spectrum import KEYS

ITEMS = tuple(f"{KEYS[k]}={v!r}" for k, v in CASE_120.items())
#: the lift-off threshold over the penetration; the fixed-point passes for delta
F, PASSES = 0.25, 4
#: the brief's target: relative, of the tension and of the wrap
TARGET = 0.01


def _inputs(res, out) -> tuple:
    """(pulley dicts, belt dict, EI N m^2, k_p) of the run, for analytic.belt_steady."""
    desc, prob = res.extra["description"], res.extra["problem"]
    b, E = desc.belt, prob.drive.spec.E
    EI = E * b["alpha2"] * b["b"] * b["h"] ** 3 / 12
    torque = {p["name"]: p["torque_Nm"] for p in out["results"]["pulleys"]}
    pulleys = [{"name": q.name, "centre": list(map(float, q.centre)), "radius": float(q.radius),
                "side": int(q.side), "law": q.law,
                **({"omega": CASE_120["omega_final"]} if q.law == "prescribed"
                   else {"torque": torque[q.name]})} for q in desc.pulleys]
    belt = dict(EA=E * b["b"] * b["h"], rhoA=b["rho"] * b["b"] * b["h"], L0=b["length"],
                mu=prob.drive.prm.mu)
    return pulleys, belt, EI, prob.drive.prm.k_p


def reference(pulleys, belt, EI, k_p) -> tuple:
    """(BVP solution, delta per span m) on rims R - delta, delta = n / (R k_p) (fixed point)."""
    R = np.array([p["radius"] for p in pulleys])
    delta = np.zeros(len(pulleys))
    for _ in range(PASSES):
        shrunk = [dict(p, radius=float(r - d)) for p, r, d in zip(pulleys, R, delta)]
        sol = bb.solve(shrunk, EI=EI, **belt)
        n = np.array([s["span"].P @ (s["span"].P / np.linalg.norm(s["span"].P))
                      for s in sol["spans"]])
        delta = n / (R * k_p)
    return sol, delta


def lift_angle(xy, c, level: float, near: float) -> float:
    """The rim angle (rad) about c where the polyline xy (m) crosses |r - c| = level (m),
    the crossing nearest the angle ``near``."""
    g = np.linalg.norm(xy - c, axis=1) - level
    k = np.flatnonzero(np.sign(g[:-1]) != np.sign(g[1:]))
    t = g[k] / (g[k] - g[k + 1])
    pts = xy[k] + t[:, None] * (xy[k + 1] - xy[k])
    ang = np.arctan2(pts[:, 1] - c[1], pts[:, 0] - c[0])
    gap = np.abs(np.angle(np.exp(1j * (ang - near))))
    return float(ang[np.argmin(gap)])


def rows(items: tuple = ()) -> list[tuple]:
    """(quantity, ours, BVP, relative difference) at ITEMS + items."""
    out, res = steady(THESIS, ITEMS + items, False)
    r, desc = out["results"], res.extra["description"]
    pulleys, belt, EI, k_p = _inputs(res, out)
    sol, delta = reference(pulleys, belt, EI, k_p)
    xy = np.column_stack([r["belt_x_m"], r["belt_y_m"]])
    xy = np.vstack([xy, xy[:1]])
    table = []
    for j, (ours, ref) in enumerate(zip(r["spans"], sol["spans"])):
        name = f"{ref['from']} → {ref['to']}"
        T = _true(ours, desc, r)
        table.append((f"span {name}: tension N", T, ref["tension_mean_N"],
                      T / ref["tension_mean_N"] - 1))
        c, R = np.array(pulleys[j]["centre"]), pulleys[j]["radius"]
        level = R - delta[j] + F * delta[j]
        sp = ref["span"]
        near = math.atan2(*(np.array(ref["string_departure_m"]) - c)[::-1])
        a_ref = lift_angle(sp.xy, c, level, near)
        a_ours = lift_angle(xy, c, level, near)
        d = math.remainder(a_ours - a_ref, 2 * math.pi)
        table.append((f"span {name}: departure angle rad", a_ours, a_ref, d / math.pi))
    return table


def compare() -> dict:
    """{"EI": rows, "10 EI": rows}."""
    return {"EI": rows(), "10 EI": rows((f"belt.alpha2={10 * CASE_120['alpha2']!r}",))}


if __name__ == "__main__":
    for label, tab in compare().items():
        for q, a, b, e in tab:
            print(f"{label:6s} {q:45s} {a:14.6f} {b:14.6f} {100 * e:+9.4f} %")
