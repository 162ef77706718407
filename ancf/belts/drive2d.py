"""The 2D belt drive as a model: a closed belt of Dufva elements on the wrapped path of
its pulleys, penalty contact with creep-rate friction on every pulley, pulleys turned
by their laws (a driver's prescribed angular velocity; a fixed pulley's zero) and free
pulleys (driven pulleys and idlers) whose rotations are generalised coordinates.

Coordinates: the belt's nodal coordinates (node by node r, r_x, r_y; the loop is
closed by the last element sharing the first node, so there are no constraint
equations, thesis section 3.3) in the numbering of a :class:`ReducedPattern`
(reverse Cuthill-McKee: a ring has a narrow band once renumbered), followed by the
free pulleys' angles theta_j (rad).  The mass matrix is constant: band storage ``Mb``
for the belt, the free pulleys' ``inertia``.

The pulleys are a :class:`Rig`.  The thesis drive's (a :class:`BeltSpec`): pulley 0
the driver (left, ``omega_driver(t)``), pulley 1 the driven one.
"""
from __future__ import annotations

from dataclasses import dataclass, field
from typing import Callable

import numpy as np
import scipy.sparse as sp

from ancf.belts import friction
from ancf.belts.arm2d import ARM_COLUMNS, COORD, arm_geometry
from ancf.belts.path import TwoPulleyPath, laid_belt
from ancf.belts.contact2d import NO_STATE, contact_forces, contact_points, contact_state
from ancf.belts.forces import DAMPING_JACOBIANS, Drive2D
from ancf.elements.dufva2d import DufvaBelt2D
from ancf.core.mesh import BeamMesh
from ancf.core.pattern import ReducedPattern, scatter
from ancf.belts.pulleys import SPEED_LAWS, T0, T1, TORQUE_LAWS, law
from ancf.core.quadrature import RectangularSection

SLOTS = ("r", "r_x", "r_y")


@dataclass(frozen=True, kw_only=True)
class DriveSpec:
    """What every belt drive's spec starts with (SI units)."""

    path: TwoPulleyPath
    belt_length: float          # reference (unstretched) length L0, m
    n_elements: int
    E: float                    # Young's modulus, Pa
    nu: float                   # Poisson's ratio (in 2D: the shear modulus only)
    rho: float                  # density, kg/m^3


@dataclass(frozen=True, kw_only=True)
class Belt2DSpec(DriveSpec):
    """The belt and its contact (SI units; see the belt2d scene)."""

    b: float                    # section width, m
    h: float                    # section height, m
    ks: float                   # shear correction factor
    alpha1: float               # axial stiffness parameter (Eq. 3.18)
    alpha2: float               # bending stiffness parameter (Eqs 3.18-3.19)
    nx: int                     # Gauss points of the elastic forces per element
    k_p: float                  # penalty stiffness per unit length, N/m^2
    c_p: float                  # penalty damping per unit length, N s/m^2
    friction: tuple             # (law, its parameters): a row of ancf.belts.friction.ALL_PARAMS
    gauss_points: int           # contact Gauss points per element (3, 4, 5, 7, 11)
    axial: str = "green"        # axial strain law (dufva2d.AXIAL_LAWS)


@dataclass(frozen=True, kw_only=True)
class BeltSpec(Belt2DSpec):
    """Everything that defines the thesis's two-pulley drive (SI units; see the belt2d
    scene)."""

    inertia: float              # driven pulley moment of inertia, kg m^2
    omega_final: float          # driver's final angular velocity, rad/s (Eq. 3.29)
    Ta_max: float               # final opposing torque, N m (Eq. 3.30)
    driver_law: str = "ramp"    # the driver's speed law (ancf.belts.pulleys.SPEED_LAWS)
    torque_law: str = "cosine-ramp"  # the load torque law (TORQUE_LAWS)


@dataclass(frozen=True, kw_only=True)
class Rig:
    """The pulleys of a drive as the march sees them (SI units): ``names`` (np,),
    ``centres`` (np, dim) m, contact ``radii`` (np,) m, ``free`` (np,) int (the free
    pulley's number j, -1 for a pulley turned by its law), the free pulleys' ``inertia``
    (k,) kg m^2 and rotational ``damping`` (k,) N m s, one law per pulley, a function of
    the time (s, an array): the angular velocity (rad/s) of a pulley turned by it, the
    load torque T_a (N m) of a free one, and the tensioners' ``arms`` (na, ARM_COLUMNS)
    (:mod:`ancf.belts.arm2d`; their angles are free coordinates too, with an inertia and
    a damping), how each free coordinate's load acts, ``loads`` (k,)
    (:func:`ancf.belts.pulleys.load_records`; None: every load signed) and the prescribed
    centre ``motions`` (:class:`ancf.belts.pulleys.CentreMotion`, at most one per pulley;
    a tensioner's carries its pivot)."""

    names: tuple
    centres: np.ndarray
    radii: np.ndarray
    free: np.ndarray
    inertia: np.ndarray
    damping: np.ndarray
    laws: tuple[Callable, ...]
    arms: np.ndarray = field(default_factory=lambda: np.zeros((0, ARM_COLUMNS)))
    loads: np.ndarray | None = None  # (k,) LOAD records (ancf.belts.pulleys; None: signed)
    motions: tuple = ()  # prescribed centre motions (ancf.belts.pulleys.CentreMotion)


def thesis_rig(spec: BeltSpec, speed, torque, dim: int = 2) -> Rig:
    """The thesis drive's pulleys: the driver (``speed(t)``) and the driven pulley
    (``torque(t)``, no damping), centres in the x-y plane of ``dim`` dimensions."""
    path = spec.path
    centres = np.zeros((2, dim))
    centres[:, :2] = [path.O1, path.O2]
    return Rig(names=("driver", "driven"), centres=centres, radii=np.array([path.R1, path.R2]),
               free=np.array([-1, 0]), inertia=np.array([float(spec.inertia)]),
               damping=np.zeros(1), laws=(speed, torque))


class PulleyDrive:
    """What the 2D and 3D belt drives share: a belt in the numbering of ``pattern``
    (``n_dofs`` global coordinates) followed by the free pulleys' angles, the pulleys
    (``rig``: :class:`Rig`), and the contact of its elements E (nel, nshape, dim) with
    the pulleys through the subclass's kernels ``contact_state`` and ``contact_forces``
    (staticmethods, the pulley arguments from :meth:`pulleys_at_rest`)."""

    @property
    def n(self) -> int:
        """Belt coordinates (the free pulleys' angles are coordinates n, n + 1, ...)."""
        return self.pattern.n

    @property
    def k(self) -> int:
        """Free pulleys."""
        return self.rig.inertia.size

    @property
    def centres(self) -> np.ndarray:
        return self.rig.centres

    @property
    def radii(self) -> np.ndarray:
        return self.rig.radii

    def moved(self, x, v, t: float = 0.0) -> tuple:
        """The pulley centres (np, 2) m and their velocities (np, 2) m/s at the system
        state x, v and time t (s): moved by their prescribed motions, a tensioner's on its
        arm (its pivot moved alike)."""
        arms = self.rig.arms
        o, odot = self.centre_motion(t)
        for a in range(arms.shape[0]):
            j = self.n + int(arms[a, COORD])
            p = arm_geometry(arms, a, float(x[j]), float(v[j]), o, odot,
                             np.zeros((arms.shape[0], 2)))
            for q, du, dv in self._displacements(t):
                if q == p:
                    o[p] += du
                    odot[p] += dv
        return o, odot

    def _displacements(self, t: float) -> list:
        """(pulley, displacement (dim,) m, velocity (dim,) m/s) of each centre motion at
        time t (s)."""
        law, npul = self.laws(np.array([t]))[:, 0], self.radii.size
        return [(m.pulley, law[npul + 2 * i] * m.direction, law[npul + 2 * i + 1] * m.direction)
                for i, m in enumerate(self.rig.motions)]

    def centre_motion(self, t: float) -> tuple:
        """The pulley centres (np, dim) m at time t (s) and their velocities (np, dim) m/s,
        moved by their prescribed motions (the march's
        :func:`ancf.belts.forces.moved_centres`)."""
        o, odot = self.centres.copy(), np.zeros_like(self.centres)
        for p, du, dv in self._displacements(t):
            o[p] += du
            odot[p] = dv
        return o, odot

    def laws(self, t) -> np.ndarray:
        """The pulley laws (np + 2 m, len(t)) of the march (:class:`Rig`): one per pulley,
        then each of the m centre motions' distance u (m) and its rate (m/s)."""
        t = np.atleast_1d(np.asarray(t, dtype=float))
        rows = [law(t) for law in self.rig.laws]
        for m in self.rig.motions:
            rows.extend(np.broadcast_to(r, t.shape) for r in m.law(t))
        return np.stack(rows)

    def motion_arrays(self) -> tuple:
        """The kernels' ``moving`` (m,) int and ``shift`` (m, dim) of the rig's motions."""
        dim = self.centres.shape[1]
        moving = np.array([m.pulley for m in self.rig.motions], dtype=np.int64)
        shift = np.array([m.direction for m in self.rig.motions], dtype=float).reshape(-1, dim)
        return moving, shift

    def omegas(self, t: float, v) -> np.ndarray:
        """Every pulley's angular velocity (np,) at time t (s) and system velocities v,
        rad/s."""
        law = self.laws(np.array([t]))[: self.radii.size, 0]
        j = self.rig.free
        return np.where(j < 0, law, np.asarray(v)[self.n + np.maximum(j, 0)])

    def state(self, q) -> np.ndarray:
        """System vector (belt in pattern numbering, then the pulley angles 0) from global
        belt q."""
        return np.append(self.pattern.restrict(q), np.zeros(self.k))

    def belt(self, x) -> np.ndarray:
        """Global belt coordinates from a system vector."""
        return self.pattern.expand(np.asarray(x)[: self.n], np.zeros(self.n_dofs))

    def penalty(self, E, want_J: bool):
        """Frictionless, undamped contact at rest: (energy sum w k_p d^2/2 J, Q (nel, ndof) N,
        dQ/de (nel, ndof, ndof) N/m or None), ndof = nshape dim."""
        nel, nd, npul = E.shape[0], E.shape[1] * E.shape[2], self.radii.size
        V, pulleys = np.zeros_like(E), self.pulleys_at_rest()
        prm = friction.contact_record(self.spec.k_p, 0.0, "creep-rate", 0.0, 0.0)
        d = self.contact_state(E, V, self.S0, *pulleys, prm)[1]
        U = 0.5 * self.spec.k_p * np.einsum("eg,egp->", self.w, np.maximum(d, 0.0) ** 2)
        if not want_J:
            return float(U), None, None
        Q, Kq = np.zeros((nel, nd)), np.zeros((nel, nd, nd))
        self.contact_forces(E, V, self.S0, self.w, *pulleys, prm, True, Q, Kq, np.zeros_like(Kq),
                            np.zeros((nel, npul, nd)), np.zeros(npul), np.zeros((npul, nel, nd)),
                            np.zeros((npul, nel, nd)), np.zeros(npul))
        return float(U), Q, Kq


class BeltDrive(PulleyDrive):
    """The assembled model of a belt on its pulleys: a :class:`BeltSpec` (the thesis
    drive), or a :class:`Belt2DSpec` on any path with the pulleys of ``rig``, the
    belt's weight under ``gravity`` (m/s^2) and its strain-rate ``damping`` (dEA N s,
    dEI N m^2 s; :func:`ancf.elements.dufva2d.damping_forces`), whose part of the march's
    iteration matrix is ``damping_jacobian`` (:data:`ancf.belts.forces.DAMPING_JACOBIANS`)."""

    contact_state = staticmethod(contact_state)
    contact_forces = staticmethod(contact_forces)

    def __init__(self, spec: Belt2DSpec, rig: Rig | None = None, gravity=(0.0, 0.0),
                 damping=(0.0, 0.0), damping_jacobian: str = "exact"):
        self.spec = s = spec
        self.strain_damping = np.array(damping, dtype=float)
        self.damping_jacobian = DAMPING_JACOBIANS.index(damping_jacobian)
        self.mesh = BeamMesh(s.belt_length, s.n_elements, SLOTS, closed=True)
        self.q0 = laid_belt(s.path, s.belt_length, s.n_elements).ravel()
        self.element = DufvaBelt2D(self.mesh.lengths, self.q0[self.mesh.dofmap],
                                   RectangularSection(s.b, s.h), E=s.E, nu=s.nu, rho=s.rho,
                                   alpha1=s.alpha1, alpha2=s.alpha2, ks=s.ks, nx=s.nx,
                                   axial=s.axial)
        n = self.mesh.n_dofs
        self.pattern = ReducedPattern(n, [self.mesh.dofmap], sp.identity(n, format="csr"))
        self.vidx, self.midx = self.pattern.groups[0]
        self.Mb = self.pattern.zeros_matrix()
        scatter(np.zeros((s.n_elements, 12)), self.element.mass(), self.vidx, self.midx,
                np.zeros(self.pattern.n), self.Mb, True)
        self.weight = self.pattern.restrict(self._weight(gravity))
        self.S0, self.w, self.xi = contact_points(self.mesh.lengths, s.gauss_points)
        self.prm = friction.contact_record(s.k_p, s.c_p, *s.friction)
        if rig is None:
            self.speed_law = law(SPEED_LAWS, s.driver_law, "driver_law")
            self.torque_law = law(TORQUE_LAWS, s.torque_law, "torque_law")
            rig = thesis_rig(s, self.omega_driver, self.torque)
        self.rig = rig
        self.z = (np.zeros((2, *self.w.shape, rig.radii.size))  # Drive2D.z
                  if friction.has_state(self.prm) else NO_STATE)
        self.h = np.zeros(1)

    def _weight(self, gravity) -> np.ndarray:
        """The belt's weight as global generalised forces, N: the consistent mass times
        the uniform field (g at every node's r, 0 at its slopes; the position shape
        functions sum to 1, so this is int rho A S^T g dx exactly)."""
        G = np.zeros((self.mesh.n_nodes, len(SLOTS), 2))
        G[:, 0] = gravity
        Ge = G.ravel()[self.dofmap]
        out = np.zeros(self.n_dofs)
        np.add.at(out, self.dofmap, np.einsum("eab,eb->ea", self.element.mass(), Ge))
        return out

    def omega_driver(self, t):
        """The thesis driver's angular velocity (Eq. 3.29), rad/s."""
        return self.speed_law(t, self.spec.omega_final, T0, T1)

    def torque(self, t):
        """The thesis drive's load torque on the driven pulley (Eq. 3.30), N m."""
        return self.torque_law(t, self.spec.Ta_max, T0, T1)

    @property
    def dofmap(self) -> np.ndarray:
        return self.mesh.dofmap

    @property
    def n_dofs(self) -> int:
        return self.mesh.n_dofs

    def element_coords(self, q) -> np.ndarray:
        """(nel, 6, 2) element coordinates from global belt coordinates q."""
        return np.ascontiguousarray(np.asarray(q)[self.dofmap].reshape(-1, 6, 2))

    def pulleys_at_rest(self) -> tuple:
        """The pulley arguments of the contact kernels, pulleys at rest: centres (np, 2) m,
        radii (np,) m, omegas (np,) rad/s."""
        return self.centres, self.radii, np.zeros(self.radii.size)

    def fixed_dofs(self) -> list:
        """Node 0's coordinate along the path tangent (the larger component): the rigid
        sliding round frictionless pulleys (:mod:`ancf.belts.pretension`)."""
        return [self.mesh.dof(0, "r", int(np.argmax(np.abs(self.q0[2:4]))))]

    def kernel(self) -> Drive2D:
        """The drive's compiled data (:mod:`ancf.belts.forces`)."""
        r = self.rig
        moving, shift = self.motion_arrays()
        return Drive2D(vidx=self.vidx, midx=self.midx, element=self.element.kernel_data(),
                       strain_damping=self.strain_damping, S0=self.S0, w=self.w,
                       centres=r.centres, radii=r.radii, prm=self.prm, free=r.free,
                       inertia=r.inertia, damping=r.damping, weight=self.weight, arms=r.arms,
                       z=self.z, h=self.h, last=np.zeros((2, r.radii.size)),
                       moving=moving, shift=shift, damping_jacobian=self.damping_jacobian)
