"""Chrono's elements as registry classes (ancf.elements.chrono_element).

The class's force and stiffness equal the module's own ``internal_force`` and
``internal_force_jacobians`` (one element at a time, ``continuum3d.internal_force``, a
different path from the class's batched ``static_batch``) to round-off, 1e-10 of the
largest entry; its energy's directional central difference (h = 1e-6 along a unit-size
direction: truncation ~h^2, round-off ~eps |U| / h) matches the gradient to 1e-6
relative; a translation changes nothing (1e-12 relative).
"""
from __future__ import annotations

import numpy as np
import pytest

from ancf.core.quadrature import RectangularSection
from ancf.elements import chrono_element as ce
from ancf.elements.material import isotropic_3d

E_MOD, NU, RHO = 2.07e11, 0.3, 7850.0
SECTION = RectangularSection(0.1, 0.2)


def _elements() -> dict:
    """name -> (element of 2 unequal elements, the module's material arguments)."""
    L, k = np.array([0.7, 1.1]), ce.chrono_shear(NU)
    a, b = np.array([0.6, 0.9]), np.array([0.5, 0.4])
    return {
        "3243": (ce.Beam3243(L, None, SECTION, E_MOD, NU, RHO), (E_MOD, NU, k, k)),
        "3333": (ce.Beam3333(L, None, SECTION, E_MOD, NU, RHO), (E_MOD, NU, k, k)),
        "3443": (ce.Shell3443(a, b, 0.02, E_MOD, NU, RHO), (isotropic_3d(E_MOD, NU),)),
        "3833": (ce.Shell3833(a, b, 0.02, E_MOD, NU, RHO), (E_MOD, NU)),
        "3843": (ce.Brick3843(L, 0.2, 0.3, E_MOD, NU, RHO), (E_MOD, NU)),
    }


ELEMENTS = _elements()


def _state(el, seed=0, size=1e-2):
    return el.e0 + size * np.random.default_rng(seed).standard_normal(el.e0.shape)


@pytest.mark.parametrize("name", ["3243", "3443", "3833"])
def test_force_and_stiffness_are_the_modules(name):
    el, material = ELEMENTS[name]
    e = _state(el)
    g, K = el.gradient(e, tangent=True)
    for i, s in enumerate(el.sizes):
        q = el.module.internal_force(e[i], 0 * e[i], *s, *material)
        k, _ = el.module.internal_force_jacobians(e[i], 0 * e[i], *s, *material)
        np.testing.assert_allclose(g[i], q, rtol=0, atol=1e-10 * np.abs(q).max())
        np.testing.assert_allclose(K[i], k, rtol=0, atol=1e-10 * np.abs(k).max())
    assert np.abs(g[0] - g[1]).max() > 1e-3 * np.abs(g).max()  # unequal elements differ


@pytest.mark.parametrize("name", list(ELEMENTS))
def test_energy_differences_give_the_gradient(name):
    el, _ = ELEMENTS[name]
    e, h = _state(el), 1e-6
    d = np.random.default_rng(1).standard_normal(e.shape)
    fd = (el.energy(e + h * d) - el.energy(e - h * d)) / (2 * h)
    exact = np.einsum("ei,ei->e", el.gradient(e)[0], d)
    np.testing.assert_allclose(fd, exact, rtol=1e-6)
    assert np.all(np.abs(el.energy(e)) > 0)


@pytest.mark.parametrize("name", list(ELEMENTS))
def test_translation_changes_nothing(name):
    """Moving every node's position by the same vector: the position functions sum to 1,
    so the strain (of e - e0) and the energy stay; moving one node alone does not."""
    el, _ = ELEMENTS[name]
    shift = np.zeros(el.e0.shape).reshape(el.nel, -1, 3)
    shift[:, ::len(el.slots)] = [2.0, -1.0, 0.5]
    e = _state(el)
    U = el.energy(e)
    np.testing.assert_allclose(el.energy(e + shift.reshape(e.shape)), U, rtol=1e-12)
    shift[:, len(el.slots):] = 0.0
    assert np.all(np.abs(el.energy(e + shift.reshape(e.shape)) - U) > 1e-3 * U)
