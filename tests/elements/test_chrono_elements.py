"""Contract tests over Chrono's five ANCF elements (``ancf3243``, ``ancf3333`` beams,
``ancf3443``, ``ancf3833`` shells, ``ancf3843`` brick): every stored file reproduced
(mass, gravity at rtol 1e-10, forces 1e-8, Jacobians 1e-6), the mass symmetric positive
definite with the rigid-translation mass and the weight, the internal force zero at rest
and under rigid motion, K and R against central differences, the exact rules converged.
The element-specific checks (planted changes, the Poisson split, layers, materials, node
layouts) stay in the per-element ``test_chrono_*`` files; parameters in ``chrono_data``.
"""
from __future__ import annotations

import numpy as np
import pytest

from tests.elements.chrono_data import (ALPHA, E, ELEMENTS, FORCE_CASES, G, JACOBIAN_CASES, RHO,
                                        RTOL_FORCE, RTOL_JAC, RTOL_MASS, check_mass_and_weight,
                                        close, load, rotation)

elements = pytest.mark.parametrize("el", ELEMENTS, ids=lambda el: el.name)


def _q(el, e, edot, geometry, material, alpha, **kw):
    return el.module.internal_force(e, edot, *geometry, *material, alpha, **kw)


@elements
def test_mass_matches_chrono(el):
    """Compact and expanded (M = m (x) I_3), and a finer rule changes nothing (exact)."""
    ref = load(f"{el.prefix}_MassMatrix", (el.module.NSHAPE,) * 2)
    scale = el.scale("mass")
    compact = None if scale is None else scale[::3]
    close(el.module.scalar_mass(*el.geometry, RHO), ref, RTOL_MASS, compact)
    close(el.module.mass_matrix(*el.geometry, RHO), np.kron(ref, np.eye(3)), RTOL_MASS)
    close(el.module.scalar_mass(*el.geometry, RHO, **el.mass_finer), ref, RTOL_MASS)


@elements
def test_gravity_matches_chrono(el):
    close(el.module.gravity(*el.geometry, RHO, G), load(f"{el.prefix}_Grav", (el.ndof,)),
          RTOL_MASS, el.scale("mass"))


@elements
def test_comparison_can_fail(el):
    """The match is not loose: a density off by 1e-8 breaks both the mass and the gravity."""
    rho = RHO * (1 + 1e-8)
    with pytest.raises(AssertionError):
        close(el.module.scalar_mass(*el.geometry, rho),
              load(f"{el.prefix}_MassMatrix", (el.module.NSHAPE,) * 2), RTOL_MASS)
    with pytest.raises(AssertionError):
        close(el.module.gravity(*el.geometry, rho, G), load(f"{el.prefix}_Grav", (el.ndof,)),
              RTOL_MASS)


@elements
def test_mass_spd_rigid_translation_and_weight(el):
    """At distinct dimensions: M SPD, u^T M u = rho V for a rigid translation, sum Q_g = rho V g."""
    g = el.generic
    check_mass_and_weight(el.module.mass_matrix(*g, RHO), el.module.gravity(*g, RHO, G),
                          list(el.positions), RHO * g[0] * g[1] * g[2])


@elements
@pytest.mark.parametrize("name, which, velocity, alpha", FORCE_CASES)
def test_internal_force_matches_chrono(el, name, which, velocity, alpha):
    e, edot = el.state(which, velocity)
    close(-_q(el, e, edot, el.geometry, el.material, alpha),
          load(f"{el.prefix}_{name}", (el.ndof,)), RTOL_FORCE, el.scale("force"))


@elements
@pytest.mark.parametrize("name, which, velocity, alpha", JACOBIAN_CASES)
def test_jacobians_match_chrono(el, name, which, velocity, alpha):
    """K (and R for the damped cases) within 1e-6; without damping R is exactly zero."""
    n = el.ndof
    e, edot = el.state(which, velocity)
    K, R = el.module.internal_force_jacobians(e, edot, *el.geometry, *el.material, alpha)
    ref = load(f"{el.prefix}_{name}", (2 * n if alpha else n, n))
    close(K, ref[:n], RTOL_JAC, el.scale("force"))
    if alpha:
        close(R, ref[n:], RTOL_JAC, el.scale("force"))
    else:
        assert not R.any()


@elements
def test_exact_rule_is_converged(el):
    """A rule beyond the exact default changes Q, K, R by less than 1e-13."""
    e, edot = el.state("disp", True)
    args = (e, edot, *el.geometry, *el.material, ALPHA)
    close(el.module.internal_force(*args, **el.finer), el.module.internal_force(*args),
          1e-13, el.scale("force"))
    for a, b in zip(el.module.internal_force_jacobians(*args, **el.finer),
                    el.module.internal_force_jacobians(*args)):
        close(a, b, 1e-13, el.scale("force"))


@elements
def test_zero_force_at_reference_and_under_rigid_motion(el):
    """Q = 0 exactly at the reference at rest; under a large rigid rotation plus
    translation, moving with a rigid velocity (omega x), the strain and its rate vanish,
    so Q vanishes to round-off: below the force of a 1e-12 strain, 1e-12 E A, while a
    1e-9 m move of one node's z position is clearly seen (> ``seen`` times that)."""
    geo = el.geometry if el.rigid_geometry is None else el.rigid_geometry
    e0, zero = el.e0(geo), np.zeros(el.ndof)
    assert not _q(el, e0, zero, geo, el.material, ALPHA).any()
    blocks = e0.reshape(-1, 3) @ rotation([1.0, -2.0, 0.5], 1.1).T   # rotated r and gradients
    pos = list(el.positions)
    blocks[pos] += [0.2, -0.4, 0.7]                     # translated node positions, m
    rates = np.cross([0.3, 2.0, -1.2], blocks)          # r' = v0 + omega x r, r_J' = omega x r_J
    rates[pos] += [1.0, 0.5, -2.0]                      # v0, m/s
    e, edot = blocks.ravel(), rates.ravel()
    bound = 1e-12 * E * el.area(geo)
    assert np.abs(_q(el, e, edot, geo, el.material, ALPHA)).max() < bound
    bent = e.copy()
    bent[el.moved] += 1e-9
    assert np.abs(_q(el, bent, edot, geo, el.material, ALPHA)).max() > el.seen * bound


@elements
def test_jacobians_match_finite_differences(el):
    """K and R against central differences of Q at a generic state (distinct dimensions,
    a velocity, the shells' layered orthotropic material); R is symmetric."""
    rng = np.random.default_rng(int(el.name))
    n, geo, mat, kw = el.ndof, el.generic, el.generic_material, el.generic_kw
    e = el.e0(geo) + 0.02 * rng.standard_normal(n)
    edot = 0.5 * rng.standard_normal(n)
    K, R = el.module.internal_force_jacobians(e, edot, *geo, *mat, ALPHA, **kw)
    for J, x0, h, fn in [(K, e, 1e-6, lambda x: _q(el, x, edot, geo, mat, ALPHA, **kw)),
                         (R, edot, 1e-4, lambda x: _q(el, e, x, geo, mat, ALPHA, **kw))]:
        fd = np.column_stack([(fn(x0 + h * d) - fn(x0 - h * d)) / (2 * h) for d in np.eye(n)])
        close(J, fd, RTOL_JAC)
    np.testing.assert_allclose(R, R.T, atol=1e-12 * np.abs(R).max())
