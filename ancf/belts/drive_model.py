"""The belt model of a drive file: a :class:`ancf.belts.drive_data.DriveDescription` as a
:class:`ancf.belts.drive2d.BeltDrive` (``belt.element = "dufva2d"``) or a
:class:`ancf.belts.drive3d.Belt3DDrive` (``"plate36"``) on any number of pulleys.

The belt (Dufva elements) is laid on the description's wrapped path (the centreline's,
at radius + ``belt.contact_offset``, on either side of the belt: the section's faces are
taken symmetric about the centreline), with its reference length L0; the contact acts on
the centreline at that radius.  Each pulley's law becomes a row of the
:class:`ancf.belts.drive2d.Rig`: ``prescribed`` its angular velocity law, ``fixed``
zero, ``driven`` a free pulley with its inertia, damping and load torque law, ``idler``
a free one without load, ``tensioner`` a free one without load on an arm whose angle is
one more free coordinate (after the pulleys', :mod:`ancf.belts.arm2d`); how each free
pulley's load acts (``load_acts``) is its row of the rig's ``loads``; a pulley's
``centre_shift`` (any law's) is one of the rig's ``motions``
(:func:`ancf.belts.drive_data.centre_motion`), its centre (a tensioner's pivot) moved in
the contact as the march's :func:`ancf.belts.forces.moved_centres`.  A pulley on the
belt's back (``side = -1``) is contact like any other.  The belt's strain-rate damping
(``damping_axial`` dEA, ``damping_bending`` dEI) acts on its axial and bending strain
rates (:func:`ancf.elements.dufva2d.damping_forces`).  The element takes the file's
``axial_strain`` law and :func:`ancf.belts.drive_data.element_modulus` (the file's E, per
stress-free or per laid length; the damping alike).

The plate belt (``plate36``, :class:`ancf.belts.drive3d.Plate3DSpec`) is laid on the same
path in the x-y plane, its width along the pulley axes (+z), with the same pulley rows
(centres at z = 0; a tensioner's arm turns about z through its pivot,
:mod:`ancf.belts.arm3d`); its friction and contact are per
unit area, its weight that of the in-plane gravity.
"""
from __future__ import annotations

import math

import numpy as np

from ancf.belts.arm2d import ARM_COLUMNS, arm_row
from ancf.belts.drive2d import Belt2DSpec, BeltDrive, Rig
from ancf.belts.drive3d import Belt3DDrive, Plate3DSpec
from ancf.belts.friction import ALL_PARAMS
from ancf.belts.pulleys import load_records
from ancf.belts.drive_data import (ROLES, DriveDescription, centre_motion, element_modulus,
                                   laid_factor)


def _arms(d: DriveDescription, free) -> np.ndarray:
    """The tensioners' arm rows (ancf.belts.arm2d), their coordinates after the k free
    pulleys'."""
    k = int(free.max()) + 1
    rows = []
    for i, p in enumerate(d.pulleys):
        if ROLES[p.law].arm:
            P, c = p.params["pivot"], p.centre
            rows.append(arm_row(pulley=i, coord=k + len(rows), pivot=P,
                                length=p.params["arm_length"],
                                beta0=math.atan2(c[1] - P[1], c[0] - P[0]),
                                stiffness=p.params["arm_stiffness"],
                                preload=p.params["arm_preload"]))
    return np.array(rows, dtype=float).reshape(-1, ARM_COLUMNS)


def rig(d: DriveDescription, dim: int = 2) -> Rig:
    """The pulleys of the description as the march sees them, centres in the x-y plane of
    ``dim`` dimensions."""
    offset = d.belt["contact_offset"]
    roles = [ROLES[p.law] for p in d.pulleys]
    free = np.cumsum([r.free for r in roles]) - 1
    free = np.array([j if r.free else -1 for r, j in zip(roles, free)])
    chosen = [p for p, r in zip(d.pulleys, roles) if r.free]
    arms = [p for p, r in zip(d.pulleys, roles) if r.arm]
    centres = np.zeros((len(d.pulleys), dim))
    centres[:, :2] = [p.centre for p in d.pulleys]
    return Rig(names=tuple(p.name for p in d.pulleys), centres=centres,
               radii=np.array([p.radius + offset for p in d.pulleys]), free=free,
               inertia=np.array([p.params["inertia"] for p in chosen]
                                + [p.params["arm_inertia"] for p in arms], dtype=float),
               damping=np.array([p.params["damping"] for p in chosen]
                                + [p.params["arm_damping"] for p in arms], dtype=float),
               laws=tuple(r.time_law(p.params) for p, r in zip(d.pulleys, roles)),
               arms=_arms(d, free), loads=load_records(
                   [(p.params.get("load_acts"), i, p.params)
                    for i, (p, r) in enumerate(zip(d.pulleys, roles)) if r.free]
                   + [(None, -1, {})] * len(arms)),
               motions=tuple(m for m in (centre_motion(p, i, dim)
                                         for i, p in enumerate(d.pulleys)) if m is not None))


def _friction(d: DriveDescription) -> tuple:
    """The friction law named in the file, with its parameters."""
    f = d.friction
    return (f["law"], *(f[q.name] for q in ALL_PARAMS[f["law"]]))


def spec3d(d: DriveDescription) -> Plate3DSpec:
    """The plate belt and its contact."""
    b, c = d.belt, d.contact
    return Plate3DSpec(path=d.path, belt_length=b["length"], n_elements=b["n_elements"],
                       E=b["E"], nu=b["nu"], rho=b["rho"], width=b["b"], h=b["h"],
                       bending=b["bending"] == "on", k_p=c["k_p"], c_p=c["c_p"],
                       friction=_friction(d), contact_points=c["gauss_points"],
                       ng=b["elastic_points"])


def spec(d: DriveDescription) -> Belt2DSpec:
    """The belt and its contact (the friction law named in the file, with its parameters)."""
    b, c = d.belt, d.contact
    return Belt2DSpec(path=d.path, belt_length=b["length"], n_elements=b["n_elements"],
                      E=element_modulus(b), nu=b["nu"], rho=b["rho"], b=b["b"], h=b["h"],
                      ks=b["ks"], alpha1=b["alpha1"], alpha2=b["alpha2"],
                      nx=b["elastic_points"], k_p=c["k_p"], c_p=c["c_p"],
                      friction=_friction(d), gauss_points=c["gauss_points"],
                      axial=b["axial_strain"])


def build(d: DriveDescription) -> BeltDrive | Belt3DDrive:
    """The drive's model (2D: the damping times
    :func:`ancf.belts.drive_data.laid_factor`)."""
    b = d.belt
    if b["element"] == "plate36":
        return Belt3DDrive(spec3d(d), rig(d, dim=3), d.gravity)
    return BeltDrive(spec(d), rig(d), d.gravity,
                     laid_factor(b) * np.array([b["damping_axial"], b["damping_bending"]]),
                     d.run["damping_jacobian"])
