"""The 2D belt drive as a model: a closed belt of Dufva elements on a two-pulley path,
penalty contact with creep-rate friction on both pulleys, a driver with prescribed
angular velocity and a driven pulley whose rotation is a generalised coordinate.

Coordinates: the belt's nodal coordinates (node by node r, r_x, r_y; the loop is
closed by the last element sharing the first node, so there are no constraint
equations, thesis section 3.3) in the numbering of a :class:`ReducedPattern`
(reverse Cuthill-McKee: a ring has a narrow band once renumbered), followed by the
driven pulley's angle theta (rad).  The mass matrix is constant: band storage
``Mb`` for the belt, ``inertia`` for the pulley.

Pulley 0 is the driver (left, ``omega_driver(t)``), pulley 1 the driven one.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import scipy.sparse as sp

from ancf.belts.path import TwoPulleyPath, laid_belt
from ancf.belts.contact2d import contact_forces, contact_points, contact_state
from ancf.belts.forces import Drive2D
from ancf.elements.dufva2d import DufvaBelt2D
from ancf.core.mesh import BeamMesh
from ancf.core.pattern import ReducedPattern, scatter
from ancf.belts.pulleys import SPEED_LAWS, T0, T1, TORQUE_LAWS, law
from ancf.core.quadrature import RectangularSection

SLOTS = ("r", "r_x", "r_y")


@dataclass(frozen=True)
class DriveSpec:
    """What every belt drive's spec starts with (SI units)."""

    path: TwoPulleyPath
    belt_length: float          # reference (unstretched) length L0, m
    n_elements: int
    E: float                    # Young's modulus, Pa
    nu: float                   # Poisson's ratio (in 2D: the shear modulus only)
    rho: float                  # density, kg/m^3


@dataclass(frozen=True)
class BeltSpec(DriveSpec):
    """Everything that defines a belt drive (SI units; see the belt2d scene)."""

    b: float                    # section width, m
    h: float                    # section height, m
    ks: float                   # shear correction factor
    alpha1: float               # axial stiffness parameter (Eq. 3.18)
    alpha2: float               # bending stiffness parameter (Eqs 3.18-3.19)
    nx: int                     # Gauss points of the elastic forces per element
    k_p: float                  # penalty stiffness per unit length, N/m^2
    c_p: float                  # penalty damping per unit length, N s/m^2
    mu: float                   # friction coefficient
    nu_s: float                 # creep-rate factor, kg/(m s)
    gauss_points: int           # contact Gauss points per element (5, 7, 11)
    inertia: float              # driven pulley moment of inertia, kg m^2
    omega_final: float          # driver's final angular velocity, rad/s (Eq. 3.29)
    Ta_max: float               # final opposing torque, N m (Eq. 3.30)
    driver_law: str = "ramp"    # the driver's speed law (ancf.belts.pulleys.SPEED_LAWS)
    torque_law: str = "cosine-ramp"  # the load torque law (TORQUE_LAWS)


class PulleyDrive:
    """What the 2D and 3D belt drives share: a belt in the numbering of ``pattern``
    (``n_dofs`` global coordinates) followed by the driven pulley's angle, and the contact
    of its elements E (nel, nshape, dim) with the pulleys through the subclass's kernels
    ``contact_state`` and ``contact_forces`` (staticmethods, the pulley arguments from
    :meth:`pulleys_at_rest`)."""

    @property
    def n(self) -> int:
        """Belt coordinates (the pulley angle is coordinate n)."""
        return self.pattern.n

    def state(self, q, theta=0.0) -> np.ndarray:
        """System vector (belt in pattern numbering, then theta) from global belt q."""
        return np.append(self.pattern.restrict(q), theta)

    def belt(self, x) -> np.ndarray:
        """Global belt coordinates from a system vector."""
        return self.pattern.expand(np.asarray(x)[: self.n], np.zeros(self.n_dofs))

    def penalty(self, E, want_J: bool):
        """Frictionless, undamped contact at rest: (energy sum w k_p d^2/2 J, Q (nel, ndof) N,
        dQ/de (nel, ndof, ndof) N/m or None), ndof = nshape dim."""
        nel, nd, npul = E.shape[0], E.shape[1] * E.shape[2], self.radii.size
        V, pulleys = np.zeros_like(E), self.pulleys_at_rest()
        prm = np.array([self.spec.k_p, 0.0, 0.0, 0.0])
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
    """The assembled model of a :class:`BeltSpec`."""

    contact_state = staticmethod(contact_state)
    contact_forces = staticmethod(contact_forces)

    def __init__(self, spec: BeltSpec):
        self.spec = s = spec
        self.mesh = BeamMesh(s.belt_length, s.n_elements, SLOTS, closed=True)
        self.q0 = laid_belt(s.path, s.belt_length, s.n_elements).ravel()
        self.element = DufvaBelt2D(self.mesh.lengths, self.q0[self.mesh.dofmap],
                                   RectangularSection(s.b, s.h), E=s.E, nu=s.nu, rho=s.rho,
                                   alpha1=s.alpha1, alpha2=s.alpha2, ks=s.ks, nx=s.nx)
        n = self.mesh.n_dofs
        self.pattern = ReducedPattern(n, [self.mesh.dofmap], sp.identity(n, format="csr"))
        self.vidx, self.midx = self.pattern.groups[0]
        self.Mb = self.pattern.zeros_matrix()
        scatter(np.zeros((s.n_elements, 12)), self.element.mass(), self.vidx, self.midx,
                np.zeros(self.pattern.n), self.Mb, True)
        self.S0, self.w, self.xi = contact_points(self.mesh.lengths, s.gauss_points)
        self.centres = np.array([s.path.O1, s.path.O2], dtype=float)
        self.radii = np.array([s.path.R1, s.path.R2])
        self.prm = np.array([s.k_p, s.c_p, s.mu, s.nu_s])
        self.speed_law = law(SPEED_LAWS, s.driver_law, "driver_law")
        self.torque_law = law(TORQUE_LAWS, s.torque_law, "torque_law")

    def omega_driver(self, t):
        return self.speed_law(t, self.spec.omega_final, T0, T1)

    def torque(self, t):
        return self.torque_law(t, self.spec.Ta_max, T0, T1)

    def laws(self, t) -> np.ndarray:
        """Pulley laws (2, len(t)) of the march: driver omega (rad/s), T_a (N m)."""
        t = np.atleast_1d(np.asarray(t, dtype=float))
        return np.stack([self.omega_driver(t), self.torque(t)])

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
        """The pulley arguments of the contact kernels, pulleys at rest: centres (2, 2) m,
        radii (2,) m, omegas (2,) rad/s."""
        return self.centres, self.radii, np.zeros(2)

    def fixed_dofs(self) -> list:
        """Node 0's coordinate along the path tangent (the larger component): the rigid
        sliding round frictionless pulleys (:mod:`ancf.belts.pretension`)."""
        return [self.mesh.dof(0, "r", int(np.argmax(np.abs(self.q0[2:4]))))]

    def kernel(self) -> Drive2D:
        """The drive's compiled data (:mod:`ancf.belts.forces`)."""
        return Drive2D(self.vidx, self.midx, self.element.kernel_data(), self.S0, self.w,
                       self.centres, self.radii, self.prm, float(self.spec.inertia))
