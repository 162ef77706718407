"""The element registry's contract, run over every registered element (ancf.elements.registry).

A record agrees with its class (family, dimension, coordinates per node, strain model);
the views (catalogue, CONTRACT_ELEMENTS, the 3D beam models' BUILDERS) derive from it;
its field at points reproduces the nodal positions and slopes at the nodes, gives zero
strain (and the element zero energy) under a rigid motion and the belts' own axial
strain on the centre line; its exact tangent matches central differences of its
gradient.  Tolerances: the tangent as test_elements.py (h = 1e-6, relative 1e-6 per
column: truncation ~h^2, round-off ~eps/h); interpolation and rigid motion are exact
up to round-off (1e-12 of lengths ~1 m).
"""
from __future__ import annotations

import inspect

import numpy as np
import pytest

from ancf.core.mesh import BeamMesh
from ancf.core.quadrature import RectangularSection
from ancf.elements import basis, catalogue
from ancf.elements.registry import ELEMENTS, KINDS
from ancf.models import chrono_beam, chrono_continuum, chrono_shell
from ancf.models.beam3d import BUILDERS
from ancf.models.plate_mesh import PlateMesh

E_MOD, NU, RHO = 2.07e11, 0.3, 7850.0
SECTION = RectangularSection(0.1, 0.2)
NAMES = list(ELEMENTS)
H, RTOL = 1e-6, 1e-6


def _build(t, n_el=2):
    """(element, reference q0, dofmap, size): a beam mesh of length 2 m, a 2 x 1 plate or
    shell mesh of 1.2 m x 0.8 m or a bar of 2 bricks 2 m x 0.1 m x 0.2 m, the element
    built from the registry's defaults."""
    if t.kind in ("shell", "solid") or t.nodes == 3:
        return _chrono_build(t, n_el)
    if t.kind == "plate":
        m = PlateMesh(1.2, 0.8, n_el, 1)
        return t.cls(m.lengths, m.widths, h=0.01, E=E_MOD, nu=NU, rho=RHO), m.reference(), \
            m.dofmap, (m.lengths, m.widths)
    m = BeamMesh(2.0, n_el, t.cls.slots, dim=t.dim)
    q0 = m.reference()
    cls, kw = t.build({"ks": 5.0 / 6.0, "integration": "thesis"})
    return cls(m.lengths, q0[m.dofmap], SECTION, E=E_MOD, nu=NU, rho=RHO, **kw), q0, m.dofmap, m.lengths


def _chrono_build(t, n_el):
    """:func:`_build` on the meshes of Chrono's models (chrono_beam, chrono_shell,
    chrono_continuum)."""
    if t.kind == "beam":
        b = chrono_beam.Beam(element=t.name[4:], n=n_el, L=2.0, H=SECTION.h, W=SECTION.b,
                             rho=RHO, E=E_MOD, nu=NU, k1=5 / 6, k2=5 / 6)
        d, L = np.array([b.dofs(k) for k in range(n_el)]), np.full(n_el, b.Le)
        q0 = b.reference()
        return t.cls(L, q0[d], SECTION, E=E_MOD, nu=NU, rho=RHO, ks=5 / 6), q0, d, L
    if t.kind == "shell":
        p = chrono_shell.Plate(t.name[4:], n_el, 1, 1.2, 0.8, 0.01, E_MOD, NU)
        a, b = (np.full(n_el, v) for v in p.dims)
        return t.cls(a, b, h=0.01, E=E_MOD, nu=NU, rho=RHO), p.reference(), p.dofs, (a, b)
    bar = chrono_continuum.BrickBar(n_el, 2.0, 0.1, 0.2, E_MOD, NU)
    d = np.array([bar.element_dofs(i) for i in range(n_el)])
    sizes = tuple(np.full(n_el, v) for v in bar.dims())
    return t.cls(*sizes, E=E_MOD, nu=NU, rho=RHO), bar.reference(), d, sizes


def _nodes(t) -> tuple:
    """Local coordinates (xi, eta[, zeta]) of the element's nodes, in node order."""
    if t.cls.__dict__.get("node_points") or getattr(t.cls, "node_points", ()):
        pts = t.cls.node_points
        return pts if len(pts) > 1 else (pts[0], 0.0)
    if t.kind == "plate":
        return np.array([0.0, 1.0, 1.0, 0.0]), np.array([0.0, 0.0, 1.0, 1.0])
    return np.array([0.0, 1.0]), 0.0


def _field(t, e, size, *points, e0=None):
    """The registry's field at local points (xi, eta[, zeta])."""
    xi, eta, *zeta = points
    return t.field(e, size, xi, eta, e0, zeta=zeta[0] if zeta else 0.0)


def _rotation(dim):
    """A rotation about (1, 2, 3) by 0.9 rad (3D) or by 0.9 rad (2D)."""
    if dim == 2:
        c, s = np.cos(0.9), np.sin(0.9)
        return np.array([[c, -s], [s, c]])
    k = np.array([1.0, 2.0, 3.0]) / np.sqrt(14.0)
    K = np.array([[0, -k[2], k[1]], [k[2], 0, -k[0]], [-k[1], k[0], 0]])
    return np.eye(3) + np.sin(0.9) * K + (1 - np.cos(0.9)) * K @ K


def _rigid(t, e0):
    """Element coordinates e0 moved by r -> R r + c, slopes -> R slopes."""
    R = _rotation(t.dim)
    E = e0.reshape(e0.shape[0], -1, t.dim) @ R.T
    slots = len(t.cls.slots)
    E[:, ::slots, :] += np.arange(1, t.dim + 1) * 0.3  # positions: slot 0 of every node
    return E.reshape(e0.shape), R


@pytest.mark.parametrize("name", NAMES)
def test_record_agrees_with_its_class(name):
    t = ELEMENTS[name]
    cls = t.cls
    assert t.kind in KINDS and t.dim in (2, 3)
    assert cls.family == t.family
    assert getattr(cls, "dim", None) or cls.strain.dim == t.dim
    assert len(cls.slots) * t.dim == t.coordinates_per_node
    strain = inspect.getmodule(cls.strain).__name__ if hasattr(cls, "strain") else cls.__module__
    assert strain == t.strain


def test_views_derive_from_the_registry():
    assert set(catalogue.CATALOGUE) == {n for n, t in ELEMENTS.items()
                                        if t.kind == "beam" and t.dim == 2}
    assert set(BUILDERS) == {n for n, t in ELEMENTS.items()
                             if t.dim == 3 and t.nodes == 2 and t.kind != "cable"}
    classes = {cls for cls, _ in catalogue.CONTRACT_ELEMENTS.values()}
    assert classes == {t.cls for t in ELEMENTS.values() if t.variants != ()}


@pytest.mark.parametrize("name", NAMES)
def test_field_reproduces_the_nodes(name):
    """At a node, r and the slopes of the family's directions are the nodal values."""
    t = ELEMENTS[name]
    el, q0, dofmap, size = _build(t)
    rng = np.random.default_rng(1)
    e = q0[dofmap] + 0.05 * rng.standard_normal(dofmap.shape)
    f = _field(t, e, size, *_nodes(t))
    slots = t.cls.slots
    E = e.reshape(e.shape[0], t.nodes, len(slots), t.dim)
    np.testing.assert_allclose(f.r, E[:, :, 0, :], rtol=0, atol=1e-12)
    for s, slot in enumerate(slots[1:], 1):
        if len(slot) != 3:  # a second derivative (r_zz): no slope of the field
            continue
        i = t.directions().index(slot[-1])
        np.testing.assert_allclose(f.slopes[:, :, i, :], E[:, :, s, :], rtol=0, atol=1e-12)


@pytest.mark.parametrize("name", NAMES)
def test_rigid_motion_gives_zero_strain_and_energy(name):
    t = ELEMENTS[name]
    el, q0, dofmap, size = _build(t)
    e, R = _rigid(t, q0[dofmap])
    xi = np.linspace(0.0, 1.0, 7)
    f, f0 = _field(t, e, size, xi, xi[::-1], xi), _field(t, q0[dofmap], size, xi, xi[::-1], xi)
    assert np.abs(f.strain).max() <= 1e-12
    np.testing.assert_allclose(f.slopes, f0.slopes @ R.T, rtol=0, atol=1e-12)
    assert np.abs(_field(t, e, size, xi, xi, xi, e0=q0[dofmap]).strain).max() <= 1e-12
    assert np.abs(el.energy(e)).max() <= 1e-12 * E_MOD * SECTION.area * 2.0


@pytest.mark.parametrize("name", [n for n, t in ELEMENTS.items() if t.kind == "belt"])
def test_field_strain_is_the_belt_axial_strain(name):
    """On the centre line, E_xx of the field is the belt's eps_l (Eq. 3.17 over E A alpha1)."""
    t = ELEMENTS[name]
    el, q0, dofmap, size = _build(t)
    e = q0[dofmap] + 0.02 * np.random.default_rng(2).standard_normal(dofmap.shape)
    xi = np.array([0.1, 0.5, 0.8])
    N = el.axial_force(e, xi) / (E_MOD * SECTION.area * el.alpha1)
    np.testing.assert_allclose(t.field(e, size, xi).strain[:, :, 0, 0], N, rtol=1e-12, atol=1e-15)


@pytest.mark.parametrize("name", NAMES)
def test_exact_tangent_matches_gradient_differences(name):
    t = ELEMENTS[name]
    el, q0, dofmap, _ = _build(t)
    e = q0[dofmap] + 0.01 * np.random.default_rng(3).standard_normal(dofmap.shape)
    _, K = el.gradient(e, tangent=True)
    fd = np.zeros_like(K)
    for j in range(el.ndof):
        ep, em = e.copy(), e.copy()
        ep[:, j] += H
        em[:, j] -= H
        fd[:, :, j] = (el.gradient(ep)[0] - el.gradient(em)[0]) / (2 * H)
    err = np.linalg.norm(fd - K, axis=1)
    assert np.all(err <= RTOL * np.linalg.norm(K, axis=1) + 1e-9 * np.abs(K).max()), err.max()


# ----------------------------------------------------------------------------------------
# Chrono's elements (ancf.elements.chrono_element): internal force under rigid motion,
# zero-energy modes and exact mass.  Tolerances: Q of a rigid motion is round-off of
# E eps dV with eps ~ 1e-16, so |Q| <= 1e-12 max|K| (1 m); the stiffness at the
# reference has 6 rigid modes, eigenvalues <= 1e-12 of the largest (seen: <= 2e-16, the
# next >= 3e-9); the mass integrals are exact up to round-off (1e-12 relative).
# ----------------------------------------------------------------------------------------

CONTINUUM = [n for n, t in ELEMENTS.items() if t.strain == "ancf.elements.continuum3d"]
#: with the ANS/EAS shell ancf3423 (its own strain module, its mass rule in test_chrono_3423)
CHRONO = CONTINUUM + [n for n, t in ELEMENTS.items() if t.strain == "ancf.elements.ancf3423"]


@pytest.mark.parametrize("name", CHRONO)
def test_rigid_motion_gives_zero_internal_force(name):
    t = ELEMENTS[name]
    el, q0, dofmap, _ = _build(t)
    e, _ = _rigid(t, q0[dofmap])
    g = el.gradient(e)[0]
    scale = np.abs(el.gradient(q0[dofmap], tangent=True)[1]).max()
    assert np.abs(g).max() <= 1e-12 * scale
    bent = e + 1e-6 * np.random.default_rng(4).standard_normal(e.shape)
    assert np.abs(el.gradient(bent)[0]).max() > 1e-3 * scale * 1e-6  # a deformation does not


@pytest.mark.parametrize("name", CHRONO)
def test_zero_energy_modes_are_the_six_rigid_ones(name):
    t = ELEMENTS[name]
    el, q0, dofmap, _ = _build(t, n_el=1)
    lam = np.abs(np.linalg.eigvalsh(el.gradient(q0[dofmap], tangent=True)[1][0]))
    assert np.sum(lam <= 1e-12 * lam.max()) == 6


def _box(t, el, e0) -> tuple:
    """(lower, upper) corners (3,) m of the element's reference box from its node
    positions and, for beams and shells, the section or thickness."""
    r = e0.reshape(-1, len(t.cls.slots), 3)[:, 0, :]
    lo, hi = r.min(axis=0), r.max(axis=0)
    if t.kind == "beam":
        half = np.array([0.0, el.section.h, el.section.b]) / 2
    else:
        half = np.array([0.0, 0.0, el.h / 2 if t.kind == "shell" else 0.0])
    return lo - half, hi + half


def _box_inertia(lo, hi, rho) -> np.ndarray:
    """rho int (|X|^2 I - X X^T) dV (3, 3), kg m^2, over the box [lo, hi] about the origin,
    from the closed-form moments int X_i dX_i = (hi^2 - lo^2)/2, int X_i^2 = (hi^3 - lo^3)/3."""
    V = np.prod(hi - lo)
    m1 = (hi**2 - lo**2) / 2 / (hi - lo)
    m2 = (hi**3 - lo**3) / 3 / (hi - lo)
    XX = np.outer(m1, m1)
    np.fill_diagonal(XX, m2)
    return rho * V * (np.trace(XX) * np.eye(3) - XX)


@pytest.mark.parametrize("name", CHRONO)
def test_mass_is_exact_for_rigid_motion(name):
    """e'^T M e' of a translation is rho V |v|^2 and of a spin omega (e' = omega x e0 per
    3-vector) omega^T J omega with J the box's inertia (closed form, no quadrature)."""
    t = ELEMENTS[name]
    el, q0, dofmap, _ = _build(t)
    M = el.mass()
    v, w = np.array([0.3, -1.1, 0.7]), np.array([0.4, 1.3, -0.9])
    for k, e0 in enumerate(q0[dofmap]):
        lo, hi = _box(t, el, e0)
        slots = len(t.cls.slots)
        vel = np.zeros(e0.shape).reshape(-1, 3)
        vel[::slots] = v
        assert np.isclose(vel.ravel() @ M[k] @ vel.ravel(), RHO * np.prod(hi - lo) * v @ v,
                          rtol=1e-12)
        spin = np.cross(w, e0.reshape(-1, 3)).ravel()
        J = _box_inertia(lo, hi, RHO)
        assert np.isclose(spin @ M[k] @ spin, w @ J @ w, rtol=1e-12)
        assert not np.isclose(spin @ M[k] @ spin, w @ _box_inertia(lo, hi * 1.001, RHO) @ w,
                              rtol=1e-12)


@pytest.mark.parametrize("name", CONTINUUM)
def test_mass_rule_is_exact(name):
    """The element's mass equals the module's by twice the Gauss points; 2 points do not."""
    t = ELEMENTS[name]
    el, *_ = _build(t, n_el=1)
    sizes, mod = el.sizes[0], t.cls.module
    n = {"ancf3243": 4, "ancf3333": 3, "ancf3843": 4}.get(name)
    kw = (lambda g: {"ngauss": g}) if n else (lambda g: {"n_plane": g, "n_thick": g})
    n = n or 4
    fine, coarse = (mod.mass_matrix(*sizes, RHO, **kw(g)) for g in (2 * n, 2))
    np.testing.assert_allclose(el.mass()[0], fine, rtol=0, atol=1e-12 * np.abs(fine).max())
    assert np.abs(coarse - fine).max() > 1e-6 * np.abs(fine).max()


def test_ancf3243_basis_and_mass_are_the_generated_cubic3d():
    """ancf3243's family claim: its mass equals the generated cubic3d integrals (sympy)."""
    t = ELEMENTS["ancf3243"]
    el, q0, dofmap, L = _build(t)
    gen = basis.consistent_mass(t.shapes(), SECTION, L, RHO, 3)
    np.testing.assert_allclose(el.mass(), gen, rtol=0, atol=1e-12 * np.abs(gen).max())
