"""Steady free span of a moving belt with bending stiffness between two pulleys (Kong &
Parker, Steady mechanics of belt-pulley systems, J. Appl. Mech. 72 (2005) 25-34).

A belt of bending stiffness EI (N m^2), axial stiffness EA (N), mass per unstretched
length rhoA (kg/m) runs at speed v (m/s) from pulley 1 (centre c1 m, radius r1 m) to
pulley 2 (c2, r2) along the span that :mod:`analytic.belt_layout` builds for both pulleys
turned counter-clockwise (sides +1, orientation +1): the external common tangent, with
pulley 1 on the left of c2 - c1 this is the lower span; swap the pulleys for the upper one.
In that string limit (EI -> 0) the belt leaves pulley 1 at angle alpha1_s and reaches
pulley 2 at alpha2_s (angles of the contact points about the centres, counter-clockwise
from +x).  With EI > 0 it leaves earlier, at alpha1 = alpha1_s - delta1, and arrives later,
at alpha2 = alpha2_s + delta2 (the shifts delta1, delta2 > 0).

Model.  In the steady (Eulerian) state the span's shape is stationary while material runs
along it; a material point's acceleration is v^2 dt/ds, so with s the arclength, theta the
tangent angle, t = (cos theta, sin theta), n = (-sin theta, cos theta), N the axial force
and Q the shear, the momentum and moment balances read

    x' = cos theta,   y' = sin theta,   theta' = kappa,   EI kappa' = M' = -Q,        (1)
    F = P t + Q n = (Fx, Fy) constant along the span,   P = N - G v,                  (2)

so Q = -Fx sin theta + Fy cos theta and EI kappa' = Fx sin theta - Fy cos theta.  G v is
the centrifugal term with G = rhoA v_o the mass flow and v_o = v / (1 + N1 / EA) the speed
per unstretched length at the departure point, where the belt moves with the rim at v; the
material speed is v_o (1 + N / EA), so

    N = (P + rhoA v_o^2) / (1 - rhoA v_o^2 / EA)   (N = P + rhoA v^2 when EA = inf).   (3)

At the departure (s = 0) and arrival (s = l) points the belt still conforms to the pulley
(moment continuity, M = EI / r):

    (x, y) = c_i + r_i (cos alpha_i, sin alpha_i),  theta = alpha_i + pi / 2,  kappa = 1 / r_i,
    P(0) = Fx cos theta(0) + Fy sin theta(0) = P1 = N1 - rhoA v_o^2 (1 + N1 / EA).      (4)

Equations (1)-(4) are 4 first-order equations with the 5 unknown constants l, alpha1,
alpha2, Fx, Fy and 9 conditions; :func:`scipy.integrate.solve_bvp` solves them on
s = l xi, xi in [0, 1], in the string's frame: origin at its departure point, x along its
direction, lengths in units of its length l_s, forces in units of P1, so that the centres
sit at (0, r1) and (1, r2).  There the states q = x - xi, w = y, phi = theta - theta_s
(theta_s the string's direction) and the constants mu = l / l_s - 1, beta_i = alpha_i -
alpha_i,s, fy vanish on the string solution and stay small near the ends (no round-off
from O(1) positions over the boundary layer's fine mesh):

    q' = mu cos phi - 2 sin^2(phi / 2),  w' = (1 + mu) sin phi,  phi' = (1 + mu) kappa,
    eps kappa' = (1 + mu) (fx sin phi - fy cos phi),  eps = EI / (P1 l_s^2),           (5)
    ends: q = r_i sin beta_i,  w = 2 r_i sin^2(beta_i / 2),  phi = beta_i,  kappa r_i = 1,

with (q, w, phi, kappa) = 0, mu = beta_i = fy = 0, fx = 1 (the string) as the start, on a
mesh graded towards both ends on the bending length sqrt(eps).  It converges from there
without continuation in EI, from EI = 1e-14 N m^2 to shifts of 80 degrees on the thesis
drive; the shifts are delta1 = -beta1, delta2 = beta2.

Assumptions: no gravity, no air drag; Euler-Bernoulli bending with M = EI kappa on the
deformed centre line (no rotary inertia, no shear deformation); the span's shape in its
deformed arclength depends on P alone, so EA only maps P to N by (3) (the geometry is
that of an inextensible elastica; EA = inf, the default, is an inextensible belt); P1 > 0
(a positive effective tension).
"""
from __future__ import annotations

import math

import numpy as np
from scipy.integrate import solve_bvp

from analytic._checks import finite, magnitude, positive
from analytic.belt_layout import turn, wrap

#: relative tolerance of solve_bvp's collocation residuals and of its boundary conditions:
#: angles and tensions come out within 5e-11 of the isolated layers' closed form and 1.5e-10
#: of a shooting method (tests/analytic/test_belt_span_bending.py)
BVP_TOL, BC_TOL = 1e-7, 1e-12
#: growth of the mesh spacing away from each end (ratio e^H per node), nodes in the middle
H, N_UNIFORM = 0.25, 41
#: solve_bvp's limit on the mesh nodes
MAX_NODES = 20000
#: Gauss-Legendre points for the mean axial force over the middle third
N_GAUSS = 32


def _point(name: str, val) -> np.ndarray:
    """A centre (x, y), m, as two finite floats, else ValueError naming ``name``."""
    try:
        x, y = val
    except (TypeError, ValueError):
        raise ValueError(f"{name} must be a point (x, y) in m (got {val!r})") from None
    return np.array([finite(f"{name}[0]", x), finite(f"{name}[1]", y)])


def _inputs(c1, r1, c2, r2, N1, EI, rhoA, v, EA):
    """Checked inputs as floats (ValueError naming the field and its range)."""
    c1, c2 = _point("c1", c1), _point("c2", c2)
    r1, r2, N1, EI = (positive(k, x) for k, x in (("r1", r1), ("r2", r2), ("N1", N1),
                                                    ("EI", EI)))
    rhoA, v = finite("rhoA", rhoA), finite("v", v)
    if rhoA < 0:
        raise ValueError(f"rhoA must be >= 0 kg/m (got {rhoA!r})")
    EA = math.inf if EA == math.inf else positive("EA", EA)
    D = math.hypot(*(c2 - c1))
    if D <= r1 + r2:
        raise ValueError(f"c2 = {tuple(c2)!r}: the pulleys overlap (centre distance {D:.6g} "
                         f"m); allowed: a distance more than r1 + r2 = {r1 + r2:.6g} m")
    return c1, r1, c2, r2, N1, EI, rhoA, v, EA


def effective_tension(N1: float, rhoA: float, v: float, EA: float) -> float:
    """P1 = N1 - rhoA v_o^2 (1 + N1 / EA), N (eq. 4), or ValueError naming v when P1 <= 0."""
    stretch = 1.0 + N1 / EA
    P1 = N1 - rhoA * v * v / stretch
    if P1 <= 0:
        vmax = math.sqrt(N1 * stretch / rhoA)
        raise ValueError(f"v = {v!r} m/s is out of range: allowed |v| < sqrt(N1 (1 + N1 / EA)"
                         f" / rhoA) = {vmax:.6g} m/s (a positive effective tension P1 = N1 - "
                         "rhoA v^2 / (1 + N1 / EA))")
    return P1


def _mesh(lam: float) -> np.ndarray:
    """xi nodes: spacing lam (e^H - 1) e^(H k) away from each end, plus a uniform grid."""
    d = lam * np.expm1(H * np.arange(int(math.log(0.5 / lam + 1.0) / H) + 2))
    d = d[d < 0.5]
    return np.unique(np.concatenate([d, 1.0 - d, np.linspace(0.0, 1.0, N_UNIFORM)]))


def _problem(r1, r2, eps):
    """solve_bvp's (fun, bc) for eqs. (5) in the string's frame (module doc), r_i in units of
    l_s; y = (q, w, phi, kappa), p = (mu, beta1, beta2, fx, fy); eps = EI / (P1 l_s^2)."""
    def fun(xi, y, p):
        mu, _, _, fx, fy = p
        phi, kap = y[2], y[3]
        return np.vstack([mu * np.cos(phi) - 2 * np.sin(phi / 2) ** 2, (1 + mu) * np.sin(phi),
                          (1 + mu) * kap, (1 + mu) * (fx * np.sin(phi) - fy * np.cos(phi)) / eps])

    def end(y, r, b):
        return [y[0] - r * math.sin(b), y[1] - 2 * r * math.sin(b / 2) ** 2, y[2] - b,
                y[3] * r - 1.0]

    def bc(ya, yb, p):
        _, b1, b2, fx, fy = p
        return np.array(end(ya, r1, b1) + end(yb, r2, b2)
                        + [fx * math.cos(ya[2]) + fy * math.sin(ya[2]) - 1.0])
    return fun, bc


def _solve(r1, r2, eps):
    """solve_bvp's solution in the string's frame from the string span (all zero, F = P1 d)."""
    xi = _mesh(math.sqrt(eps))
    fun, bc = _problem(r1, r2, eps)
    return solve_bvp(fun, bc, xi, np.zeros((4, xi.size)), np.array([0.0, 0.0, 0.0, 1.0, 0.0]),
                     tol=BVP_TOL, bc_tol=BC_TOL, max_nodes=MAX_NODES)


def _tension_mean(sol, to_N) -> float:
    """(3 / l) int over the middle third of N ds, N."""
    g, w = np.polynomial.legendre.leggauss(N_GAUSS)
    y = sol.sol(0.5 + g / 6)
    P = sol.p[3] * np.cos(y[2]) + sol.p[4] * np.sin(y[2])
    return float(w @ to_N(P)) / 2


def span(c1, r1, c2, r2, N1, EI, rhoA, v, EA=math.inf) -> dict:
    """The steady span from pulley 1 to pulley 2 (module doc): angles (rad), shifts from the
    string's tangent points (rad, > 0: leaves earlier / arrives later), its length l (m);
    the arclength s, positions x, y (m) and axial force N (N) on solve_bvp's mesh; the mean
    N over the middle third and the effective force (Fx, Fy), N."""
    c1, r1, c2, r2, N1, EI, rhoA, v, EA = _inputs(c1, r1, c2, r2, N1, EI, rhoA, v, EA)
    P1 = effective_tension(N1, rhoA, v, EA)
    lay = wrap(np.array([c1, c2]), np.array([r1, r2]), (1, 1), ("1", "2"), 1)
    ls, d, start = float(lay.span[0]), lay.d[0], lay.start[0]
    eps = magnitude("the bending length ratio EI / (P1 l_s^2)",
                    {"EI": (EI, 1), "N1": (P1, -1), "c2": (ls, -2)})
    sol = _solve(r1 / ls, r2 / ls, eps)
    shifts = -float(sol.p[1]), float(sol.p[2])
    if sol.status != 0 or not all(0 < b < math.pi / 2 for b in shifts):
        raise ValueError(f"EI = {EI!r} N m^2 is out of range for this span (solve_bvp: "
                         f"{sol.message}; shifts {np.degrees(shifts)} deg); allowed: EI "
                         "such that the belt leaves and reaches the pulleys less than 90 "
                         "degrees from the string's tangent points")
    rvo2 = rhoA * v * v / (1.0 + N1 / EA) ** 2  # rhoA v_o^2, N

    def to_N(P):  # eq. (3), P in units of P1
        return (P * P1 + rvo2) / (1.0 - rvo2 / EA)
    P = sol.p[3] * np.cos(sol.y[2]) + sol.p[4] * np.sin(sol.y[2])
    frame = np.column_stack([d, turn(d)])  # string frame -> fixed frame
    xy = start[:, None] + ls * frame @ np.vstack([sol.y[0] + sol.x, sol.y[1]])
    a1s, a2s = (math.atan2(*(p - c)[::-1]) for p, c in ((start, c1), (lay.end[0], c2)))
    return {"departure_angle_rad": a1s - shifts[0], "arrival_angle_rad": a2s + shifts[1],
            "departure_shift_rad": shifts[0], "arrival_shift_rad": shifts[1],
            "length_m": (1 + float(sol.p[0])) * ls, "s_m": (1 + sol.p[0]) * ls * sol.x,
            "x_m": xy[0], "y_m": xy[1], "axial_force_N": to_N(P),
            "tension_mean_N": _tension_mean(sol, to_N),
            "effective_force_N": tuple(float(f) for f in P1 * frame @ sol.p[3:])}
