"""A flat rectangular plate of Chrono's ANCF shells (``ancf3443``, ``ancf3833``, ``ancf3423``)
as our own model: mesh, assembly, mass, loads, supports, Newton's static solve and natural frequencies.

Mesh: the mid-surface [x0, x0 + a] x [y0, y0 + b] in the plane z = 0 (m), thickness H (m),
nx x ny equal elements of Le = a/nx by We = b/ny.  The nodes lie on a grid of steps
Le/s, We/s with s = 1 (3443, 3423: corners only) or s = 2 (3833: corners and mid-sides,
the element centres (odd, odd) left out); neighbours share nodes.  Each node carries c
coordinates (3443: c = 12, [r, r_x, r_y, r_z]; 3833: c = 9, [r, r_z, r_zz]; 3423: c = 6,
[r, r_z]), its entries at node * c + 3 slot + component; the reference e0 is every
element's own reference (positions in m, unit gradients r_x, r_y, r_z; r_zz = 0).
Equations (N, N m on gradient entries; the elements' ``internal_force`` and
``internal_force_jacobians``, the 3423's ANS/EAS ``Shell3423.gradient``, no velocity):

    Q(e) = sum_k A_k^T Q_k(A_k e),  K(e) = dQ/de = sum_k A_k^T K_k A_k,  N/m       (1)
    M = sum_k A_k^T M_k A_k,  M_k = int_V rho S^T S dV                   kg        (2)
    F_g = sum_k A_k^T int_V rho S^T g dV,  F_p = sum_k A_k^T int_A S^T(z=0) p e_z dA (3)
    F_pt = S(xi, eta, 0)^T f + 1/2 m x grad_r s_a       point force f, moment m   (4)
    R(e) = Q(e) - F = 0 on the free coordinates (Newton)                          (5)
    K_ff phi = w^2 M_ff phi,  f = w / (2 pi)  Hz, about e0                         (6)

A_k gathers element k's coordinates; the loads are dead loads at the reference, as
Chrono's ``DoStaticLinear`` assembles them.  Eq. (4) is Chrono's ``ComputeNF`` (Recuero et
al. 2016): grad_r s_a = (ds_a/dxi) J^-1, J = dr/dxi (3, 3) at the point.  Supports are
lists of fixed coordinates: ``clamped`` (every coordinate of the edge's nodes) and
``simply_supported`` (the transverse displacement w, the z-displacement of the edge: the
nodes' z-positions, and for the 3443 also the z-component of the edge-tangent gradient, so
that w = 0 all along its cubic edge; the 3833's quadratic and the 3423's linear edge are
w = 0 from their nodes).  A simple support leaves the in-plane positions and the fibre
gradients (r_z, r_zz, the 3423's d = r_z; the 3443's normal slope) free, as Navier's plate leaves the rotation about the edge
and the in-plane motion free; ``in_plane_rigid`` then removes only the three in-plane
rigid motions.

``Plate.poisson`` names the 3443's law (``ancf3443``, eqs. (P1)-(P2)): "3d" (Chrono's, the
default; Poisson-locked in bending by (1 - nu)^2/(1 - 2 nu)), "plane_stress" or "split"
(the remedies).  The 3833 (r_zz free, no such locking) takes "3d" only.
"""
from __future__ import annotations

import warnings
from dataclasses import dataclass, field
from functools import cached_property, lru_cache

import numpy as np
import scipy.sparse as sp
import scipy.sparse.linalg as spla

from ancf.elements import ancf3423, ancf3443, ancf3833
from ancf.elements import continuum3d as c3
from ancf.elements.ancf3423 import Shell3423
from ancf.models.chrono_beam import Solution, cardan_xyz  # noqa: F401 (re-exported)

#: element name -> (module, grid steps per element side)
ELEMENTS = {"3443": (ancf3443, 1), "3833": (ancf3833, 2), "3423": (ancf3423, 1)}
#: edge name -> (grid axis, at the start (0) or the end (1))
EDGES = {"x0": (0, 0), "x1": (0, 1), "y0": (1, 0), "y1": (1, 1)}


@dataclass(frozen=True)
class Plate:
    """The plate: element ("3443", "3833" or "3423"), nx x ny elements, sides a (along x) and b
    (along y), thickness H, all m, the corner (x0, y0) in m, density rho (kg/m^3), Young's
    modulus E (Pa), Poisson's ratio nu (isotropic, one layer); ``poisson`` the 3443's law
    (module docstring, ``ancf3443.POISSON``; the 3833 and 3423 take "3d" only)."""

    element: str
    nx: int
    ny: int
    a: float
    b: float
    H: float
    E: float
    nu: float
    rho: float = 0.0
    x0: float = 0.0
    y0: float = 0.0
    poisson: str = "3d"
    module: object = field(init=False, repr=False)

    def __post_init__(self):
        object.__setattr__(self, "module", ELEMENTS[self.element][0])
        allowed = ancf3443.POISSON if self.element == "3443" else ("3d",)
        if self.poisson not in allowed:
            raise ValueError(f"poisson for the {self.element} must be one of {allowed} "
                             f"(got {self.poisson!r})")

    @property
    def dims(self):
        """(Le, We): an element's sides, m."""
        return self.a / self.nx, self.b / self.ny

    @property
    def ncoord(self) -> int:
        return self.module.NDOF // self.module.NNODE

    @cached_property
    def grid(self) -> np.ndarray:
        """(nnode, 2) integer grid indices (I, J) of the nodes, row by row."""
        s = ELEMENTS[self.element][1]
        I, J = np.meshgrid(np.arange(s * self.nx + 1), np.arange(s * self.ny + 1))
        keep = ~((I % 2 == 1) & (J % 2 == 1)) if s == 2 else np.ones(I.shape, bool)
        return np.column_stack([I[keep], J[keep]])

    @cached_property
    def connectivity(self) -> np.ndarray:
        """(nel, NNODE) global nodes of each element in the module's order A, B, C, D(, ...);
        element k = j nx + i."""
        s = ELEMENTS[self.element][1]
        index = {tuple(g): n for n, g in enumerate(self.grid)}
        local = np.column_stack([self.module.NODE_XI + 1, self.module.NODE_ETA + 1]) * s // 2
        return np.array([[index[(s * i + int(p), s * j + int(q))] for p, q in local]
                         for j in range(self.ny) for i in range(self.nx)])

    @cached_property
    def dofs(self) -> np.ndarray:
        """A_k as indices (nel, NDOF): element k's coordinates, module order."""
        c = self.ncoord
        nodes = self.connectivity
        return (nodes[:, :, None] * c + np.arange(c)).reshape(len(nodes), -1)

    @property
    def ndof(self) -> int:
        return len(self.grid) * self.ncoord

    def positions(self) -> np.ndarray:
        """(nnode, 2) node positions (x, y) in m."""
        s = ELEMENTS[self.element][1]
        return np.array([self.x0, self.y0]) + self.grid * np.array(self.dims) / s

    @cached_property
    def element_reference(self) -> np.ndarray:
        """e0 of one element (NDOF,), its corner A at the origin."""
        return self.module.reference_coordinates(*self.dims)

    def reference(self) -> np.ndarray:
        """e0 (ndof,): node positions (m) at z = 0, the element's reference gradients."""
        e = np.zeros(self.ndof)
        e[self.dofs] = self.element_reference           # gradients; positions overwritten
        xy = self.positions()
        e[self.coordinate(np.arange(len(xy)), 0, 0)] = xy[:, 0]
        e[self.coordinate(np.arange(len(xy)), 0, 1)] = xy[:, 1]
        return e

    def coordinate(self, nodes, slot: int, component: int) -> np.ndarray:
        """Global indices of the coordinate (slot: 0 r, then the gradients in the module's
        order; component: 0 x, 1 y, 2 z) at the given nodes."""
        return np.asarray(nodes) * self.ncoord + 3 * slot + component

    def edge_nodes(self, edge: str) -> np.ndarray:
        """The nodes on an edge: "x0", "x1" (x = x0, x0 + a), "y0", "y1" (y = y0, y0 + b)."""
        axis, end = EDGES[edge]
        return np.flatnonzero(self.grid[:, axis] == end * self.grid[:, axis].max())

    def clamped(self, edge: str) -> np.ndarray:
        """Every coordinate of the edge's nodes."""
        n = self.edge_nodes(edge)
        return (n[:, None] * self.ncoord + np.arange(self.ncoord)).ravel()

    def simply_supported(self, edge: str) -> np.ndarray:
        """w = 0 along the edge (module docstring): the nodes' z-positions, and for the
        3443 the z-component of r_y (edges "x0", "x1") or r_x (edges "y0", "y1")."""
        n = self.edge_nodes(edge)
        fixed = [self.coordinate(n, 0, 2)]
        if self.element == "3443":
            fixed.append(self.coordinate(n, 2 if EDGES[edge][0] == 0 else 1, 2))
        return np.concatenate(fixed)

    def in_plane_rigid(self) -> np.ndarray:
        """x, y of the node nearest the centre and y of the node nearest (x0 + a, y0 + b/2):
        removes the three in-plane rigid motions and nothing else."""
        xy, centre = self.positions(), np.array([self.x0 + self.a / 2, self.y0 + self.b / 2])
        c = np.argmin(np.linalg.norm(xy - centre, axis=1))
        r = np.argmin(np.linalg.norm(xy - centre - [self.a / 2, 0.0], axis=1))
        return np.array([self.coordinate(c, 0, 0), self.coordinate(c, 0, 1),
                         self.coordinate(r, 0, 1)])

    def free(self, fixed) -> np.ndarray:
        """The complement of the fixed coordinates."""
        return np.setdiff1d(np.arange(self.ndof), np.concatenate([np.ravel(f) for f in fixed]))

    def material(self):
        """The constitutive arguments of the module's internal force after (L, W, H)."""
        if self.element == "3443":
            return (ancf3443.elasticity(self.E, self.nu),)
        return (self.E, self.nu)

    def options(self) -> dict:
        """The keyword arguments of the module's internal force (the 3443's ``poisson``)."""
        return {"poisson": self.poisson} if self.element == "3443" else {}

    def shell3423(self, nel: int) -> Shell3423:
        """nel 3423 elements of this plate's sides, thickness and law, each on its own
        reference (corner A at the origin)."""
        return _shell3423(nel, self.dims, self.H, self.E, self.nu)


def _scatter(plate: Plate, blocks: np.ndarray) -> sp.csr_matrix:
    """sum_k A_k^T blocks_k A_k as a sparse (ndof, ndof) matrix; blocks (nel, NDOF, NDOF)."""
    d = plate.dofs
    rows = np.broadcast_to(d[:, :, None], blocks.shape).ravel()
    cols = np.broadcast_to(d[:, None, :], blocks.shape).ravel()
    return sp.csr_matrix((blocks.ravel(), (rows, cols)), shape=(plate.ndof, plate.ndof))


@lru_cache(maxsize=16)
def _kernel(element: str, dims: tuple, H: float, E: float, nu: float, poisson: str):
    """(e0 (m,) in m, parts): an element's reference and ``continuum3d`` parts, computed
    once per element, sides (m), thickness (m), material (Pa, -) and Poisson law."""
    plate = Plate(element=element, nx=1, ny=1, a=dims[0], b=dims[1], H=H, E=E, nu=nu,
                  poisson=poisson)
    basis, rules = plate.module.continuum(*dims, H, *plate.material(), **plate.options())
    return basis.e0, c3.parts(basis, rules)


@lru_cache(maxsize=16)
def _shell3423(nel: int, dims: tuple, H: float, E: float, nu: float) -> Shell3423:
    """:meth:`Plate.shell3423` of sides dims (m), thickness H (m), E (Pa), nu, built once
    per mesh."""
    return Shell3423(np.full(nel, dims[0]), np.full(nel, dims[1]), H, E, nu)


def assemble(plate: Plate, e: np.ndarray, tangent: bool = True):
    """(Q (ndof,) in N, K sparse in N/m or None) of eq. (1) at the state e (m), all elements
    in one ``continuum3d.static_batch`` (the 3423: one ``Shell3423.gradient``).  Each
    element sees its displacement A_k (e - e0) on its own reference, so the mesh offset
    (up to a, m) does not round off the small strains."""
    u = (e - plate.reference())[plate.dofs]
    if plate.element == "3423":
        Qk, Kk = plate.shell3423(len(plate.dofs)).gradient(u + plate.element_reference, tangent)
    else:
        e0, parts = _kernel(plate.element, plate.dims, plate.H, plate.E, plate.nu,
                            plate.poisson)
        Qk, Kk = c3.static_batch(u + (plate.element_reference - e0), parts, tangent)
    Q = np.zeros(plate.ndof)
    np.add.at(Q, plate.dofs, Qk)
    return Q, (_scatter(plate, Kk) if tangent else None)


def reference_stiffness(plate: Plate) -> sp.csr_matrix:
    """K(e0) (N/m): every element has the same reference, so one element's K_k serves all."""
    m, zero = plate.module, np.zeros(plate.module.NDOF)
    if plate.element == "3423":
        Kk = plate.shell3423(1).gradient(plate.element_reference, tangent=True)[1][0]
    else:
        Kk = m.internal_force_jacobians(plate.element_reference, zero, *plate.dims, plate.H,
                                        *plate.material(), **plate.options())[0]
    return _scatter(plate, np.broadcast_to(Kk, (len(plate.dofs),) + Kk.shape))


def mass(plate: Plate) -> sp.csr_matrix:
    """The consistent mass M of eq. (2), kg (kg m, kg m^2 ... on gradient entries)."""
    Mk = plate.module.mass_matrix(*plate.dims, plate.H, plate.rho)
    return _scatter(plate, np.broadcast_to(Mk, (len(plate.dofs),) + Mk.shape))


def _sum_elements(plate: Plate, fk: np.ndarray) -> np.ndarray:
    F = np.zeros(plate.ndof)
    np.add.at(F, plate.dofs, np.broadcast_to(fk, plate.dofs.shape))
    return F


def gravity(plate: Plate, g) -> np.ndarray:
    """F_g of eq. (3), N (N m ... on gradient entries), for g (3,) in m/s^2."""
    return _sum_elements(plate, plate.module.gravity(*plate.dims, plate.H, plate.rho, g))


def _shape(plate: Plate, xi, eta, z=0.0) -> np.ndarray:
    """The module's scalar shape functions (..., NSHAPE) at (xi, eta, z), z in m."""
    if plate.element == "3443":
        return ancf3443.scalar_shape(xi, eta, z, *plate.dims)
    return plate.module.scalar_shape(xi, eta, z)


def _natural_gradient(plate: Plate, xi, eta) -> np.ndarray:
    if plate.element == "3443":
        return ancf3443.natural_gradient(xi, eta, 0.0, *plate.dims)
    return plate.module.natural_gradient(xi, eta, 0.0)


def pressure(plate: Plate, p: float, ngauss: int = 3) -> np.ndarray:
    """F_p of eq. (3): the uniform pressure p (Pa) along +z on the mid-surface, N; the
    ngauss^2 rule is exact for ngauss >= 2 (s_a is at most cubic in xi, eta)."""
    t, w = np.polynomial.legendre.leggauss(ngauss)
    XI, ETA = np.meshgrid(t, t)
    Le, We = plate.dims
    q = np.einsum("ij,ija->a", np.outer(w, w), _shape(plate, XI, ETA)) * Le * We / 4
    return _sum_elements(plate, np.kron(q, [0.0, 0.0, p]))


def point_load(plate: Plate, k: int, xi: float, eta: float, force=(0, 0, 0), moment=(0, 0, 0),
               e=None) -> np.ndarray:
    """F_pt of eq. (4) (N): force (N) and moment (N m), global axes, at the mid-surface
    point (xi, eta) of element k, evaluated at the state e (default the reference)."""
    e = plate.reference() if e is None else e
    ebar = e[plate.dofs[k]].reshape(-1, 3)
    ds = _natural_gradient(plate, xi, eta)
    grad = ds @ np.linalg.inv(ebar.T @ ds)
    Fe = np.outer(_shape(plate, xi, eta), force) + 0.5 * np.cross(np.asarray(moment, float), grad)
    F = np.zeros(plate.ndof)
    F[plate.dofs[k]] = Fe.ravel()
    return F


def point(plate: Plate, e: np.ndarray, k: int, xi: float, eta: float) -> np.ndarray:
    """r (3,) in m of the mid-surface point (xi, eta) of element k at the state e."""
    return _shape(plate, xi, eta) @ e[plate.dofs[k]].reshape(-1, 3)


def section_frame(plate: Plate, e: np.ndarray, k: int, xi: float, eta: float):
    """(r (3,) in m, R (3, 3)) of Chrono's ``EvaluateSectionFrame``: X along dr/dxi, Z = X x
    dr/deta, Y = Z x X, normalised, at the mid-surface point (xi, eta) of element k."""
    ebar, ds = e[plate.dofs[k]].reshape(-1, 3), _natural_gradient(plate, xi, eta)
    X = ebar.T @ ds[:, 0]
    X /= np.linalg.norm(X)
    Z = np.cross(X, ebar.T @ ds[:, 1])
    Z /= np.linalg.norm(Z)
    return point(plate, e, k, xi, eta), np.column_stack([X, np.cross(Z, X), Z])


def solve_static(plate: Plate, F: np.ndarray, fixed, rtol: float = 1e-10,
                 maxiter: int = 20) -> Solution:
    """Newton on eq. (5) from e0 (sparse direct solves on the free coordinates; ``fixed`` a
    list of index arrays) until |R_f| <= max(rtol |F_f|, floor), floor = eps sqrt(n_f)
    max|K_ff| max|e0_el| (N): the force of one rounding of the element coordinates, which
    no iteration goes below (~1e-6 N for Chrono's aluminium strip, where the thickness
    stiffness E W Le / H is ~1e10 N/m).  ``Solution.floor`` is floor / |F_f|; converged
    says that the rtol test passed.  Warns if maxiter iterations reach neither."""
    e, f = plate.reference(), plate.free(fixed)
    scale = np.linalg.norm(F[f])
    for it in range(maxiter + 1):
        Q, K = assemble(plate, e)
        Kff, r = K[f][:, f].tocsc(), Q[f] - F[f]
        if it == 0:
            floor = (np.finfo(float).eps * np.sqrt(f.size) * abs(Kff).max()
                     * np.abs(plate.element_reference).max()) / scale
        res = np.linalg.norm(r) / scale
        if res <= max(rtol, floor):
            return Solution(e, it, res, floor, bool(res <= rtol))
        if it < maxiter:
            e[f] -= spla.spsolve(Kff, r)
    warnings.warn(f"chrono_shell: Newton stopped at {maxiter} iterations, residual {res:.2e}")
    return Solution(e, maxiter, res, floor, False)


#: the shift (rad/s)^2 of the eigensolver: just below 0, so that K - SHIFT M is positive
#: definite even where rigid motions are left free
SHIFT = -1.0


def modes(plate: Plate, fixed, k: int = 6) -> np.ndarray:
    """The first k natural frequencies f = w/(2 pi) in Hz of eq. (6) about e0: the k
    eigenvalues w^2 of K(e0) (N/m) and M (kg) on the free coordinates nearest
    :data:`SHIFT` by ARPACK's shift-invert Lanczos (``scipy.sparse.linalg.eigsh``, one
    sparse LU of K - SHIFT M); the same values as the dense ``scipy.linalg.eigh`` within
    1e-9 relative (1.2 s against 55 s CPU for the 3833 at 16 x 16, n_f ~ 7400)."""
    f = plate.free(fixed)
    K, M = reference_stiffness(plate)[f][:, f].tocsc(), mass(plate)[f][:, f].tocsc()
    v0 = 1.0 + 0.5 * np.sin(1.0 + 7.0 * np.arange(K.shape[0]))  # reproducible runs
    w2 = np.sort(spla.eigsh(K, k=k, M=M, sigma=SHIFT, which="LM", v0=v0,
                            return_eigenvectors=False))
    return np.sqrt(np.abs(w2)) * np.sign(w2) / (2 * np.pi)


def simply_supported_square(shell_cls, n: int, a: float, H: float, E: float, nu: float,
                            p: float):
    """(plate, u) of the scene ``plate-square`` with a registry shell class ``shell_cls``
    (``chrono_element.Shell3443``, ``Shell3833`` or ``ancf3423.Shell3423``): n x n elements over a x a (m),
    thickness H (m), E (Pa), nu; w = 0 on the four edges (``simply_supported``) and
    ``in_plane_rigid``; the uniform pressure p (Pa) along +z (eq. (3)); the linear solve
    K(e0) u = F_p on the free coordinates, K(e0) (N/m) the class's tangent assembled on
    this mesh; u (ndof,) in m."""
    plate = Plate(shell_cls.module.__name__[-4:], n, n, a, a, H, E, nu)
    e0 = plate.reference()[plate.dofs]
    el = shell_cls(np.full(n * n, a / n), np.full(n * n, a / n), H, E, nu, e0=e0)
    K = _scatter(plate, el.gradient(e0, tangent=True)[1])
    f = plate.free([plate.simply_supported(edge) for edge in EDGES] + [plate.in_plane_rigid()])
    u = np.zeros(plate.ndof)
    u[f] = spla.spsolve(K[f][:, f].tocsc(), pressure(plate, p)[f])
    return plate, u


def centre_node(plate: Plate) -> int:
    """The node nearest the plate's centre (x0 + a/2, y0 + b/2)."""
    centre = np.array([plate.x0 + plate.a / 2, plate.y0 + plate.b / 2])
    return int(np.argmin(np.linalg.norm(plate.positions() - centre, axis=1)))
