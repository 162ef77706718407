"""Misaligned pulleys of the plate belt (``belt.element = "plate36"``): each pulley's axis
from its drive-file keys ``axis_tilt_deg`` and ``axis_roll_deg``
(:data:`ancf.belts.drive_data.ALIGNMENT`), and the belt's tracking on every pulley.

Definitions.  At pulley k (centre c in the x-y plane, the belt's width along z from 0 to
w), the span k-1 -> k reaches it at the tangent point T running along the unit vector d
(the entering span's direction, in the x-y plane); u = (T - c) / |T - c| is the radius
to T, the entering span's in-plane normal there.  With the tilt a and the roll b (rad):

    p = cos b (cos a e_z + sin a d) + sin b u                                   (1)

the tilt turns the axis about u toward d, in the plane (e_z, d) of the entering span
itself; the roll then turns it toward u, across that span's plane (about d).  Both turn
about the pulley's mid-face point f = c + (w / 2) e_z, where the laid belt's mid-line
runs (:meth:`ancf.belts.drive3d.Belt3DDrive.align`)::

    seen along -u (onto T from outside)          seen along d (from behind the entering belt)

          e_z    p                                       e_z     p
           |    /                                         |     /
           | a /                                          |  b /
           |  /                                           |   /
           | /                                            |  /
    -------f-------> d   (span enters at T)        -------f-------> u   (T lies this way)

The tracking rule.  The pulley's surface at T moves along p x u / |p x u| = cos a d -
sin a e_z (b = 0; the same on the belt's back, side -1, where the pulley turns the other
way).  Where the belt meets the surface it moves with it (no slip, Shelton's "normal
entry"), so the belt's entry point s_E = (r_E - f) . p walks along the axis at

    ds_E/dt = -v e . p   (= -v sin a, v tan a to 0.02 % at 1 deg, while e = d)          (2)

v the belt speed, e the entering belt's unit direction: toward the end of the face the
entering belt reaches first (a > 0: toward -z).  The roll alone leaves d . p = 0, the belt
meeting the surface square (no walk by Eq. 2).  As the belt walks the entering span turns
toward the surface's direction (e . p falls from sin a) and the walk slows: on a closed
belt, whose other pulleys hold the span's upstream end, the belt's mean position over the
wrap walks slower than v tan a (tests/belts/test_belt3d_tracking.py: 0.63 v tan a over
the first 0.12 m of travel; its entry point by Eq. 2 within 10 %).  With the span's
upstream end held, its inclination z / L (L its length) gives dz/dt = v (tan a - z / L):
the entry settles at the offset L tan a over a few L of travel (analytic/belt_tracking.py,
Eq. 3; the plate belt's entry point within 8 % over 0.27 to 2.1 L of travel).

Per pulley, at every output sample (:func:`histories`): ``lateral_position_m``, the mean
over the belt's contact points on it (penetration > 0, weighted by their areas) of
(r - f) . p, m; ``axial_force_N``, the pulley's contact force on the belt along p summed
over the points, N (the friction's: the normal n is normal to p), with its flanges' force
on the belt's edges (:mod:`ancf.belts.flange3d`); ``flange_force_N``, the flanges' part
alone, N (0 on a pulley without flanges).  On a crowned drive
(:mod:`ancf.belts.contact3d_state`, crowned rims) the points in contact are those of the
crowned rim, f is the face's mid-plane point (z_m = w / 2 + ``face_offset_m``) and the
axial force includes the normal force's part along p (nu . p = -R' / g).
"""
from __future__ import annotations

import numpy as np

from ancf.belts import flange3d, friction, post3d
from ancf.belts.contact3d_state import contact_state3d_crown
from ancf.belts.drive_data import ROLES
from ancf.common.params import InputError

#: the steepest crown: its rim's slope at the face's ends, |R'(W/2)| = 4 c / W (rad).  Flat-
#: belt pulleys are crowned to 0.3-1 mm on faces of 40-250 mm (ISO 22), slopes below 0.03;
#: a steeper crown pokes through a belt laid flat across it (a membrane across its width)
#: and sets the pulleys rocking before the drive starts (0.5 rad/s on three_pulleys_3d's
#: idler at slope 0.045, 26 rad/s at 0.45)
MAX_CROWN_SLOPE = 0.1


def pulley_axes(desc) -> np.ndarray:
    """The unit axes p (np, 3) of Eq. 1 from a description's pulleys' ``axis_tilt_deg`` and
    ``axis_roll_deg`` on its wrapped path."""
    path = desc.path
    out = np.zeros((len(desc.pulleys), 3))
    for k, q in enumerate(desc.pulleys):
        span = path.spans[k - 1]
        d = (span.end - span.start) / span.length
        u = span.end - np.asarray(q.centre, dtype=float)
        u /= np.linalg.norm(u)
        a, b = np.radians([q.params["axis_tilt_deg"], q.params["axis_roll_deg"]])
        out[k, :2] = np.cos(b) * np.sin(a) * d + np.sin(b) * u
        out[k, 2] = np.cos(b) * np.cos(a)
    return out


def misaligned(desc) -> bool:
    """Whether any pulley's axis is turned (a tilt or a roll other than 0)."""
    keys = ("axis_tilt_deg", "axis_roll_deg")
    return any(q.params[key] != 0.0 for q in desc.pulleys for key in keys)


def align(drive, desc):
    """The plate belt's ``drive`` with the axes of :func:`pulley_axes` when a pulley is
    misaligned (an aligned drive is left as built) and the flanges of its flanged pulleys
    (:func:`ancf.belts.flange3d.flanges_of`), returned."""
    if misaligned(desc):
        drive.align(pulley_axes(desc))
    drive.flanges = flange3d.flanges_of(drive, desc)
    crowns = crowns_of(desc)
    if crowns is not None:
        drive.flanges = drive.flanges._replace(crowns=crowns)
    return drive


def crowns_of(desc):
    """(np, 3) per pulley crown c (m), mid-face z_m (m), W / 2 (m) (:mod:`ancf.belts.
    contact3d_state`, crowned rims) of a plate-belt description with a crowned pulley, else
    None; a crown on a tensioner, with a friction law carrying a state, not below the
    pulley's radius or steeper than :data:`MAX_CROWN_SLOPE`: InputError (one line naming
    the key and its allowed range)."""
    if desc.belt["element"] != "plate36" or not any(
            q.params.get("crown_m", 0.0) > 0 for q in desc.pulleys):
        return None
    w, rows = desc.belt["b"], []
    for i, q in enumerate(desc.pulleys):
        c = q.params["crown_m"]
        if c >= q.radius:
            raise InputError(f"pulleys.{i}.crown_m = {c!r} is out of range: not below the "
                             f"pulley's radius {q.radius:g} m; allowed: a number in "
                             f"[0, {q.radius:g}) m")
        if c > 0 and ROLES[q.law].arm:
            raise InputError(f"pulleys.{i}.crown_m = {c!r} is out of range for law = "
                             f"{q.law!r}; allowed: 0 (a tensioner's pulley is a cylinder)")
        face = flange3d.face_width(q.params, w)
        if 4 * c / face > MAX_CROWN_SLOPE:
            raise InputError(f"pulleys.{i}.crown_m = {c!r} is out of range: its slope at the "
                             f"face's ends 4 c / W = {4 * c / face:.3g} is above "
                             f"{MAX_CROWN_SLOPE:g} (W = {face:g} m the face width); allowed: "
                             f"a number in [0, {MAX_CROWN_SLOPE * face / 4:.4g}] m")
        rows.append((c, 0.5 * w + q.params["face_offset_m"],
                     0.5 * face))
    if desc.friction["law"] not in friction.LAWS:
        raise InputError(f"friction.law = {desc.friction['law']!r} is out of range with a "
                         "crowned pulley (crown_m > 0); allowed: one of "
                         f"{', '.join(friction.LAWS)} (no state per contact point)")
    return np.array(rows, dtype=float)


def tracking(drive, x, v, t: float, state=None) -> tuple:
    """(lateral (np,) m, axial (np,) N, flange (np,) N) at state (x, v), time t (s): the
    module docstring's per-pulley quantities (NaN lateral position off contact); ``state``
    a friction law's (:func:`ancf.belts.post3d.contact_sample`)."""
    crowns = drive.flanges.crowns
    o, odot = drive.moved(x, v, t)
    if crowns.shape[0]:
        E, V, o2, om, od2 = post3d._contact_args(drive, x, v, t)
        r, d, Fn, ft, _, _, nu = contact_state3d_crown(E, V, drive.S0, o2, drive.axes,
                                                       drive.radii, om, od2, drive.prm, crowns)
        ft = ft + Fn[..., None] * nu  # the crowned rim's normal has a part along p
    else:
        r, d, _, ft = post3d.contact_sample(drive, x, v, t, state)[:4]
    f = o.copy()
    f[:, 2] = 0.5 * drive.spec.width if not crowns.shape[0] else crowns[:, 1]
    y = np.einsum("eqpc,pc->eqp", r[:, :, None, :] - f, drive.axes)
    W = drive.w[:, :, None] * (d > 0)
    area = W.sum(axis=(0, 1))
    lateral = np.divide((W * y).sum(axis=(0, 1)), area, out=np.full(area.size, np.nan),
                        where=area > 0)
    E, V = drive.element_coords(drive.belt(x)), drive.element_coords(drive.belt(v))
    flange = flange3d.axial_forces(drive, E, V, o, odot)
    return lateral, np.einsum("eqp,eqpc,pc->p", W, ft, drive.axes) + flange, flange


def histories(drive, res) -> list:
    """Per pulley {"lateral_position_m", "axial_force_N", "flange_force_N"}: :func:`tracking`
    at every sample of the march's result ``res`` (its friction state where the law has
    one)."""
    states = res.extra.get("friction_state", [None] * res.t.size)
    got = [tracking(drive, x, v, float(t), z) for x, v, t, z in zip(res.q, res.v, res.t,
                                                                      states)]
    lateral, axial, flange = (np.array([g[i] for g in got]) for i in (0, 1, 2))
    return [{"lateral_position_m": lateral[:, k].tolist(), "axial_force_N": axial[:, k].tolist(),
             "flange_force_N": flange[:, k].tolist()} for k in range(lateral.shape[1])]
