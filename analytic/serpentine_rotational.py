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
complement.  Transverse span vibration (Beikmann's hybrid model) and belt inertia are left
out.
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


def matrices(pulleys, *, EA, J, T, J_arm=None, m_t=0.0, arm_angle=None) -> dict:
    """M and K of eqs. (3)-(4) (kg m^2, N m/rad; the psi row in the same units) with the
    coordinate names and the layout.  ``pulleys``: belt_steady's dicts; ``EA`` N; ``J``
    kg m^2 per pulley; ``T`` N per span in belt order (span j: pulley j to j + 1);
    ``J_arm`` kg m^2, the arm about its pivot, and ``m_t`` kg, the tensioner pulley's mass
    (only with a tensioner); ``arm_angle`` rad, the arm's steady angle from x (default:
    the tensioner's ``centre``), e.g. belt_steady.solve's ``arm_angle_rad``."""
    pulleys = _checked(pulleys)
    N, t = len(pulleys), _tensioner(pulleys)
    EA = _checks.positive("EA", EA)
    J, T = _per_pulley("J", J, N), _per_pulley("T", T, N)
    arm, J_psi = _arm_inputs(pulleys, t, J_arm, m_t, arm_angle)
    lay = _layout(pulleys, arm, 0.0)
    n = N + (arm is not None)
    B = np.zeros((N, n))  # row j: b_j of eq. (3)
    for j in range(N):
        k = (j + 1) % N
        B[j, k] += lay.sense[k] * lay.radii[k]
        B[j, j] -= lay.sense[j] * lay.radii[j]
    K_psi = 0.0
    if arm is not None:
        g1, g2 = span_derivatives(lay, t, arm.centre(0.0) - arm.pivot)
        B[:, N] = g1
        K_psi = pulleys[t]["stiffness"] + T @ g2
    K = B.T @ ((EA / lay.span)[:, None] * B)
    masses = J
    if arm is not None:
        K[N, N] += K_psi
        masses = np.append(J, J_psi)
    names = [f"theta_{p['name']}" for p in pulleys] + (["psi"] if arm is not None else [])
    return {"M": np.diag(masses), "K": K, "coordinates": names, "layout": lay,
            "tensioner": t}


def _basis(M, pulleys, lay: Layout, driver: str) -> np.ndarray:
    """Columns spanning the admissible motions: without the driver's theta ("fixed"), or
    M-orthogonal to the rigid mode theta_i = s_i / r_i ("free")."""
    n = len(M)
    if driver == "fixed":
        return np.delete(np.eye(n), _driver(pulleys), axis=1)
    rigid = np.zeros(n)
    rigid[:len(lay.radii)] = lay.sense / lay.radii
    return null_space((M @ rigid)[None, :])


def modes(pulleys, *, EA, J, T, J_arm=None, m_t=0.0, arm_angle=None,
          driver: str = "fixed") -> dict:
    """Natural frequencies and shapes of eq. (4) (arguments as :func:`matrices`; ``driver``
    "fixed" or "free").  Returns ``frequencies_hz`` ascending, ``shapes`` (columns, mass-
    normalised phi^T M phi = 1, largest entry positive; the coordinates' order, a held
    driver's entry 0), ``labels`` (per mode the coordinate with the largest share of its
    kinetic energy), ``coordinates``; ValueError naming the field for bad input or an arm
    the belt's tension buckles (sum_j T_j g_j'' + k_a too negative)."""
    if driver not in DRIVERS:
        raise ValueError(f"driver = {driver!r} is not valid; allowed: one of {DRIVERS}")
    mat = matrices(pulleys, EA=EA, J=J, T=T, J_arm=J_arm, m_t=m_t, arm_angle=arm_angle)
    M, K = mat["M"], mat["K"]
    Q = _basis(M, pulleys, mat["layout"], driver)
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
