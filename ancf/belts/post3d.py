"""Post-processing of the 3D belt drive (thesis 4.2 and 4.6): quantities along a line
of the belt and on its spans.

Along the line y (element coordinate across the belt, m; 0: the edge the thesis
samples, w/2: the centre line) at ``npts`` points per element: positions,
velocities, the three strain measures of :mod:`ancf.belts.strains` with their
tensions k eps (k = E h w, N; Table 4.1's "k = 0.2 kN" for Model 2), the belt speed
along the tangent, det F, and the membrane's own axial force

    N_m = h w t . (r_x S_xx + r_y S_xy),   S = plane-stress Saint-Venant-Kirchhoff
    stresses of the mid-surface Green strains (the stresses of Eq. 4.16),

i.e. the force the element actually transmits (the tangential component of the first
Piola stress resultant on a section x = const, taken uniform over the width).  The
span means average the points whose projection lies in the middle third of a span
and within R/2 of its line (:mod:`ancf.belts.post2d`); the tight span is the upper one,
which runs into the counter-clockwise driver.
"""
from __future__ import annotations

import numpy as np

from ancf.belts.post2d import _span_coords, spans
from ancf.belts.strains import DEFAULT_POINTS, measures
from ancf.belts import friction
from ancf.belts.contact3d import contact_forces3d, contact_state3d
from ancf.belts.contact3d_state import (contact_forces3d_crown, contact_forces3d_state,
                                        contact_state3d_crown, contact_state3d_stepped)
from ancf.core.quadrature import gauss01
from ancf.elements.basis import plate36_S, plate36_x, plate36_y

MEASURES = ("green", "true", "almansi")


def _shapes(lengths, width, y, npts):
    xi = (np.arange(npts) + 0.5) / npts
    X = xi[None, :] * lengths[:, None]
    Y, A = np.full_like(X, y), np.broadcast_to(lengths[:, None], X.shape)
    Bw = np.full_like(X, width)
    return xi, [np.ascontiguousarray(f(X, Y, A, Bw)) for f in (plate36_S, plate36_x, plate36_y)]


def flat_reference(lengths, width) -> np.ndarray:
    """(nel, 12, 3) coordinates of the flat, unstrained reference plates."""
    E0 = np.zeros((lengths.size, 12, 3))
    for k, (x, y) in enumerate(((0, 0), (1, 0), (1, 1), (0, 1))):
        E0[:, 3 * k, 0], E0[:, 3 * k, 1] = x * lengths, y * width
        E0[:, 3 * k + 1, 0] = 1.0
        E0[:, 3 * k + 2, 1] = 1.0
    return E0


def membrane_force(rx, ry, E: float, nu: float, h: float, w: float) -> np.ndarray:
    """N_m (module docstring) from r_x, r_y (..., 3), N."""
    Exx = 0.5 * (np.einsum("...d,...d", rx, rx) - 1.0)
    Eyy = 0.5 * (np.einsum("...d,...d", ry, ry) - 1.0)
    Exy = 0.5 * np.einsum("...d,...d", rx, ry)
    Sxx = E / (1.0 - nu**2) * (Exx + nu * Eyy)
    Sxy = E / (1.0 + nu) * Exy
    t = rx / np.linalg.norm(rx, axis=-1, keepdims=True)
    return h * w * (np.einsum("...d,...d", t, rx) * Sxx + np.einsum("...d,...d", t, ry) * Sxy)


def line_sample(drive, x, v, y: float = 0.0, npts: int = DEFAULT_POINTS) -> dict:
    """Arrays (nel * npts,) along the line y of the belt at system state (x, v); ``r``
    (m, 3) positions, ``s`` reference arc length from node 0 (m)."""
    s = drive.spec
    E, V = drive.element_coords(drive.belt(x)), drive.element_coords(drive.belt(v))
    L = drive.lengths
    xi, (S, Sx, Sy) = _shapes(L, s.width, y, npts)
    k = s.E * s.h * s.width
    out = measures(S, Sx, E, flat_reference(L, s.width), V, k, others=(Sy,))
    rx, ry = (np.einsum("eqk,ekd->eqd", B, E) for B in (Sx, Sy))
    out["tension_membrane_N"] = membrane_force(rx, ry, s.E, s.nu, s.h, s.width)
    out["r"] = np.einsum("eqk,ekd->eqd", S, E)
    out["s"] = (np.arange(L.size)[:, None] + xi[None, :]) * L[0]
    return {key: a.reshape(-1, *a.shape[2:]) for key, a in out.items()}


def _middle_third(drive, r, span) -> np.ndarray:
    """The points r (m, 3) in the middle third of ``span`` ((start, end) in the x-y
    plane, m) within R/2 of its line, R the smallest pulley radius (bool)."""
    R = float(drive.radii.min())
    lam, off = _span_coords(r[:, :2], span)
    return (lam > 1 / 3) & (lam < 2 / 3) & (np.abs(off) < R / 2)


def span_means(drive, smp: dict) -> dict:
    """{"tight"/"slack": {quantity: mean over the span's middle third}}."""
    out = {}
    for name, span in spans(drive.spec.path).items():
        sel = _middle_third(drive, smp["r"], span)
        out[name] = {key: float(np.mean(a[sel])) if sel.any() else float("nan")
                     for key, a in smp.items() if key not in ("r", "s")}
    return out


def span_tension(drive, smp: dict, span) -> float:
    """The mean membrane axial force N_m (N) of a :func:`line_sample` over the middle
    third of ``span`` ((start, end), m; NaN if no point lies there)."""
    sel = _middle_third(drive, smp["r"], span)
    return float(np.mean(smp["tension_membrane_N"][sel])) if sel.any() else float("nan")


def _contact_args(drive, x, v, t: float) -> tuple:
    """Arguments of the 3D contact kernels at state (x, v), time t: the centres moved by
    their laws and a tensioner's on its arm (:meth:`ancf.belts.drive2d.PulleyDrive.moved`)."""
    E, V = drive.element_coords(drive.belt(x)), drive.element_coords(drive.belt(v))
    o, odot = drive.moved(x, v, t)
    return E, V, o, drive.omegas(t, v), odot


def _crowns(drive):
    """The crowned rims (np, 3) of a drive with a crowned pulley (:mod:`ancf.belts.
    contact3d_state`), else None: the post-processing then takes the cylinders'."""
    crowns = drive.flanges.crowns
    return crowns if crowns.shape[0] else None


def _state(drive, state):
    """(z0 (nel, nq, np, 2) m at the march's contact points, h s) of a friction law with a
    state: ``state`` (the march's at a sample: the state its step started from, and that
    step, ``res.extra["friction_state"][i]``) or the drive's own z[0] over 0 s; None for a
    stateless law."""
    if not friction.has_state(drive.prm):
        return None
    return (drive.z[0], 0.0) if state is None else state


def pulley_moments(drive, x, v, t: float, state=None) -> np.ndarray:
    """Moments (np,) of the contact forces about the pulley axes at state (x, v), N m
    (a driven pulley's is the integral of the friction of Eq. 4.45 times the lever); a
    friction law with a state on ``state`` (:func:`_state`)."""
    E, V, o, om, odot = _contact_args(drive, x, v, t)
    nel, npul = E.shape[0], drive.radii.size
    T = np.zeros(npul)
    out = (False, np.zeros((nel, 36)), np.zeros((0, 36, 36)), np.zeros((0, 36, 36)),
           np.zeros((0, npul, 36)), T, np.zeros((npul, 0, 36)), np.zeros((npul, 0, 36)),
           np.zeros(npul))
    stepped, crowns = _state(drive, state), _crowns(drive)
    if crowns is not None:  # no friction state on crowned rims (ancf.belts.tracking3d)
        contact_forces3d_crown(E, V, drive.S0, drive.w, o, drive.axes, drive.radii, om, odot,
                               drive.prm, crowns, *out)
    elif stepped is None:
        contact_forces3d(E, V, drive.S0, drive.w, o, drive.axes, drive.radii, om, odot,
                         drive.prm, *out)
    else:
        z = np.zeros((2, *np.shape(stepped[0])))
        z[0] = stepped[0]
        contact_forces3d_state(E, V, drive.S0, drive.w, o, drive.axes, drive.radii, om, odot,
                               drive.prm, z, float(stepped[1]), *out)
    return T


def contact_sample(drive, x, v, t: float, state=None) -> tuple:
    """:func:`ancf.belts.contact3d.contact_state3d` at state (x, v) at the march's contact
    points: r, d, F_n, f_t, v_s, branch (a friction law with a state on ``state``)."""
    E, V, o, om, odot = _contact_args(drive, x, v, t)
    stepped, crowns = _state(drive, state), _crowns(drive)
    if crowns is not None:
        return contact_state3d_crown(E, V, drive.S0, o, drive.axes, drive.radii, om, odot,
                                     drive.prm, crowns)[:6]
    if stepped is None:
        return contact_state3d(E, V, drive.S0, o, drive.axes, drive.radii, om, odot, drive.prm)
    return contact_state3d_stepped(E, V, drive.S0, o, drive.axes, drive.radii, om, odot,
                                   drive.prm, np.ascontiguousarray(stepped[0]),
                                   float(stepped[1]))


def _state_along(drive, z0, xi) -> np.ndarray:
    """The state z0 (nel, n n, np, 2) at the march's n x n Gauss points (q = n i + j, i
    along the belt) carried to the points (xi_k, y_j) of each element, k major: linear
    along the belt between the Gauss points of each row j, periodic (the belt is closed)."""
    nel = z0.shape[0]
    n = int(round(np.sqrt(z0.shape[1])))
    tg, _ = gauss01(n)
    rows = np.reshape(z0, (nel, n, n, *z0.shape[2:]))  # e, i, j, p, c
    at = (np.arange(nel)[:, None] + np.asarray(xi)[None, :]).ravel()
    g = (np.arange(nel)[:, None] + tg[None, :]).ravel()
    out = np.empty((nel, np.size(xi), n, *z0.shape[2:]))
    for j in range(n):
        for p in range(z0.shape[2]):
            for c in range(z0.shape[3]):
                out[:, :, j, p, c] = np.interp(at, g, rows[:, :, j, p, c].ravel(),
                                               period=nel).reshape(nel, np.size(xi))
    return np.ascontiguousarray(out.reshape(nel, np.size(xi) * n, *z0.shape[2:]))


def width_contact(drive, x, v, t: float, npts: int = DEFAULT_POINTS, state=None) -> tuple:
    """(normal, friction) (nel * npts,) N/m: the pulleys' force on the belt per unit
    length at the points of a :func:`line_sample` along the belt (xi = (j + 1/2) / npts
    of each element), the contact state of :func:`ancf.belts.contact3d.contact_state3d`
    at the contact rule's n Gauss points across the width integrated over it and summed
    over the pulleys: the normal force F_n and the friction along each pulley's
    counter-clockwise tangent p x n (0 off contact); a friction law with a state on
    ``state`` (:func:`_state`), carried to the points by :func:`_state_along`."""
    s, L = drive.spec, drive.lengths
    E, V, o, om, odot = _contact_args(drive, x, v, t)
    yg, wg = gauss01(int(round(np.sqrt(s.contact_points))))
    xi = (np.arange(npts) + 0.5) / npts
    X = np.repeat(xi[None, :] * L[:, None], yg.size, axis=1)
    Y = np.broadcast_to(np.tile(yg * s.width, npts), X.shape)
    S = np.ascontiguousarray(plate36_S(X, Y, np.broadcast_to(L[:, None], X.shape),
                                       np.full_like(X, s.width)))
    stepped, crowns = _state(drive, state), _crowns(drive)
    if crowns is not None:
        r, _, Fn, ft = contact_state3d_crown(E, V, S, o, drive.axes, drive.radii, om, odot,
                                             drive.prm, crowns)[:4]
    elif stepped is None:
        r, _, Fn, ft = contact_state3d(E, V, S, o, drive.axes, drive.radii, om, odot,
                                       drive.prm)[:4]
    else:
        r, _, Fn, ft = contact_state3d_stepped(E, V, S, o, drive.axes, drive.radii, om, odot,
                                               drive.prm, _state_along(drive, stepped[0], xi),
                                               float(stepped[1]))[:4]
    a = r[:, :, None, :] - o[None, None]
    a -= np.einsum("eqpc,pc->eqp", a, drive.axes)[..., None] * drive.axes
    tang = np.cross(drive.axes, a / np.linalg.norm(a, axis=-1, keepdims=True))
    per_width = np.stack([Fn, np.einsum("eqpc,eqpc->eqp", ft, tang)]).sum(axis=-1)
    out = np.einsum("keij,j->kei", per_width.reshape(2, L.size, npts, yg.size), wg * s.width)
    return out[0].ravel(), out[1].ravel()


def end_state(drive, x, v, t: float, measure: str) -> dict:
    """The belt3d scene's results at the final state (span means along the edge y = 0)."""
    means = span_means(drive, line_sample(drive, x, v))
    tensions = {m: {side: means[side][f"tension_{m}_N"] for side in ("tight", "slack")}
                for m in (*MEASURES, "membrane")}
    R = float(drive.radii[1])
    return {"T_tight_N": tensions[measure]["tight"], "T_slack_N": tensions[measure]["slack"],
            "v_tight": means["tight"]["speed"], "v_slack": means["slack"]["speed"],
            "tensions": tensions,
            "torque_from_tensions_Nm": (tensions[measure]["tight"] - tensions[measure]["slack"]) * R,
            "torques_from_tensions_Nm": {m: (tn["tight"] - tn["slack"]) * R
                                         for m, tn in tensions.items()},
            "torque_from_friction_Nm": float(pulley_moments(drive, x, v, t)[1]),
            "penetration_max_m": float(max(contact_sample(drive, x, v, t)[1].max(), 0.0))}
