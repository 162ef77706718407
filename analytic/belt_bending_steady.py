"""Steady axially moving belt with bending stiffness on N pulleys (Kong & Parker, "Steady
mechanics of belt-pulley systems", J. Appl. Mech. 72 (2005) 25-34): each free span a
boundary-value problem (:func:`scipy.integrate.solve_bvp`) whose contact points are unknowns;
the wraps from the string/creep theory :mod:`analytic.belt_steady`, to which it reduces as
EI -> 0.

Belt: extensible, axial stiffness EA (N), mass rhoA (kg/m) per unstretched length, bending
stiffness EI (N m^2), running at v = v_o lambda, mass flow G = rhoA v_o.  In a frame where the
path is fixed, a section carries F = N t + Q nu (t the unit tangent at angle theta, nu = Ĩ t,
N the tension, Q the shear) and M = EI kappa, kappa = dtheta/ds (s: arc length of the path;
the stretch in the bending term is neglected, an O(T / EA) relative effect on EI).  Steady
balance of a free span's momentum and angular momentum (no gravity, no rotary inertia):

    d/ds (F - G v t) = 0      => P = F - G v t = n t + Q nu constant,  n = N - G v   (1)
    dM/ds + t x F = 0         => EI dkappa/ds = -Q = P_x sin theta - P_y cos theta     (2)
    dx/ds = cos theta,  dy/ds = sin theta,  dtheta/ds = kappa                         (3)

(the momentum flux G v t is parallel to t, so it adds no moment).  Eqs (1)-(3) are the static
elastica under the force P: the centrifugal term enters through n = T - G v (= T - m c^2 for an
inextensible belt).  The tension along the span follows from n(s) = P . t(s) and
lambda = (n + EA) / a, a = EA - rhoA v_o^2 (:mod:`analytic.belt_steady`):
T = EA (n + EA - a) / a.                                                              (4)

Wrap on pulley i (centre c, radius R, sense sigma = +-1): kappa = sigma / R, so M = EI / R is
constant, Q = 0 and the normal pressure is n / R = (T - G v) / R, as for the string; friction
sticks, then creeps with dn/dtheta = +-mu n over the exit arc (:mod:`analytic.belt_steady`).
The wraps' n at each span's start is the string's.  Contact transitions: the span leaves
pulley i at rim angle phi_a and reaches pulley k at phi_b with

    r = c + R (cos phi, sin phi),  theta = phi + sigma pi / 2,  kappa = sigma / R     (5)

at each end (position on the rim, tangent and curvature continuous; the shear may jump: a
frictionless point reaction there), and P . t(0) = n_j, the wrap's exit n.             (6)

Unknown parameters of the BVP: span length L, phi_a, phi_b, P (5); Eq. (5) gives 8 and Eq. (6)
1 boundary condition for the 4 states.  The bending length eps = sqrt(EI / n_j) may be 1e-8
of the span: s = L g(u) with g(u) = (1 + tanh(b (2u - 1)) / tanh b) / 2, u in [0, 1],
b = ln(l / eps) / 2 clusters the mesh at both ends; states theta - theta_0 (theta_0 the
string's angle), eps kappa, (r - c_i) / l (l the string span); P by its size over n_j and its
angle from theta_0, so that the shear's sin(theta - angle of P) is a difference of small
numbers (else its round-off, times L / eps ~ 1e8, stalls the mesh refinement).  The moment balance of a wrap about its centre gives the torque
sigma R (n_out - n_in) (Eq. (6) and (5): (r - c) x P = sigma R P . t), the string's: the
torques, creep arcs and span n are unchanged, the contact points move.
Not included: the loop-length change from the moved contact points (an O(eps^2 / R) path
change, a relative O(eps^2 / (R L0 strain)) on the tensions) and friction on the point
reactions.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from scipy.integrate import solve_bvp

from analytic import belt_steady
from analytic._checks import positive
from analytic.belt_layout import _tangents, turn

#: solve_bvp's residual tolerance; its mesh cap; the initial nodes; the largest eps / R
TOL, MAX_NODES, NODES, EPS_MAX = 1e-9, 200000, 401, 0.25
#: the smallest eps / l (the mesh map needs tanh b < 1 in double precision)
EPS_MIN = 1e-12


@dataclass(frozen=True)
class Span:
    """One span's solution: departure/arrival rim angles phi_a, phi_b (rad) and the string's
    phi_a0, phi_b0; the shifts along the belt's travel sigma (phi - phi0) (rad); length L (m);
    P (N, 2); eps (m); s (m), xy (m), theta (rad), kappa (1/m), n (N) along the span."""

    phi_a: float
    phi_b: float
    phi_a0: float
    phi_b0: float
    departure_shift: float
    arrival_shift: float
    L: float
    P: np.ndarray
    eps: float
    s: np.ndarray
    xy: np.ndarray
    theta: np.ndarray
    kappa: np.ndarray
    n: np.ndarray


def _map(u: np.ndarray, b: float) -> tuple:
    """(g, g') of the end-clustering map (module docstring)."""
    z = b * (2.0 * u - 1.0)
    return 0.5 * (1.0 + np.tanh(z) / math.tanh(b)), b / (math.tanh(b) * np.cosh(z) ** 2)


def span(ci, Ri: float, si: int, ck, Rk: float, sk: int, n: float, EI: float) -> Span:
    """The span from pulley i (centre ci m, radius Ri m, sense si) to pulley k at the wrap's
    exit n (N), bending stiffness EI (N m^2): Eqs (1)-(6)."""
    ci, ck = np.asarray(ci, float), np.asarray(ck, float)
    m, spans = _tangents(np.array([ci, ck]), np.array([Ri, Rk]), np.array([si, sk]))
    l, d = float(spans[0]), turn(m[0])
    n = positive("n (span's n = T - G v, N)", n)
    eps = math.sqrt(positive("belt.EI", EI) / n)
    if not EPS_MIN * l <= eps <= EPS_MAX * min(Ri, Rk):
        raise ValueError(f"belt.EI = {EI!r} is out of range: the bending length sqrt(EI / n) "
                         f"= {eps:.3g} m; allowed: EI in [{n * (EPS_MIN * l) ** 2:.3g}, "
                         f"{n * (EPS_MAX * min(Ri, Rk)) ** 2:.3g}] N m^2 at n = {n:.6g} N")
    b = max(0.5, 0.5 * math.log(l / eps))
    th0 = math.atan2(d[1], d[0])
    fa, fb = th0 - si * math.pi / 2, th0 - sk * math.pi / 2
    dk = (ck - ci) / l

    def rhs(u, y, p):  # y[0] = theta - th0; P = n p[3] (cos, sin)(th0 + p[4])
        _, g1 = _map(u, b)
        J = p[0] * l * g1
        return np.vstack([J / eps * y[1], J / eps * p[3] * np.sin(y[0] - p[4]),
                          p[0] * g1 * np.cos(th0 + y[0]), p[0] * g1 * np.sin(th0 + y[0])])

    def bc(ya, yb, p):  # p[1], p[2]: phi_a - fa, phi_b - fb
        return np.array([
            ya[0] - p[1], ya[1] - eps * si / Ri,
            ya[2] - Ri / l * math.cos(fa + p[1]), ya[3] - Ri / l * math.sin(fa + p[1]),
            yb[0] - p[2], yb[1] - eps * sk / Rk,
            yb[2] - dk[0] - Rk / l * math.cos(fb + p[2]),
            yb[3] - dk[1] - Rk / l * math.sin(fb + p[2]),
            p[3] * math.cos(ya[0] - p[4]) - 1.0])

    u = np.linspace(0.0, 1.0, NODES)
    g, _ = _map(u, b)
    a0 = Ri * si * m[0] / l
    y0 = np.vstack([np.zeros_like(u), np.zeros_like(u), a0[0] + g * d[0], a0[1] + g * d[1]])
    sol = solve_bvp(rhs, bc, u, y0, p=np.array([1.0, 0.0, 0.0, 1.0, 0.0]), tol=TOL,
                    max_nodes=MAX_NODES, bc_tol=TOL)
    if sol.status != 0:
        raise RuntimeError(f"span BVP did not converge: {sol.message}")
    p, y = sol.p, sol.y
    P = n * p[3] * np.array([math.cos(th0 + p[4]), math.sin(th0 + p[4])])
    return Span(fa + p[1], fb + p[2], fa, fb, float(si * p[1]), float(sk * p[2]),
                float(p[0] * l), P, eps, p[0] * l * _map(sol.x, b)[0], ci + l * y[2:4].T,
                th0 + y[0], y[1] / eps, n * p[3] * np.cos(y[0] - p[4]))


def tension(n, EA: float, a: float):
    """Eq. (4): the tension T (N) at n (N)."""
    return EA * (np.asarray(n) + EA - a) / a


def middle_mean(sp: Span, values) -> float:
    """Arc-length mean of ``values`` (at sp.s) over the span's middle third."""
    s = sp.s
    grid = np.linspace(s[-1] / 3, 2 * s[-1] / 3, 601)
    return float(np.mean(np.interp(grid, s, values)))


def solve(pulleys, *, EA: float, rhoA: float, L0: float, mu: float, EI: float) -> dict:
    """The string solution (:func:`analytic.belt_steady.solve`, its fields) with each span's
    bending BVP: returns {"string": its dict, "spans": [per span from, to, the string's
    tension_N, tension_mean_N (Eq. (4), middle third), tension_ends_N, departure_shift_rad,
    arrival_shift_rad, departure_point_m, arrival_point_m, string points, length_m, eps_m]}."""
    EI = positive("belt.EI", EI)
    string = belt_steady.solve(pulleys, EA=EA, rhoA=rhoA, L0=L0, mu=mu)
    checked = belt_steady._checked(pulleys)
    lay = belt_steady._layout(checked)
    if any(p["law"] == "tensioner" for p in checked):
        raise ValueError("pulleys: a tensioner is not supported here; allowed: fixed centres")
    N = len(checked)
    out = []
    for j, row in enumerate(string["spans"]):
        k = (j + 1) % N
        T, v = row["tension_N"], row["speed"]
        v_o = v / (1.0 + T / EA)
        nj, a = T - rhoA * v_o * v, EA - rhoA * v_o * v_o
        sp = span(lay.centres[j], lay.radii[j], int(lay.sense[j]), lay.centres[k],
                  lay.radii[k], int(lay.sense[k]), nj, EI)
        Ts = tension(sp.n, EA, a)
        out.append({"from": row["from"], "to": row["to"], "tension_N": T,
                    "tension_mean_N": middle_mean(sp, Ts),
                    "tension_ends_N": [float(Ts[0]), float(Ts[-1])],
                    "departure_shift_rad": sp.departure_shift,
                    "arrival_shift_rad": sp.arrival_shift,
                    "departure_point_m": sp.xy[0].tolist(), "arrival_point_m": sp.xy[-1].tolist(),
                    "string_departure_m": lay.start[j].tolist(),
                    "string_arrival_m": lay.end[j].tolist(),
                    "length_m": sp.L, "eps_m": sp.eps, "span": sp})
    return {"string": string, "spans": out}
