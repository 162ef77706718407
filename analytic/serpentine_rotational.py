"""Rotational free vibration of a serpentine belt drive with a dynamic tensioner: the
discrete model of Hwang, Perkins, Ulsoy & Meckstroth (1994) and Beikmann, Perkins & Ulsoy,
"Free vibration of serpentine belt drive systems", J. Vib. Acoust. 118 (1996) 406-413.

Coordinates x = (theta_1 .. theta_N, psi): each pulley's rotation (rad, counter-clockwise)
and, when there is a tensioner, its arm's rotation about the pivot (rad, counter-clockwise).
The pulleys are :mod:`analytic.belt_steady`'s dicts in belt order; the span geometry is
:mod:`analytic.belt_layout`'s (span j runs from pulley i = j to k = j + 1, direction d_j,
normal m_j at the angle phi_j, length l_j, senses s_i; Delta_j = c_k - c_i,
rho_j = s_i r_i - s_k r_k, Delta_j . m_j = rho_j).

Model.  The spans are massless linear springs k_j = EA / l_j (N/m) at the steady tensions
T_j (N); the belt sticks to every pulley over its whole wrap (no creep) and its strain is
small (material is counted in stretched length).  A belt point on pulley i at the polar
angle a carries the label S = s_i r_i (a - theta_i) + const, so the stretch of span j, its
length less the belt between its end points at rest, is

    e_j = g_j(psi) - g_j(0) + s_k r_k theta_k - s_i r_i theta_i,   g_j = l_j + rho_j phi_j   (1)

(the tangent points slide round the rims as the arm turns: g_j counts the belt that moves
between span and wrap arc; sum_j g_j = P, the path length).  From Delta . m = rho,
m' = phi' d and l = Delta . d, with ' = d / dpsi and Delta' the centres' relative motion:

    g_j' = d_j . Delta_j',   g_j'' = d_j . Delta_j'' + (m_j . Delta_j')^2 / l_j            (2)

The tensioner's centre c_t = p + R(psi) a (a = c_t - p at the steady arm angle, p the pivot)
moves by c_t' = Ĩ a, c_t'' = -a; Delta_j' = +c_t' on the span into it (j = t - 1), -c_t' on
the span out of it (j = t), 0 elsewhere.  The potential energy
V = sum_j (T_j e_j + k_j e_j^2 / 2) + k_a psi^2 / 2 (k_a the arm spring's ``stiffness``,
N m/rad), less the work of the loads (linear in x, balanced at the steady state), gives

    K = sum_j k_j b_j b_j^T + (k_a + sum_j T_j g_j'') e_psi e_psi^T,
    b_j = s_k r_k e_k - s_i r_i e_i + g_j' e_psi                                           (3)
    M = diag(J_1 .. J_N, J_arm + m_t |a|^2),   K phi = omega^2 M phi                        (4)

(J_arm about the pivot; m_t the tensioner pulley's mass carried by the arm; its spin J_t is
its own coordinate theta_t, the absolute rotation, so M is diagonal).  ``driver="fixed"``
holds the prescribed pulley's theta (a prescribed-speed crankshaft); ``"free"`` keeps it and
removes the rigid mode s_i theta_i r_i = const (psi = 0) by reducing to its M-orthogonal
complement.  Transverse span vibration (Beikmann's hybrid model) is left out.

Belt inertia (optional, ``belt_mass`` m kg/m >= 0; default 0: eqs. (1)-(4) unchanged).  The
belt keeps its quasi-static shape (it sticks on every wrap, each span a straight chord), so
its kinetic energy adds a constant matrix M_b to M.  On pulley i the belt's material points
x turn with the rim, x' = theta_i' Ĩ (x - c_i) + c_i' psi' (c_i' = c_t' on the tensioner,
else 0), over the wrap length r_i w_i (w_i the steady wrap, rad).  With
int Ĩ (x - c_i) ds = s_i r_i (x_out,i - x_in,i) over the arc (x_in,i, x_out,i its entry and
exit points), the wraps give

    M_b += m r_i^3 w_i e_i e_i^T   (every pulley),
    M_b += m r_t w_t |a|^2 e_psi e_psi^T + m s_t r_t c_t' . (x_out,t - x_in,t)
           (e_t e_psi^T + e_psi e_t^T)                                                  (5)

A span's velocity is linear between its end points' (the rim's, at the tangent points):
along d_j the axial rows u_j^- = s_i r_i e_i + (d_j . c_i') e_psi and
u_j^+ = s_k r_k e_k + (d_j . c_k') e_psi (so b_j = u_j^+ - u_j^-, the stretch of eq. (1)),
along m_j the chord's rows w_j^+- = (m_j . c_i,k') e_psi (only as the arm turns).  The
consistent bar mass m l_j / 6 [[2, 1], [1, 2]] on each pair gives

    M_b += m l_j / 6 (2 u^- u^-T + u^- u^+T + u^+ u^-T + 2 u^+ u^+T + the same in w)   (6)

Optionally (``belt_speed`` c m/s) the spans' centrifugal tension softens the arm: the belt's
force on the pulleys is T_j - m c^2 (belt_steady's n; the moving string's effective
tension, Wickert & Mote 1990), so T_j -> T_j - m c^2 in the g_j'' term of eq. (3); k_j is
kept.  The transport's gyroscopic terms (m c times rates) and the belt moved between spans
and wraps as the arm turns (second order) are left out.  m counts the belt as laid (per
stretched length, a 1 / lambda below the mass per unstretched length: 1 % at 1 % strain).
"""
from __future__ import annotations

import math

import numpy as np
from scipy.linalg import eigh, null_space

from analytic import _checks
from analytic.belt_layout import Layout, turn
# the pulley dicts' checks and the layout with belt_steady's orientation, so that the spans
# here are the spans of belt_steady.solve's tensions
from analytic.belt_steady import Arm, _checked, _driver, _layout

DRIVERS = ("fixed", "free")


def _tensioner(pulleys) -> int | None:
    return next((i for i, p in enumerate(pulleys) if p["law"] == "tensioner"), None)


def _per_pulley(name: str, values, N: int) -> np.ndarray:
    """A list of N positive numbers, else ValueError naming ``name``."""
    if not isinstance(values, (list, tuple, np.ndarray)) or len(values) != N:
        raise ValueError(f"{name} must list {N} positive numbers, one per pulley in belt "
                         f"order (got {values!r})")
    return np.array([_checks.positive(f"{name}[{i}]", v) for i, v in enumerate(values)])


def _arm_inputs(pulleys, t, J_arm, m_t, arm_angle):
    """(arm or None, psi inertia about the pivot kg m^2 or None), checked."""
    if t is None:
        for name, val in (("J_arm", J_arm), ("arm_angle", arm_angle)):
            if val is not None:
                raise ValueError(f"{name} = {val!r} is given but no pulley is a tensioner; "
                                 f"allowed: None")
        return None, None
    J_arm = _checks.positive("J_arm", J_arm)
    m_t = _checks.finite("m_t", m_t)
    if m_t < 0:
        raise ValueError(f"m_t must be >= 0 (got {m_t!r})")
    pivot = pulleys[t]["pivot"]
    a = pulleys[t]["centre"] - pivot
    angle = math.atan2(a[1], a[0]) if arm_angle is None else _checks.finite("arm_angle",
                                                                             arm_angle)
    length = float(np.hypot(*a))
    return Arm(t, pivot, length, angle, 1), J_arm + m_t * length ** 2


def span_derivatives(lay: Layout, t: int, a: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """(g_j', g_j'') of eq. (2) per span, m and m/rad^2: the tensioner (index t) on an arm
    a = c_t - pivot (m) turning counter-clockwise; zero on spans away from it."""
    N = len(lay.span)
    g1, g2 = np.zeros(N), np.zeros(N)
    for j, sign in ((t - 1) % N, 1.0), (t, -1.0):
        dD, ddD = sign * turn(a), -sign * a
        m = -turn(lay.d[j])  # the right-hand normal, d = Ĩ m
        g1[j] = lay.d[j] @ dD
        g2[j] = lay.d[j] @ ddD + (m @ dD) ** 2 / lay.span[j]
    return g1, g2


def _stretch_rows(lay: Layout, n: int) -> np.ndarray:
    """(N, n): row j is b_j of eq. (3) without its psi entry, m per rad."""
    N = len(lay.span)
    B = np.zeros((N, n))
    for j in range(N):
        k = (j + 1) % N
        B[j, k] += lay.sense[k] * lay.radii[k]
        B[j, j] -= lay.sense[j] * lay.radii[j]
    return B


def belt_inertia(lay: Layout, m: float, n: int, t: int | None = None,
                 ct: np.ndarray | None = None) -> np.ndarray:
    """M_b of eqs. (5)-(6), kg m^2 (n coordinates): belt mass m kg/m on ``lay``; with a
    tensioner t, its centre's velocity per arm rate ct = dc_t / dpsi (m/rad), psi last."""
    N = len(lay.span)
    out = np.zeros((n, n))
    out[range(N), range(N)] = m * lay.radii ** 3 * lay.wrap
    vel = np.zeros((N, 2)) if t is None else np.eye(N)[t][:, None] * ct  # c_i' per pulley
    for j in range(N):
        i, k = j, (j + 1) % N
        normal = -turn(lay.d[j])
        u_a, u_b = np.zeros(n), np.zeros(n)
        u_a[i], u_b[k] = lay.sense[i] * lay.radii[i], lay.sense[k] * lay.radii[k]
        w_a, w_b = np.zeros(n), np.zeros(n)
        if t is not None:
            u_a[-1], u_b[-1] = lay.d[j] @ vel[i], lay.d[j] @ vel[k]
            w_a[-1], w_b[-1] = normal @ vel[i], normal @ vel[k]
        for a, b in (u_a, u_b), (w_a, w_b):
            out += m * lay.span[j] / 6 * (2 * np.outer(a, a) + np.outer(a, b)
                                          + np.outer(b, a) + 2 * np.outer(b, b))
    if t is not None:
        r, s = lay.radii[t], lay.sense[t]
        out[-1, -1] += m * r * lay.wrap[t] * (ct @ ct)
        cross = m * s * r * ct @ (lay.start[t] - lay.end[t - 1])
        out[t, -1] += cross
        out[-1, t] += cross
    return out


def _belt_inputs(belt_mass, belt_speed) -> tuple[float, float]:
    m = _checks.finite("belt_mass", belt_mass)
    if m < 0:
        raise ValueError(f"belt_mass must be >= 0 kg/m (got {belt_mass!r})")
    return m, _checks.finite("belt_speed", belt_speed)


def matrices(pulleys, *, EA, J, T, J_arm=None, m_t=0.0, arm_angle=None, belt_mass=0.0,
             belt_speed=0.0) -> dict:
    """M and K of eqs. (3)-(6) (kg m^2, N m/rad; the psi row in the same units) with the
    coordinate names, the layout and the stretch rows ``B`` (row j: b_j of eq. 3, m/rad).  ``pulleys``: belt_steady's dicts; ``EA`` N; ``J``
    kg m^2 per pulley; ``T`` N per span in belt order (span j: pulley j to j + 1);
    ``J_arm`` kg m^2, the arm about its pivot, and ``m_t`` kg, the tensioner pulley's mass
    (only with a tensioner); ``arm_angle`` rad, the arm's steady angle from x (default:
    the tensioner's ``centre``), e.g. belt_steady.solve's ``arm_angle_rad``; ``belt_mass``
    kg/m >= 0 (eqs. 5-6) and ``belt_speed`` m/s (its centrifugal tension on the arm)."""
    pulleys = _checked(pulleys)
    N, t = len(pulleys), _tensioner(pulleys)
    EA = _checks.positive("EA", EA)
    J, T = _per_pulley("J", J, N), _per_pulley("T", T, N)
    m, c = _belt_inputs(belt_mass, belt_speed)
    arm, J_psi = _arm_inputs(pulleys, t, J_arm, m_t, arm_angle)
    lay = _layout(pulleys, arm, 0.0)
    n = N + (arm is not None)
    B = _stretch_rows(lay, n)
    masses, ct = J, None
    if arm is not None:
        a = arm.centre(0.0) - arm.pivot
        g1, g2 = span_derivatives(lay, t, a)
        B[:, N] = g1
        masses, ct = np.append(J, J_psi), turn(a)
    K = B.T @ ((EA / lay.span)[:, None] * B)
    if arm is not None:
        K[N, N] += pulleys[t]["stiffness"] + (T - m * c * c) @ g2
    M = np.diag(masses)
    if m > 0:
        M = M + belt_inertia(lay, m, n, t, ct)
    names = [f"theta_{p['name']}" for p in pulleys] + (["psi"] if arm is not None else [])
    return {"M": M, "K": K, "coordinates": names, "layout": lay, "tensioner": t, "B": B}


def basis(M, pulleys, lay: Layout, driver: str) -> np.ndarray:
    """Columns spanning the admissible motions: without the driver's theta ("fixed"), or
    M-orthogonal to the rigid mode theta_i = s_i / r_i ("free")."""
    n = len(M)
    if driver == "fixed":
        return np.delete(np.eye(n), _driver(pulleys), axis=1)
    rigid = np.zeros(n)
    rigid[:len(lay.radii)] = lay.sense / lay.radii
    return null_space((M @ rigid)[None, :])


def modes(pulleys, *, EA, J, T, J_arm=None, m_t=0.0, arm_angle=None, belt_mass=0.0,
          belt_speed=0.0, driver: str = "fixed") -> dict:
    """Natural frequencies and shapes of eq. (4) (arguments as :func:`matrices`; ``driver``
    "fixed" or "free").  Returns ``frequencies_hz`` ascending, ``shapes`` (columns, mass-
    normalised phi^T M phi = 1, largest entry positive; the coordinates' order, a held
    driver's entry 0), ``labels`` (per mode the coordinate with the largest share of its
    kinetic energy), ``coordinates``; ValueError naming the field for bad input or an arm
    the belt's tension buckles (sum_j T_j g_j'' + k_a too negative)."""
    if driver not in DRIVERS:
        raise ValueError(f"driver = {driver!r} is not valid; allowed: one of {DRIVERS}")
    mat = matrices(pulleys, EA=EA, J=J, T=T, J_arm=J_arm, m_t=m_t, arm_angle=arm_angle,
                   belt_mass=belt_mass, belt_speed=belt_speed)
    M, K = mat["M"], mat["K"]
    Q = basis(M, pulleys, mat["layout"], driver)
    lam, Y = eigh(Q.T @ K @ Q, Q.T @ M @ Q)
    if lam[0] <= 0:  # only the arm's geometric stiffness can be negative
        raise ValueError(f"pulleys.{mat['tensioner']}.stiffness: the belt's tension buckles "
                         f"the tensioner's arm (omega^2 = {lam[0]:.6g} 1/s^2); allowed: a "
                         "spring stiffer than the tension's negative geometric stiffness")
    shapes = Q @ Y
    shapes *= np.sign(shapes[np.argmax(np.abs(shapes), axis=0), range(shapes.shape[1])])
    energy = np.diag(M)[:, None] * shapes ** 2
    names = mat["coordinates"]
    return {"frequencies_hz": np.sqrt(lam) / (2 * math.pi), "shapes": shapes,
            "labels": [names[i] for i in np.argmax(energy, axis=0)], "coordinates": names}
