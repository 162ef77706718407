"""Project Chrono's stored ANCF reference data: the parameters of the unit tests that
wrote them, the loader and the comparison (shared by the ``test_chrono_*`` files).

Data: ``tests/data/chrono/`` (see its README: source path, commit, licence, layout).
Chrono stores each mass as the compact matrix m over the scalar shape functions
(M = m (x) I_3), the gravity force as the full vector, -Q (``ComputeInternalForces``),
and K = dQ/de, R = dQ/de' (``ComputeKRMmatricesGlobal``; the "WithDamping" files stack
[K; R]).  States: every node at the reference, except "SmallDisp", which moves one
node's z position by 0.001 m (``Element.moved``), and "SmallVel", which gives it the
velocity 0.001 m/s; alpha = 0.01 s for "SmallVel" and "WithDamping", 0 otherwise.
Line numbers below are those of ``src/tests/unit_tests/fea/utest_FEA_ANCF*_Formulation.cpp``.
"""
from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path
from types import ModuleType
from typing import Callable

import numpy as np
import pytest

from ancf.elements import ancf3243, ancf3333, ancf3443, ancf3833, ancf3843
from ancf.elements.material import isotropic_3d

DATA = Path(__file__).resolve().parents[1] / "data" / "chrono"

G = (0.0, 0.0, -9.80665)  # m/s^2, every test's gravity (beams, brick :132; shells :140)
RHO = 7850.0              # kg/m^3 (beams :153, shells :163, brick :155)
E, NU = 210e9, 0.3        # Pa, - (beams :154-155, shells :164-165, brick :156-157)
ALPHA = 0.01              # s, Kelvin-Voigt damping of the "SmallVel"/"WithDamping" cases
RTOL_MASS, RTOL_FORCE, RTOL_JAC = 1e-10, 1e-8, 1e-6
K_TIMOSHENKO = 10 * (1 + NU) / (12 + 11 * NU)   # beams' shear correction k1 = k2, :156-159

#: (file name, state, velocity, alpha): the stored force and Jacobian cases
FORCE_CASES = [("IntFrcSmallDispNoVel", "disp", False, 0.0),
               ("IntFrcNoDispSmallVel", "rest", True, ALPHA)]
JACOBIAN_CASES = [("JacNoDispNoVelNoDamping", "rest", False, 0.0),
                  ("JacSmallDispNoVelNoDamping", "disp", False, 0.0),
                  ("JacNoDispNoVelWithDamping", "rest", False, ALPHA),
                  ("JacSmallDispNoVelWithDamping", "disp", False, ALPHA),
                  ("JacNoDispSmallVelWithDamping", "rest", True, ALPHA)]


def load(name: str, shape) -> np.ndarray:
    """The stored array ``tests/data/chrono/<name>.txt``, checked to have ``shape``."""
    a = np.loadtxt(DATA / f"{name}.txt")
    assert a.shape == tuple(shape)
    return a


def close(actual, expected, rtol: float, scale=None):
    """assert_allclose with rtol and an atol of rtol times the largest |expected| entry;
    with ``scale`` (per coordinate) also on the scaled d a (vector) or d a d (matrix),
    so that small gradient entries are held to rtol of the largest entry too."""
    pairs = [(np.asarray(actual), np.asarray(expected))]
    if scale is not None:
        d = np.asarray(scale, dtype=float)
        d = d if np.ndim(expected) == 1 else np.outer(d, d)
        pairs.append((d * actual, d * expected))
    for a, b in pairs:
        np.testing.assert_allclose(a, b, rtol=rtol, atol=rtol * np.abs(b).max())


def check_mass_and_weight(M, q, positions, mass, g=G):
    """M symmetric positive definite; a rigid unit translation along each axis (1 on
    that component of every node position, compact indices ``positions``) carries
    u^T M u = mass (kg); the gravity entries of the node positions add up to mass g (N)."""
    n = M.shape[0]
    assert M.shape == (n, n) and q.shape == (n,)
    np.testing.assert_allclose(M, M.T, rtol=0, atol=1e-14 * np.abs(M).max())
    np.linalg.cholesky(M)  # raises unless positive definite
    assert np.linalg.eigvalsh(M).min() > 0
    rows = 3 * np.asarray(positions)
    for k in range(3):
        u = np.zeros(n)
        u[rows + k] = 1.0
        assert u @ M @ u == pytest.approx(mass, rel=1e-12)
    np.testing.assert_allclose(q.reshape(-1, 3)[positions].sum(axis=0), mass * np.asarray(g),
                               rtol=1e-12, atol=0)


def rotation(axis, angle) -> np.ndarray:
    """Rodrigues rotation matrix (3, 3) about the unit ``axis`` by ``angle`` (rad)."""
    a = np.asarray(axis, dtype=float) / np.linalg.norm(axis)
    A = np.array([[0, -a[2], a[1]], [a[2], 0, -a[0]], [-a[1], a[0], 0]])
    return np.eye(3) + np.sin(angle) * A + (1 - np.cos(angle)) * A @ A


@dataclass(frozen=True)
class Element:
    """One of Chrono's ANCF elements as its stored data and our module see it.  ``geometry``
    and ``material`` are the positional arguments (after e, edot) of the module's
    functions: mass_matrix(*geometry, rho), internal_force(e, edot, *geometry, *material,
    alpha, **kw).  ``generic*``: a state with distinct dimensions (and materials)."""

    module: ModuleType
    prefix: str                 # file name prefix, e.g. "UT_ANCFBeam_3243"
    geometry: tuple             # m, Chrono's test
    material: tuple             # Chrono's test
    moved: int                  # e-index of the node z position Chrono moves / drives
    positions: tuple            # compact indices of the node positions
    reference: Callable         # geometry -> e0
    area: Callable              # geometry -> the section a strain acts on, m^2
    generic: tuple
    generic_material: tuple
    finer: dict                 # a rule beyond the exact default (internal force)
    mass_finer: dict            # a rule beyond the exact default (mass)
    seen: float                 # a 1e-9 m move gives > seen * 1e-12 E area
    generic_kw: dict = field(default_factory=dict)
    rigid_geometry: tuple | None = None   # the rigid-motion test's, default Chrono's
    mass_scale: Callable | None = None    # geometry -> per-scalar-function scale
    force_scale: Callable | None = None

    @property
    def name(self) -> str:
        return self.prefix[-4:]

    @property
    def ndof(self) -> int:
        return self.module.NDOF

    def e0(self, geometry=None) -> np.ndarray:
        return self.reference(self.geometry if geometry is None else geometry)

    def state(self, which: str, velocity: bool):
        """(e, edot) of a stored case: "rest" or "disp", and the "SmallVel" velocity."""
        e, edot = self.e0(), np.zeros(self.ndof)
        if which == "disp":
            e[self.moved] = 0.001
        if velocity:
            edot[self.moved] = 0.001
        return e, edot

    def scale(self, kind: str, geometry=None):
        """The expanded (3 per scalar function) comparison scale, or None."""
        f = self.mass_scale if kind == "mass" else self.force_scale
        geometry = self.geometry if geometry is None else geometry
        return None if f is None else np.repeat(f(geometry), 3)


def _beam_e0(module):
    return lambda g: module.reference_coordinates(g[0])


BEAM = dict(geometry=(1.0, 0.1, 0.1),   # L, H, W: :150-152, SetDimensions :180 (3333 :181)
            material=(E, NU, K_TIMOSHENKO, K_TIMOSHENKO), area=lambda g: g[1] * g[2],
            generic=(1.2, 0.15, 0.08), generic_material=(2e9, 0.25, 0.8, 0.9),
            finer={"naxis": 8}, seen=1e3)
SHELL = dict(geometry=(1.0, 1.0, 0.01),  # L, W, H: :160-162, SetDimensions, one AddLayer
             area=lambda g: g[1] * g[2], seen=1e2)

ELEMENTS = [
    Element(ancf3243, "UT_ANCFBeam_3243", moved=14, positions=(0, 4),   # node B, :369, :412
            reference=_beam_e0(ancf3243), mass_finer={"ngauss": 6}, **BEAM),
    Element(ancf3333, "UT_ANCFBeam_3333", moved=20, positions=(0, 3, 6),  # node C, :370, :413
            reference=_beam_e0(ancf3333), mass_finer={"ngauss": 5}, **BEAM),
    Element(ancf3443, "UT_ANCFShell_3443", material=(isotropic_3d(E, NU),),  # :167, layer :192
            moved=14, positions=(0, 4, 8, 12),                            # node B, :385, :428
            reference=lambda g: ancf3443.reference_coordinates(g[0], g[1]),
            generic=(1.2, 0.8, 0.03), generic_material=(None,),
            generic_kw={"layers": [
                (0.01, ancf3443.rotate_about_z(ancf3443.orthotropic(
                    [50e9, 10e9, 8e9], [0.3, 0.25, 0.35], [5e9, 4e9, 3e9]), 0.4)),
                (0.02, ancf3443.rotate_about_z(ancf3443.orthotropic(
                    [50e9, 10e9, 8e9], [0.3, 0.25, 0.35], [5e9, 4e9, 3e9]), -1.0))],
                "n_plane": 4, "n_thick": 2},     # any rule: K, R are Q's exact derivatives
            finer={"n_plane": 9, "n_thick": 4}, mass_finer={"n_plane": 6, "n_thick": 3},
            mass_scale=lambda g: np.tile([1.0, 1.0 / g[0], 1.0 / g[1], 2.0 / g[2]], 4),
            **SHELL),
    Element(ancf3833, "UT_ANCFShell_3833", material=(E, NU),           # :167, layer :198
            moved=11, positions=tuple(range(0, 24, 3)),                   # node B, :391, :434
            reference=lambda g: ancf3833.reference_coordinates(g[0], g[1]),
            generic=(1.2, 0.7, 0.05), generic_material=(2e9, 0.25),
            finer={"ngauss": 7}, mass_finer={"n_plane": 5, "n_thick": 5},
            mass_scale=lambda g: np.tile([1.0, 2.0 / g[2], 8.0 / g[2] ** 2], 8),
            force_scale=lambda g: np.tile([1.0, g[2] / 2, g[2] ** 2 / 8], 8),
            **SHELL),
    Element(ancf3843, "UT_ANCFBrick_3843", geometry=(1.0, 1.0, 1.0),   # :152-154, :190
            material=(E, NU), moved=14, positions=tuple(range(0, 32, 4)),  # node B, :379, :422
            reference=lambda g: ancf3843.reference_coordinates(*g), area=lambda g: g[1] * g[2],
            generic=(2.0, 0.5, 0.25), generic_material=(2e9, 0.25),
            finer={"ngauss": 8}, mass_finer={"ngauss": 6}, seen=1e3,
            rigid_geometry=(2.0, 0.5, 0.25)),   # the unit cube cannot tell Lx, Ly, Lz apart
]
BY_NAME = {el.name: el for el in ELEMENTS}
