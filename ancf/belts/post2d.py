"""Post-processing of belt-drive states: quantities along the belt and on the spans.

Along the belt (``npts`` points per element, belt arc coordinate s = reference
arc length from node 0, m): position, velocity, belt speed |r'|, axial force
N = E A alpha1 eps_l (Eq. 3.17, N) and the contact state (penetration, normal and
friction force per unit length, relative velocity, the pulley centres' velocities
included: :func:`ancf.belts.contact2d.contact_state_stepped`).  A friction law with a
state (the bristle law) is evaluated on the march's state, carried from its contact Gauss
points to the sample points (:func:`friction_state`): its spring's force is what carries
the tension change over a wrap, the damper alone does not.

On the spans: the point where the belt crosses a span's perpendicular bisector
(its "midpoint", Figs 3.10-3.11) and the mean axial force over the belt points
whose projection falls in the middle third of a span and lies within ``R/2`` of
its line (the span tension).  The upper span runs from pulley 2 to pulley 1 and is
the tight one while the driver (pulley 1, counter-clockwise) pulls the belt off
it; the lower span is the slack one.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ancf.belts.contact2d import contact_state_stepped
from ancf.elements.basis import cubic2d_S


@dataclass
class BeltSample:
    s: np.ndarray         # (m,) belt arc coordinate, m
    r: np.ndarray         # (m, 2) positions, m
    v: np.ndarray         # (m, 2) velocities, m/s
    N: np.ndarray         # (m,) axial force, N
    d: np.ndarray         # (m, npulley) penetration, m
    Fn: np.ndarray        # (m, npulley) normal force per unit length, N/m
    Ft: np.ndarray        # (m, npulley) friction per unit length along t, N/m
    vt: np.ndarray        # (m, npulley) relative tangential velocity, m/s

    @property
    def speed(self) -> np.ndarray:
        return np.linalg.norm(self.v, axis=1)


def _shapes(drive, npts: int):
    xi = (np.arange(npts) + 0.5) / npts
    l = drive.mesh.lengths
    X = xi[None, :] * l[:, None]
    S0 = cubic2d_S(X, np.zeros_like(X), np.broadcast_to(l[:, None], X.shape))
    return xi, np.ascontiguousarray(S0.reshape(l.size, npts, 6))


def friction_state(drive, xi, state=None) -> tuple:
    """(z (nel, len(xi), np) m, h s): a friction law's state at the points xi ([0, 1]) of
    every element and the step it is stepped over, from ``state`` = (z0 (nel, ng, np), h),
    the march's at its contact Gauss points (``res.extra["friction_state"][i]``: the state
    the step ending at sample i started from, and that step), or, without it, the drive's
    own ``z[0]`` over 0 s: the state its last march ended in (the final sample's);
    linear along the belt between the Gauss points, periodic (the belt is closed).
    Zeros for a drive without a state."""
    nel, npul = drive.mesh.n_elements, drive.radii.size
    if state is None:
        own = getattr(drive, "z", None)
        state = (None, 0.0) if own is None or not own.size else (own[0], 0.0)
    z0, h = state
    if z0 is None:
        return np.zeros((nel, np.size(xi), npul)), 0.0
    at = (np.arange(nel)[:, None] + np.asarray(xi)[None, :]).ravel()
    g = (np.arange(nel)[:, None] + drive.xi[None, :]).ravel()
    z = np.stack([np.interp(at, g, z0[:, :, p].ravel(), period=nel) for p in range(npul)], -1)
    return np.ascontiguousarray(z.reshape(nel, np.size(xi), npul)), float(h)


def sample(drive, x, v, t: float, npts: int = 8, state=None) -> BeltSample:
    """The belt at system state (x, v), time t (s); a friction law with a state on
    ``state`` (:func:`friction_state`: by default the drive's own, right at the state its
    last march ended in)."""
    q, qd = drive.belt(x), drive.belt(v)
    dm = drive.mesh.dofmap
    E, V = q[dm].reshape(-1, 6, 2), qd[dm].reshape(-1, 6, 2)
    o, odot = drive.moved(x, v, t)
    return sample_elements(drive, E, V, drive.omegas(t, v), o, odot, npts, state)


def sample_elements(drive, E, V, omegas, o, odot, npts: int = 8, state=None) -> BeltSample:
    """:func:`sample` from the element coordinates E and velocities V (nel, 6, 2), the
    pulleys' angular velocities (np,) rad/s, centres o and their velocities odot (np, 2)."""
    xi, S0 = _shapes(drive, npts)
    z, h = friction_state(drive, xi, state)
    r, d, Fn, phi, vt = contact_state_stepped(E, V, S0, o, odot, drive.radii, omegas, drive.prm,
                                              z, h)
    s = (np.arange(drive.mesh.n_elements)[:, None] + xi[None, :]) * drive.mesh.lengths[0]
    N = drive.element.axial_force(np.reshape(E, (E.shape[0], -1)), xi)
    flat = lambda a: np.asarray(a).reshape(s.size, *np.shape(a)[2:])  # noqa: E731
    return BeltSample(s.ravel(), flat(r), flat(np.einsum("eqk,ekd->eqd", S0, V)), N.ravel(),
                      flat(d), flat(Fn), flat(phi), flat(vt))


def spans(path) -> dict:
    """{"tight": (start, end), "slack": (start, end)} span end points, m."""
    r, _ = path(np.array([p[1] for p in path.pieces()[1:4:2]]))
    e, _ = path(np.array([p[2] for p in path.pieces()[1:4:2]]))
    return {"slack": (r[0], e[0]), "tight": (r[1], e[1])}


def _span_coords(points, span):
    a, b = span
    u = (b - a) / np.linalg.norm(b - a)
    rel = points - a
    lam = rel @ u / np.linalg.norm(b - a)
    off = rel @ np.array([-u[1], u[0]])
    return lam, off


def _middle_third(smp: BeltSample, span, R: float) -> np.ndarray:
    """The belt points in the middle third of ``span`` within R/2 of its line (bool)."""
    lam, off = _span_coords(smp.r, span)
    return (lam > 1 / 3) & (lam < 2 / 3) & (np.abs(off) < R / 2)


def span_tension(smp: BeltSample, span, R: float) -> float:
    """Mean axial force (N) over the belt points in the middle third of ``span``."""
    sel = _middle_third(smp, span, R)
    return float(smp.N[sel].mean()) if sel.any() else float("nan")


def span_speed(smp: BeltSample, span, R: float) -> float:
    """Mean speed |v| (m/s) of the belt points in the middle third of ``span``."""
    sel = _middle_third(smp, span, R)
    return float(smp.speed[sel].mean()) if sel.any() else float("nan")


def span_midpoint(smp: BeltSample, span, R: float) -> np.ndarray:
    """Position (2,) where the belt crosses the span's perpendicular bisector, m."""
    r = np.vstack([smp.r, smp.r[:1]])  # the belt is closed
    lam, off = _span_coords(r, span)
    near = np.abs(off) < R
    for i in np.flatnonzero(near[:-1] & near[1:]):
        j = i + 1
        if (lam[i] - 0.5) * (lam[j] - 0.5) <= 0 and lam[i] != lam[j]:
            f = (0.5 - lam[i]) / (lam[j] - lam[i])
            return r[i] + f * (r[j] - r[i])
    return np.full(2, np.nan)
