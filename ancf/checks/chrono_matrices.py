"""Project Chrono's stored ANCF element matrices (issue 35) against our elements: the
parameters of the unit tests that wrote them, the loader and the largest relative
differences, shared by the report chapter ``chrono_elements`` and the tests
``tests/elements/test_chrono_*.py`` (through ``tests/elements/chrono_data.py``).

Data: ``tests/data/chrono/`` (see its README: source path, commit, licence, layout).
Chrono stores each mass as the compact matrix m over the scalar shape functions
(M = m (x) I_3), the gravity force as the full vector, -Q (``ComputeInternalForces``),
and K = dQ/de, R = dQ/de' (``ComputeKRMmatricesGlobal``; the "WithDamping" files stack
[K; R]).  States: every node at the reference, except "SmallDisp", which moves one
node's z position by 0.001 m (``Element.moved``), and "SmallVel", which gives it the
velocity 0.001 m/s; alpha = 0.01 s for "SmallVel" and "WithDamping", 0 otherwise.
Line numbers below are those of ``src/tests/unit_tests/fea/utest_FEA_ANCF*_Formulation.cpp``.

Difference of ours a from Chrono's b: max|a - b| / max|b| (largest difference over the
largest stored entry); with a comparison scale d per coordinate also that of d a, d b
(vector) or d a d, d b d (matrix), so that small gradient entries count too.
"""
from __future__ import annotations

from dataclasses import dataclass, field
from types import ModuleType
from typing import Callable

import numpy as np

from ancf.common.paths import REPO
from ancf.elements import ancf3243, ancf3333, ancf3443, ancf3833, ancf3843
from ancf.elements.material import isotropic_3d

DATA = REPO / "tests" / "data" / "chrono"

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
    if a.shape != tuple(shape):
        raise ValueError(f"{name}: shape {a.shape}, expected {tuple(shape)}")
    return a


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


def _layered_3443() -> dict:
    """Two rotated orthotropic layers (m, stiffness) and a coarse rule: a generic state."""
    def ortho(angle):
        return ancf3443.rotate_about_z(ancf3443.orthotropic(
            [50e9, 10e9, 8e9], [0.3, 0.25, 0.35], [5e9, 4e9, 3e9]), angle)
    return {"layers": [(0.01, ortho(0.4)), (0.02, ortho(-1.0))], "n_plane": 4, "n_thick": 2}


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
            generic_kw=_layered_3443(),      # any rule: K, R are Q's exact derivatives
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


def difference(actual, expected, scale=None) -> float:
    """max|a - b| / max|b|, and with ``scale`` d (per coordinate) the larger of that and
    the same of d a, d b (vector) or d a d, d b d (matrix)."""
    a, b = np.asarray(actual, float), np.asarray(expected, float)
    out = np.abs(a - b).max() / np.abs(b).max()
    if scale is None:
        return float(out)
    d = np.asarray(scale, float)
    d = d if b.ndim == 1 else np.outer(d, d)
    return float(max(out, np.abs(d * (a - b)).max() / np.abs(d * b).max()))


def _ours(el: Element, name: str, which: str, velocity: bool, alpha: float):
    """Our counterpart of a stored force (-Q) or Jacobian ([K; R] when damped, else K)."""
    e, edot = el.state(which, velocity)
    args = (e, edot, *el.geometry, *el.material, alpha)
    if name.startswith("IntFrc"):
        return -el.module.internal_force(*args)
    K, R = el.module.internal_force_jacobians(*args)
    return np.vstack([K, R]) if alpha else K


def rows(el: Element) -> list[dict]:
    """One row per stored file of the element: kind, file, shape, the difference and its
    acceptance bound (mass, gravity 1e-10; forces 1e-8; Jacobians 1e-6)."""
    n, mass_scale = el.ndof, el.scale("mass")
    out = [("mass", "MassMatrix", el.module.scalar_mass(*el.geometry, RHO),
            None if mass_scale is None else mass_scale[::3], RTOL_MASS),
           ("gravity", "Grav", el.module.gravity(*el.geometry, RHO, G), mass_scale, RTOL_MASS)]
    for name, which, velocity, alpha in FORCE_CASES + JACOBIAN_CASES:
        kind = "force" if name.startswith("IntFrc") else "Jacobian"
        out.append((kind, name, _ours(el, name, which, velocity, alpha), el.scale("force"),
                    RTOL_FORCE if kind == "force" else RTOL_JAC))
    result = []
    for kind, name, ours, scale, bound in out:
        stored = load(f"{el.prefix}_{name}", ours.shape)
        blocks = range(0, ours.shape[0], n) if kind == "Jacobian" else (0,)  # K and R apart
        d = max(difference(ours[i:i + n], stored[i:i + n], scale) for i in blocks)
        result.append({"element": el.name, "kind": kind, "file": f"{el.prefix}_{name}.txt",
                       "shape": "×".join(map(str, stored.shape)), "difference": d,
                       "bound": bound})
    return result


def table() -> list[dict]:
    """The rows of every element, in the order of :data:`ELEMENTS`."""
    return [r for el in ELEMENTS for r in rows(el)]
