"""The zero-energy-mode measure of :func:`ancf.solvers.eigen.lowest` (issue 33 item 7):
phi^T K phi / (|K|_inf phi^T phi) is a ratio of stiffnesses, so the count of rigid-body modes
of a free body cannot depend on its material's scale.  A free plate and a free 3D beam have
exactly six rigid motions (three translations, three rotations), whether the material is
1e6 times lighter or heavier than steel, stiffer or softer; and scaling K and M by any
factors leaves the count (and the measure) unchanged.  Without the normalisation a light
free plate reports 0 rigid modes instead of 6."""
from __future__ import annotations

import numpy as np
import pytest

import ancf
from ancf.core.constraints import Elimination
from ancf.scenes import beam3d_cantilever, beam_static
from ancf.scenes.modes import modal_scene
from ancf.solvers.eigen import lowest
from ancf.solvers.linear import ZERO_EIGENVALUE_REL

#: a free body in space: three translations and three rotations
RIGID = 6
#: (density, Young's modulus) scale factors against steel: light, heavy, both together
SCALES = [(1e-6, 1.0), (1e6, 1.0), (1e-6, 1e-6), (1e6, 1e6), (1.0, 1e-6), (1.0, 1e6)]


def _free_beam(rho_scale: float, E_scale: float):
    """(pattern, K, M) of the steel 3D beam of ``beam3d-cantilever`` (4 elements) with no
    coordinate fixed, its density and modulus scaled."""
    p = modal_scene("beam3d-cantilever").resolve(
        {"n_elements": 4, "rho": 7850.0 * rho_scale, "E": 2.07e11 * E_scale})
    m, q0, asm, _, Qk = beam3d_cantilever.setup(p)
    mm = beam_static.modal(p, m, q0, asm, Elimination(m.n_dofs), Qk)
    _, K = mm.pattern.assemble(mm.assembly, q0)
    return mm.pattern, K, mm.pattern.mass(mm.assembly)


def _rigid(pairs) -> int:
    return int(np.sum(pairs.stiffness_rel <= ZERO_EIGENVALUE_REL))


@pytest.mark.parametrize("rho_scale, E_scale", SCALES)
def test_a_free_plate_has_six_rigid_modes_whatever_its_material(rho_scale, E_scale):
    res = ancf.modes("plate-square", {"supports": "free", "n_elements": 4,
                                      "rho": 7850.0 * rho_scale, "E": 2.1e11 * E_scale}, count=8)
    assert res.results["rigid_body_modes"] == RIGID
    # the first elastic mode is no rigid one: sqrt(E / rho) times steel's 33.7 Hz, within 1e-6
    f7 = res.results["frequencies_hz"][RIGID]
    assert f7 == pytest.approx(33.68238018382 * np.sqrt(E_scale / rho_scale), rel=1e-6)


@pytest.mark.parametrize("rho_scale, E_scale", SCALES)
def test_a_free_3d_beam_has_six_rigid_modes_whatever_its_material(rho_scale, E_scale):
    assert _rigid(lowest(*_free_beam(rho_scale, E_scale), 8)) == RIGID


@pytest.mark.parametrize("k_scale, m_scale", [(1e-6, 1e6), (1e6, 1e-6), (1e8, 1e8),
                                              (1e-8, 1e-8)])
def test_scaling_stiffness_and_mass_leaves_the_rigid_count_and_measure(k_scale, m_scale):
    """lambda scales by k / m, phi by m^-1/2: the measure of each elastic mode is invariant
    (1e-9 relative), the zero modes' stays at round-off (below 1e-2 of the threshold)."""
    pattern, K, M = _free_beam(1.0, 1.0)
    base = lowest(pattern, K, M, 8)
    scaled = lowest(pattern, k_scale * K, m_scale * M, 8)
    assert _rigid(scaled) == _rigid(base) == RIGID
    assert scaled.stiffness_rel[RIGID:] == pytest.approx(base.stiffness_rel[RIGID:], rel=1e-9)
    assert np.all(scaled.stiffness_rel[:RIGID] <= 1e-2 * ZERO_EIGENVALUE_REL)
    assert scaled.values[RIGID:] == pytest.approx(base.values[RIGID:] * k_scale / m_scale,
                                                  rel=1e-9)
