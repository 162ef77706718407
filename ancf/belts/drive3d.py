"""The 3D belt drive as a model (thesis sections 4.5-4.6): a closed belt of thin
``plate36`` elements on its pulleys, distributed penalty contact with friction over
each element's mid surface (:mod:`ancf.belts.contact3d`).  The thesis drive (a
:class:`Belt3DSpec`): two pulleys, a driver with prescribed angular velocity (Eq. 3.29)
that may be moved to pre-tension the belt (Eq. 4.46), and a driven pulley whose
rotation is a generalised coordinate loaded by the opposing torque (Eq. 4.47).  Any
other layout (a :class:`Plate3DSpec` on a :class:`ancf.belts.path.PulleyPath` of N
pulleys, the pulleys a :class:`ancf.belts.drive2d.Rig`, as a drive file gives them:
:mod:`ancf.belts.drive_model`): each pulley turned by its law or free (its angle a
coordinate with inertia, damping and a load torque), the belt under in-plane gravity.

Geometry: the belt path (:class:`ancf.belts.path.TwoPulleyPath` or ``PulleyPath``) in
the x-y plane, pulley axes along +z, the belt's width along z from 0 to ``width``.  One element
across the width: element i has the nodes A = (i, 0), B = (i + 1, 0), C = (i + 1, 1),
D = (i, 1) (position along the belt, edge), node (i, j) numbered 2 i + j and node n
taken as node 0, so the loop is closed without constraint equations.  Element x runs
along the belt, element y across it (global z).  The laid belt: r on the path at
equal spacing P/n, ``r_x`` = t P / L0 (the stretch of the flat reference of length
L0 / n, so a belt shorter than the path starts pre-tensioned), ``r_y`` = e_z.

Coordinates: the belt's nodal coordinates in the numbering of a
:class:`ancf.core.pattern.ReducedPattern` (band), then the free pulleys' angles.  The
mass matrix is constant: band storage ``Mb`` for the belt, ``inertia`` for the pulleys.
The thesis drive's pulleys are :func:`ancf.belts.drive2d.thesis_rig`'s: pulley 0 the
driver (left), pulley 1 the driven one; the driver moves by u(t) along ``shift`` = -e_x
(away from the driven pulley: it tightens the belt), a prescribed centre motion
(:class:`ancf.belts.pulleys.CentreMotion`) like any drive file's pulley's.  The march's
pulley laws are one row per pulley followed by each centre motion's u and its rate
(:meth:`ancf.belts.drive2d.PulleyDrive.laws`).
"""
from __future__ import annotations

from dataclasses import dataclass, replace

import numpy as np
import scipy.sparse as sp

from ancf.belts import friction
from ancf.belts.arm3d import Drive3DArms
from ancf.belts.drive2d import DriveSpec, PulleyDrive, Rig, thesis_rig
from ancf.belts.path import laid_belt
from ancf.belts.contact3d import contact_forces3d, contact_points3d, contact_state3d
from ancf.belts.flange3d import NO_FLANGES
from ancf.belts.forces import Drive3D
from ancf.elements.plate36 import Plate36
from ancf.core.pattern import ReducedPattern, scatter
from ancf.belts.pulleys import SPEED_LAWS, TORQUE_LAWS, CentreMotion, driver_shift, law

PER_NODE = 9  # r, r_x, r_y, 3 components each
SHIFT = np.array([-1.0, 0.0, 0.0])  # direction the driver is moved in (Eq. 4.46)
AXIS = np.array([0.0, 0.0, 1.0])    # pulley axes
#: the friction state of a stateless law's drive (2, 0, 0, 0, 2): the record's z has the
#: type of a state's, so a drive with a state and one without share the march's compilation
NO_STATE = np.zeros((2, 0, 0, 0, 2))


@dataclass(frozen=True, kw_only=True)
class Plate3DSpec(DriveSpec):
    """The plate belt and its contact (SI units; see the belt3d scene)."""

    width: float                # belt width w, m
    h: float                    # thickness, m
    bending: bool               # Eq. 4.17 on (Model 1) or off (Model 2)
    k_p: float                  # penalty stiffness per unit area, N/m^3
    c_p: float                  # penalty damping per unit area, N s/m^3
    friction: tuple             # (law, its parameters): a row of ancf.belts.friction.ALL_PARAMS
    contact_points: int         # surface rule per element (25, 49, 81)
    ng: int = 4                 # Gauss points per direction, elastic forces


@dataclass(frozen=True, kw_only=True)
class Belt3DSpec(Plate3DSpec):
    """Everything that defines the thesis's 3D belt drive (SI units; see the belt3d scene)."""

    inertia: float              # driven pulley moment of inertia, kg m^2
    omega_final: float          # driver's final angular velocity, rad/s (Eq. 3.29)
    t0: float                   # start of the ramps, s
    t1: float                   # end of the driver ramp, s (Table 4.1)
    Ta_max: float               # final opposing torque, N m (Eq. 4.47)
    Ta_t1: float                # end of the torque ramp, s (Eq. 4.47: 1.0)
    u0: float                   # driver displacement, m (Eq. 4.46; 0: none)
    driver_law: str = "ramp"    # the driver's speed law (ancf.belts.pulleys.SPEED_LAWS)
    torque_law: str = "cosine-ramp"  # the load torque law (TORQUE_LAWS)


def ring_dofmap(n: int) -> np.ndarray:
    """(n, 36) element DOF maps of a closed ring of n plates, one across the width."""
    i = np.arange(n)
    nodes = np.stack([2 * i, 2 * ((i + 1) % n), 2 * ((i + 1) % n) + 1, 2 * i + 1], 1)
    return (nodes[:, :, None] * PER_NODE + np.arange(PER_NODE)).reshape(n, -1)


def laid_plate_belt(path, L0: float, n: int, width: float) -> np.ndarray:
    """Global coordinates (2 n * 9,) of the belt laid on the path (module docstring)."""
    q2 = laid_belt(path, L0, n)  # (n, 3, 2): r, r_x, r_y of the planar belt
    q = np.zeros((n, 2, 3, 3))
    for j, z in enumerate((0.0, width)):
        q[:, j, 0, :2], q[:, j, 0, 2] = q2[:, 0], z
        q[:, j, 1, :2] = q2[:, 1]
        q[:, j, 2] = AXIS
    return q.ravel()


class Belt3DDrive(PulleyDrive):
    """The assembled model of a :class:`Belt3DSpec` (the thesis drive), or of a
    :class:`Plate3DSpec` on any path with the pulleys of ``rig`` (centres (np, 3) in the
    x-y plane) and the belt's weight under the in-plane ``gravity`` (m/s^2)."""

    contact_state = staticmethod(contact_state3d)
    contact_forces = staticmethod(contact_forces3d)

    def __init__(self, spec: Plate3DSpec, rig: Rig | None = None, gravity=(0.0, 0.0)):
        self.spec = s = spec
        n = s.n_elements
        self.dofmap = ring_dofmap(n)
        self.n_dofs = 2 * n * PER_NODE
        self.q0 = laid_plate_belt(s.path, s.belt_length, n, s.width)
        self.lengths = np.full(n, s.belt_length / n)
        self.element = Plate36(self.lengths, s.width, s.h, s.E, s.nu, s.rho, bending=s.bending,
                               ng=s.ng)
        self.pattern = ReducedPattern(self.n_dofs, [self.dofmap],
                                      sp.identity(self.n_dofs, format="csr"))
        self.vidx, self.midx = self.pattern.groups[0]
        self.Mb = self.pattern.zeros_matrix()
        scatter(np.zeros((n, 36)), self.element.mass(), self.vidx, self.midx,
                np.zeros(self.pattern.n), self.Mb, True)
        self.weight = self.pattern.restrict(self._weight(gravity))
        self.S0, self.w = contact_points3d(self.lengths, np.full(n, s.width), s.contact_points)
        self.prm = friction.contact_record(s.k_p, s.c_p, *s.friction)
        if rig is None:
            self.speed_law = law(SPEED_LAWS, s.driver_law, "driver_law")
            self.torque_law = law(TORQUE_LAWS, s.torque_law, "torque_law")
            rig = replace(thesis_rig(s, self.omega_driver, self.torque, dim=3),
                          motions=(CentreMotion(pulley=0, direction=SHIFT, law=self.shift),))
        self.rig = rig
        self.axes = np.tile(AXIS, (rig.radii.size, 1))
        self.flanges = NO_FLANGES  # flanged pulleys (ancf.belts.flange3d.flanges_of)
        self.z = self._friction_state()
        self.h = np.zeros(1)

    def align(self, axes) -> None:
        """Turn the pulley axes to ``axes`` (np, 3), each about its pulley's mid-face point:
        the centres the kernels take are raised to z = w / 2 (on an aligned axis a shift
        along it, which the contact does not see), the axes normalised."""
        axes = np.asarray(axes, dtype=float)
        norms = np.linalg.norm(axes, axis=-1) if axes.shape == self.axes.shape else 0.0
        if not np.all(np.isfinite(norms) & (norms > 0)):
            raise ValueError(f"axes: {axes.shape} array; allowed: {self.axes.shape}, finite, "
                             "no row zero")
        centres = self.rig.centres.copy()
        centres[:, 2] = 0.5 * self.spec.width
        self.rig = replace(self.rig, centres=centres)
        self.axes = axes / norms[:, None]

    def _friction_state(self):
        """The friction state (2, nel, nq, np, 2) m of a law with a state
        (:mod:`ancf.belts.contact3d_state`; not with tensioner arms: ValueError), else None."""
        if not friction.has_state(self.prm):
            return None
        if self.rig.arms.shape[0]:
            raise ValueError(f"friction law {self.spec.friction[0]!r}: its state per contact "
                             "point is not carried by the plate belt's tensioner arms; "
                             "allowed with arms: " + ", ".join(friction.LAWS))
        return np.zeros((2, *self.w.shape, self.rig.radii.size, 2))

    def _weight(self, gravity) -> np.ndarray:
        """The belt's weight as global generalised forces, N: the consistent mass times
        the uniform field (g at every node's r, 0 at its slopes; as the 2D drive's)."""
        G = np.zeros((self.n_dofs // PER_NODE, 3, 3))
        G[:, 0, :2] = gravity
        out = np.zeros(self.n_dofs)
        np.add.at(out, self.dofmap, np.einsum("eab,eb->ea", self.element.mass(),
                                              G.ravel()[self.dofmap]))
        return out

    def omega_driver(self, t):
        return self.speed_law(t, self.spec.omega_final, self.spec.t0, self.spec.t1)

    def torque(self, t):
        return self.torque_law(t, self.spec.Ta_max, self.spec.t0, self.spec.Ta_t1)

    def shift(self, t) -> tuple:
        """The thesis driver's displacement u (m) along :data:`SHIFT` and its rate (m/s) at
        t (s, an array): Eq. 4.46, u0 reached at t0."""
        return driver_shift(t, self.spec.u0, self.spec.t0)

    def pulley_centres(self, t: float) -> np.ndarray:
        """Pulley centres (np, 3) at time t, m (moved by their prescribed motions: the
        thesis driver's Eq. 4.46)."""
        return self.centre_motion(t)[0]

    def element_coords(self, q) -> np.ndarray:
        """(nel, 12, 3) element coordinates from global belt coordinates q."""
        return np.ascontiguousarray(np.asarray(q)[self.dofmap].reshape(-1, 12, 3))

    def fixed_dofs(self) -> list:
        """Node 0's (edge 0) coordinates along the path tangent and along the pulley axes:
        the rigid motions frictionless pulleys leave free (:mod:`ancf.belts.pretension`)."""
        along = int(np.argmax(np.abs(self.q0[3:5])))
        return [along, 2]

    def pulleys_at_rest(self) -> tuple:
        """The pulley arguments of the contact kernels, pulleys at rest: centres (np, 3) m,
        axes (np, 3), radii (np,) m, omegas (np,) rad/s, centre velocities (np, 3) m/s."""
        npul = self.radii.size
        return self.centres, self.axes, self.radii, np.zeros(npul), np.zeros((npul, 3))

    def kernel(self) -> Drive3D:
        """The drive's compiled data (:mod:`ancf.belts.forces`): a
        :class:`ancf.belts.arm3d.Drive3DArms`, arms or none, cylinders or crowned rims, a
        friction state or none (:data:`NO_STATE` then: one type, so one compilation of the
        march, for all of them)."""
        r = self.rig
        moving, shift = self.motion_arrays()
        return Drive3DArms(vidx=self.vidx, midx=self.midx, element=self.element.kernel_data(),
                            S0=self.S0, w=self.w, centres=r.centres, radii=r.radii, prm=self.prm,
                            free=r.free, inertia=r.inertia, damping=r.damping, weight=self.weight,
                            arms=r.arms, z=NO_STATE if self.z is None else self.z, h=self.h,
                            last=np.zeros((2, r.radii.size)), axes=self.axes, moving=moving,
                            shift=shift, flanges=self.flanges)
