"""Rotational free vibration of a serpentine belt drive whose wraps creep: the discrete model
of :mod:`analytic.serpentine_rotational` (Hwang et al. 1994, Beikmann et al. 1996) with the
belt-pulley contact of the creep-rate friction law instead of a belt stuck to every rim.

Why.  The sticking model holds the belt to each rim from tangent point to tangent point.
Under the creep-rate law (Kerkkänen's thesis Eq. 3.23, Fig. 3.3) the friction per unit
length is f = -c v_rel (c = ``nu_s``, kg/(m s)) while c |v_rel| <= mu F_n: a viscous layer,
not a bond, so a tension change runs a lag length sqrt(EA / (omega c)) into the wrap (2 cm on
the serpentine at 80 Hz, against spans of 10-25 cm) and every span acts longer.  Where the
steady state saturates the law (|f| = mu F_n) the layer carries no added shear at all.

Model.  On wrap i (length L_i = r_i w_i, x from its entry point along the running belt) the
belt's axial displacement relative to the rim, w(x) e^{st} (s the Laplace variable, 1/s), is
quasi-static in a belt moving at the transport speed V (m/s; its material derivative is
s w + V w'), so the tension's change EA w' balances the friction's:

    EA w'' = c (s w + V w')              where the law is linear (viscous zone)       (1)
    EA w'' = sigma (mu / r_i) EA w'      where it is saturated (sigma = +-1, the sign of
                                          the steady slip; F_n = T / r_i)              (2)

Across the zones of a wrap (transfer of eqs. 1-2 from zone to zone with w and w' continuous)
the end tensions are linear in the end values:

    [w'(0), w'(L_i)] = D_i(s) [w_in,i, w_out,i]                                         (3)

Span j (pulley j to k = j + 1) carries the tension change

    dT_j = k_j (b_j . x + w_in,k - w_out,j),   k_j = EA_j / l_j                          (4)

(b_j the sticking model's stretch row, eq. 3 of serpentine_rotational), and each wrap's
ends carry its spans' tensions: EA_i w'(0) = dT_{i-1}, EA_i w'(L_i) = dT_i.  Eliminating the
w gives the dynamic stiffness

    K(s) = K_geo + sum_j k_j b_j (b_j + S_j W(s))^T,   (s^2 M + K(s)) phi = 0             (5)

with K_geo the arm's spring and geometric terms and M the sticking model's (belt mass
included, eqs. 5-6 there); with the bearings' and the arm's damping C, (s^2 M + s C + K(s))
phi = 0.  Each mode is sought from the sticking model's by the secant
method on s = i sqrt(eig(M^-1 K(s))) (6).  c -> infinity with V = 0 gives the sticking
model back; with V != 0 the belt entering a stuck wrap carries its strain change in
(w = w(0) e^{-s x / V}, the running belt's creep), a compliance V / (s EA) at each entry
that the sticking model leaves out.

EA_j is the span's tangent stiffness lambda dT/dlambda (N; :func:`tangent_stiffness`, eq. 7):
the elastic law's force-stretch slope at the span's tension with material counted in
unstretched length, EA (3 lambda^2 - 1) lambda / 2 for a Green-strain belt (true force
T = EA lambda (lambda^2 - 1) / 2), EA lambda for an engineering-strain one (T = EA (lambda - 1)).

Left out: the belt's inertia inside the lag (its mass is the sticking model's), the normal
compliance of the contact, the spans' transverse motion, the transport's gyroscopic terms.
"""
from __future__ import annotations

import math

import numpy as np

from analytic import _checks
from analytic import serpentine_rotational as sr

STRAINS = ("green", "engineering")
#: secant iterations on each mode (eq. 6) and their relative tolerance on s
MAX_ITER, RTOL = 60, 1e-10


def tangent_stiffness(EA: float, T, strain: str = "green") -> np.ndarray:
    """Eq. (7): lambda dT/dlambda (N) at each tension T (N) of a belt of axial stiffness EA
    (N) under the ``strain`` law, lambda solved from T(lambda) by Newton."""
    EA = _checks.positive("EA", EA)
    if strain not in STRAINS:
        raise ValueError(f"strain = {strain!r} is not valid; allowed: one of {STRAINS}")
    T = np.asarray(T, float)
    lam = 1 + T / EA
    if strain == "engineering":
        return EA * lam
    for _ in range(50):
        lam = lam - (EA * lam * (lam * lam - 1) / 2 - T) / (EA * (3 * lam * lam - 1) / 2)
    return EA * lam * (3 * lam * lam - 1) / 2


def zone_port(EA: float, L: float, a: float, b: complex) -> np.ndarray:
    """D (1/m) of one zone of length L (m) where EA w'' = EA (a w' + b w): [w'(0), w'(L)] =
    D [w(0), w(L)].  w = A e^{k1 x} + B e^{k2 (x - L)} with Re k1 <= Re k2 (roots of
    k^2 - a k - b), scaled so that neither exponential grows; linear if the roots meet."""
    k1, k2 = sorted(np.roots([1.0, -a, -b]).astype(complex), key=lambda z: z.real)
    if abs(k2 - k1) * L < 1e-9:
        return np.array([[-1.0, 1.0], [-1.0, 1.0]], complex) / L
    e1, e2 = np.exp(k1 * L), np.exp(-k2 * L)
    W = np.array([[1, e2], [e1, 1]])
    return np.array([[k1, k2 * e2], [k1 * e1, k2]]) @ np.linalg.inv(W)


def chain(Da: np.ndarray, Db: np.ndarray) -> np.ndarray:
    """The port of zone a followed by zone b (eq. 3): w and w' continuous at the joint."""
    wm = np.array([-Da[1, 0], Db[0, 1]]) / (Da[1, 1] - Db[0, 0])  # w_mid per [w0, wL]
    return np.array([[Da[0, 0] + Da[0, 1] * wm[0], Da[0, 1] * wm[1]],
                     [Db[1, 0] * wm[0], Db[1, 0] * wm[1] + Db[1, 1]]])


def wrap_port(L: float, zones, r: float, s: complex, c: float, V: float, mu: float,
              EA: float) -> np.ndarray:
    """D_i(s) of eq. (3) for a wrap of length L (m) on radius r (m): viscous (eq. 1) except
    the saturated ``zones`` [(start m, end m, sigma)] (eq. 2)."""
    cuts, x = [], 0.0
    for start, end, sigma in sorted(zones):
        cuts += [(start - x, None), (end - start, sigma)]
        x = end
    cuts.append((L - x, None))
    port = None
    for length, sigma in cuts:
        if length <= 1e-12 * L:
            continue
        a, b = (c * V / EA, c * s / EA) if sigma is None else (sigma * mu / r, 0.0)
        D = zone_port(EA, length, a, b)
        port = D if port is None else chain(port, D)
    return port


def _checked_zones(zones, lengths: np.ndarray) -> list:
    if zones is None:
        return [[] for _ in lengths]
    if len(zones) != len(lengths):
        raise ValueError(f"zones must list {len(lengths)} pulleys' saturated zones, one list "
                         f"per pulley in belt order (got {len(zones)})")
    for i, (zs, L) in enumerate(zip(zones, lengths)):
        for start, end, sigma in zs:
            if not (0 <= start < end <= L * (1 + 1e-9)) or sigma not in (-1, 1):
                raise ValueError(f"zones[{i}] = ({start!r}, {end!r}, {sigma!r}) is out of "
                                 f"range; allowed: 0 <= start < end <= {L:.6g} m (the wrap), "
                                 "sigma -1 or 1")
    return [list(zs) for zs in zones]


class Dynamic:
    """K(s) of eq. (5) for a drive: built once, evaluated per s."""

    def __init__(self, pulleys, *, EA, J, T, creep, mu, transport_speed, zones=None,
                 damping=None, arm_damping=0.0, belt_damping=0.0, **sticking):
        mat = sr.matrices(pulleys, EA=1.0, J=J, T=T, **sticking)
        lay, B = mat["layout"], mat["B"]
        N = len(lay.span)
        EA = np.atleast_1d(np.asarray(EA, float))
        if EA.shape not in ((1,), (N,)):
            raise ValueError(f"EA must be a number or list {N} numbers > 0, one per span "
                             f"(got {len(EA)})")
        EA = np.broadcast_to(EA, (N,)).copy()
        for j, v in enumerate(EA):
            _checks.positive(f"EA[{j}]", v)
        self.c = _checks.positive("creep", creep)
        self.mu = _checks.finite("mu", mu)
        if self.mu < 0:
            raise ValueError(f"mu must be >= 0 (got {mu!r})")
        self.V = _checks.finite("transport_speed", transport_speed)
        self.mat, self.lay, self.B, self.N = mat, lay, B, N
        self.k = EA / lay.span
        self.EA_wrap = (EA + np.roll(EA, 1)) / 2  # wrap i between spans i - 1 and i
        self.zones = _checked_zones(zones, lay.radii * lay.wrap)
        self.K_geo = mat["K"] - B.T @ ((1 / lay.span)[:, None] * B)
        self.C = _damping(damping, arm_damping, N, B.shape[1])
        self.d_belt = _checks.finite("belt_damping", belt_damping)
        if self.d_belt < 0:
            raise ValueError(f"belt_damping must be >= 0 N s (got {belt_damping!r})")
        self.S = np.hstack([np.roll(np.eye(N), 1, axis=1), -np.eye(N)])  # eq. (4)'s w terms
        self.Q = sr.basis(mat["M"], pulleys, lay, "fixed")

    def K(self, s: complex) -> np.ndarray:
        """Eq. (5) at s (1/s), N m/rad."""
        N, B, S, lay = self.N, self.B, self.S, self.lay
        k = self.k + s * self.d_belt / lay.span  # eq. (4) with the belt's strain rate
        EA = self.EA_wrap + s * self.d_belt
        G = np.zeros((2 * N, 2 * N), complex)
        H = np.zeros((2 * N, B.shape[1]), complex)
        for i in range(N):
            D = EA[i] * wrap_port(lay.radii[i] * lay.wrap[i], self.zones[i], lay.radii[i],
                                  s, self.c, self.V, self.mu, EA[i])
            for row, span in ((i, (i - 1) % N), (N + i, i)):
                G[row, i] += D[row // N, 0]
                G[row, N + i] += D[row // N, 1]
                G[row] -= k[span] * S[span]
                H[row] -= k[span] * B[span]
        W = -np.linalg.solve(G, H)
        return self.K_geo + B.T @ (k[:, None] * (B + S @ W))

    def stiff(self) -> np.ndarray:
        """K in the sticking limit (c -> infinity, no damping), N m/rad."""
        return self.K_geo + self.B.T @ (self.k[:, None] * self.B)

    def nearest(self, s: complex) -> tuple[complex, np.ndarray]:
        """(s', phi): the root s' (Im s' > 0) of eq. (6) nearest s, and its shape: the
        eigenvalues of [[0, I], [-M^-1 K(s), -M^-1 C]] in the basis Q."""
        Q, M = self.Q, self.mat["M"]
        m = Q.shape[1]
        Mi = np.linalg.inv(Q.T @ M @ Q)
        A = np.block([[np.zeros((m, m)), np.eye(m)],
                      [-Mi @ (Q.T @ self.K(s) @ Q), -Mi @ (Q.T @ self.C @ Q)]])
        roots, Y = np.linalg.eig(A)
        # K(s) holds only near s (Im s > 0): the mirrored roots near -s-bar are not roots
        k = int(np.argmin(np.where(roots.imag > 0, np.abs(roots - s), np.inf)))
        return complex(roots[k]), Q @ Y[:m, k]


def _damping(damping, arm_damping, N: int, n: int) -> np.ndarray:
    """C (N m s): the pulleys' bearing damping (one per pulley, or None) and the arm's."""
    C = np.zeros((n, n))
    if damping is not None:
        if len(damping) != N:
            raise ValueError(f"damping must list {N} numbers >= 0, one per pulley in belt "
                             f"order (got {damping!r})")
        for i, v in enumerate(damping):
            if not _checks.finite(f"damping[{i}]", v) >= 0:
                raise ValueError(f"damping[{i}] must be >= 0 N m s (got {v!r})")
            C[i, i] = v
    a = _checks.finite("arm_damping", arm_damping)
    if a < 0 or (a > 0 and n == N):
        raise ValueError(f"arm_damping = {arm_damping!r} is out of range; allowed: >= 0 N m s, "
                         "and 0 without a tensioner")
    if n > N:
        C[N, N] = a
    return C


def _root(dyn: Dynamic, s0: complex) -> tuple[complex, np.ndarray, int]:
    """Eq. (6) by the secant method on r(s) = s - nearest(s) from s0."""
    s_prev, (s_cur, phi) = s0, dyn.nearest(s0)
    r_prev = s_prev - s_cur
    for it in range(1, MAX_ITER + 1):
        s_new, phi = dyn.nearest(s_cur)
        r_cur = s_cur - s_new
        if abs(r_cur) <= RTOL * abs(s_cur):
            return s_new, phi, it
        step = r_cur * (s_cur - s_prev) / (r_cur - r_prev) if r_cur != r_prev else r_cur
        s_prev, r_prev, s_cur = s_cur, r_cur, s_cur - step
    raise RuntimeError(f"serpentine_creep: a mode from {abs(s0.imag) / (2 * math.pi):.6g} Hz "
                       f"did not converge in {MAX_ITER} iterations")


def modes(pulleys, *, EA, J, T, creep, mu=0.0, transport_speed, zones=None, damping=None,
          arm_damping=0.0, belt_damping=0.0, J_arm=None, m_t=0.0, arm_angle=None,
          belt_mass=0.0, belt_speed=0.0) -> dict:
    """The modes of eq. (5), the driver held.  ``pulleys``, ``J``, ``T``, ``J_arm``, ``m_t``,
    ``arm_angle``, ``belt_mass``, ``belt_speed``: as :func:`analytic.serpentine_rotational.
    matrices`; ``EA`` N, a number or one per span (eq. 7's tangent stiffness); ``creep`` c of
    eq. (1), kg/(m s); ``mu`` the friction coefficient of eq. (2); ``transport_speed`` V, m/s,
    positive along the belt order; ``zones`` per pulley in belt order the saturated zones
    [(start m, end m, sigma)] from the wrap's entry (default: none); ``damping`` N m s per
    pulley (bearing), ``arm_damping`` N m s, ``belt_damping`` the belt's axial strain-rate
    damping dEA, N s (k_j -> k_j + s dEA / l_j, EA -> EA + s dEA in eq. 1).  Returns per mode
    ``frequencies_hz`` |Im s| / 2 pi, ``damping_ratios`` -Re s / |s|, ``labels`` (the
    coordinate of largest kinetic energy), ``sticking_hz`` (the mode it was followed from)
    and ``iterations``; ascending."""
    dyn = Dynamic(pulleys, EA=EA, J=J, T=T, creep=creep, mu=mu, transport_speed=transport_speed,
                  zones=zones, damping=damping, arm_damping=arm_damping,
                  belt_damping=belt_damping, J_arm=J_arm, m_t=m_t, arm_angle=arm_angle,
                  belt_mass=belt_mass, belt_speed=belt_speed)
    M, names = dyn.mat["M"], dyn.mat["coordinates"]
    Q = dyn.Q
    lam = np.linalg.eigvals(np.linalg.solve(Q.T @ M @ Q, Q.T @ dyn.stiff() @ Q)).real
    rows = []
    for f0 in np.sort(np.sqrt(np.abs(lam))) / (2 * math.pi):
        s, phi, it = _root(dyn, 2j * math.pi * f0)
        energy = np.diag(M) * np.abs(phi) ** 2
        rows.append((abs(s.imag) / (2 * math.pi), -s.real / abs(s),
                     names[int(np.argmax(energy))], f0, it))
    rows.sort()
    return {key: [r[k] for r in rows] for k, key in enumerate(
        ("frequencies_hz", "damping_ratios", "labels", "sticking_hz", "iterations"))}
