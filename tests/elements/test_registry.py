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

import numpy as np
import pytest

from ancf.core.mesh import BeamMesh
from ancf.core.quadrature import RectangularSection
from ancf.elements import catalogue
from ancf.elements.registry import ELEMENTS, KINDS
from ancf.models.beam3d import BUILDERS
from ancf.models.plate_mesh import PlateMesh

E_MOD, NU, RHO = 2.07e11, 0.3, 7850.0
SECTION = RectangularSection(0.1, 0.2)
NAMES = list(ELEMENTS)
H, RTOL = 1e-6, 1e-6


def _build(t, n_el=2):
    """(element, reference q0, dofmap, size): a beam mesh of length 2 m or a 2 x 1 plate
    mesh of 1.2 m x 0.8 m, the element built from the registry's defaults."""
    if t.kind == "plate":
        m = PlateMesh(1.2, 0.8, n_el, 1)
        return t.cls(m.lengths, m.widths, h=0.01, E=E_MOD, nu=NU, rho=RHO), m.reference(), \
            m.dofmap, (m.lengths, m.widths)
    m = BeamMesh(2.0, n_el, t.cls.slots, dim=t.dim)
    q0 = m.reference()
    cls, kw = t.build({"ks": 5.0 / 6.0, "integration": "thesis"})
    return cls(m.lengths, q0[m.dofmap], SECTION, E=E_MOD, nu=NU, rho=RHO, **kw), q0, m.dofmap, m.lengths


def _nodes(t) -> tuple:
    """Local coordinates (xi, eta) of the element's nodes, in node order."""
    if t.kind == "plate":
        return np.array([0.0, 1.0, 1.0, 0.0]), np.array([0.0, 0.0, 1.0, 1.0])
    return np.array([0.0, 1.0]), 0.0


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
    strain = cls.strain.__module__ if hasattr(cls, "strain") else cls.__module__
    assert strain == t.strain


def test_views_derive_from_the_registry():
    assert set(catalogue.CATALOGUE) == {n for n, t in ELEMENTS.items()
                                        if t.kind == "beam" and t.dim == 2}
    assert set(BUILDERS) == {n for n, t in ELEMENTS.items() if t.dim == 3 and t.nodes == 2}
    classes = {cls for cls, _ in catalogue.CONTRACT_ELEMENTS.values()}
    assert classes == {t.cls for t in ELEMENTS.values() if t.variants != ()}


@pytest.mark.parametrize("name", NAMES)
def test_field_reproduces_the_nodes(name):
    """At a node, r and the slopes of the family's directions are the nodal values."""
    t = ELEMENTS[name]
    el, q0, dofmap, size = _build(t)
    rng = np.random.default_rng(1)
    e = q0[dofmap] + 0.05 * rng.standard_normal(dofmap.shape)
    f = t.field(e, size, *_nodes(t))
    slots = t.cls.slots
    E = e.reshape(e.shape[0], t.nodes, len(slots), t.dim)
    np.testing.assert_allclose(f.r, E[:, :, 0, :], rtol=0, atol=1e-12)
    for s, slot in enumerate(slots[1:], 1):
        i = t.directions().index(slot[-1])
        np.testing.assert_allclose(f.slopes[:, :, i, :], E[:, :, s, :], rtol=0, atol=1e-12)


@pytest.mark.parametrize("name", NAMES)
def test_rigid_motion_gives_zero_strain_and_energy(name):
    t = ELEMENTS[name]
    el, q0, dofmap, size = _build(t)
    e, R = _rigid(t, q0[dofmap])
    xi = np.linspace(0.0, 1.0, 7)
    f, f0 = t.field(e, size, xi, xi[::-1]), t.field(q0[dofmap], size, xi, xi[::-1])
    assert np.abs(f.strain).max() <= 1e-12
    np.testing.assert_allclose(f.slopes, f0.slopes @ R.T, rtol=0, atol=1e-12)
    assert np.abs(t.field(e, size, xi, xi, e0=q0[dofmap]).strain).max() <= 1e-12
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
