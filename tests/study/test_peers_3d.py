"""The pure logic of the 3D race (benchmarks/peers_3d.py, benchmarks/peers_3d_exudyn.py):
Exudyn's plate load and supports against our plate model's (a different construction),
the relative differences, the parameter check and the tip difference."""
import math

import numpy as np
import pytest

from ancf.models.plate import _supports
from ancf.models.plate_mesh import PER_NODE, PlateMesh
from benchmarks import peers_3d as p3
from benchmarks import peers_3d_exudyn as px

TOL = 1e-12


def _exudyn_load(n: int, a: float, p: float, scale=(1.0, 1.0, 1.0)) -> np.ndarray:
    """Assembled z generalised forces of pressure_weights (each slot's column times
    ``scale``) on our mesh's numbering."""
    m = PlateMesh(a, a, n, n)
    f = np.zeros(m.n_dofs)
    corners = ((0, 0), (1, 0), (1, 1), (0, 1))
    for i in range(n):
        for j in range(n):
            for (di, dj), w in zip(corners, px.pressure_weights(a / n, a / n) * scale):
                for slot, s in enumerate(("r", "r_x", "r_y")):
                    f[m.dof(m.node(i + di, j + dj), s, 2)] += p * w[slot]
    return f


@pytest.mark.parametrize("n, a, p", [(2, 1.0, 1e3), (4, 0.7, -250.0), (6, 2.5, 3.0)])
def test_pressure_weights_equal_the_gauss_integrated_load(n, a, p):
    """The closed-form element integrals equal our mesh's 2 x 2 Gauss load of the
    incomplete cubic (ancf.models.plate_mesh.PlateMesh.pressure_load), and their total on
    r is p a^2."""
    ours = PlateMesh(a, a, n, n).pressure_load(p)
    theirs = _exudyn_load(n, a, p)
    assert np.max(np.abs(ours - theirs)) <= TOL * abs(p) * a * a
    assert math.isclose(theirs[2::PER_NODE].sum(), p * a * a, rel_tol=TOL)


@pytest.mark.parametrize("scale", [(1.0, 2.0, 1.0), (1.0, 1.0, 0.5), (1.0 + 1e-9, 1.0, 1.0)])
def test_a_wrong_weight_breaks_the_load(scale):
    """a^2 b / 12 on r_x (the beam's slope integral without the linear factor's 1/2), half
    the r_y weight or r's off by 1e-9 are seen beyond the tolerance."""
    ours = PlateMesh(1.0, 1.0, 4, 4).pressure_load(1e3)
    assert np.max(np.abs(ours - _exudyn_load(4, 1.0, 1e3, np.array(scale)))) > TOL * 1e3


@pytest.mark.parametrize("n", [2, 4, 8])
def test_supports_are_our_simply_supported_coordinates(n):
    """Exudyn's fixed NodePointSlope12 coordinates, per node (i, j), are our plate's
    (ancf.models.plate._supports, by node position); the coordinate order (r, r_x, r_y)
    is the same."""
    m = PlateMesh(1.0, 1.0, n, n)
    theirs = {m.node(i, j) * PER_NODE + k for i in range(n + 1) for j in range(n + 1)
              for k in px.supported(i, j, n)}
    assert theirs == _supports(m)
    swapped = {m.node(j, i) * PER_NODE + k for i in range(n + 1) for j in range(n + 1)
               for k in px.supported(i, j, n)}
    assert swapped != _supports(m)   # the edge slopes tell x from y


def test_relative_difference_and_missing_values():
    assert math.isclose(p3.relative(1.1, -1.0), 2.1, rel_tol=TOL)
    assert p3.relative(None, 1.0) is None and p3.relative(1.0, 0.0) is None


def test_mismatches_names_the_parameters_that_differ():
    ours = {"E": 2.1e11, "nu": 0.3, "h": 0.01}
    assert p3.mismatches(ours, {"E": 2.1e11, "nu": 0.3}) == []
    assert p3.mismatches(ours, {"E": 2.1e11 * (1 + 1e-9), "nu": 0.3}) == ["E"]


def test_expected_parameters_are_the_scenes_defaults():
    """What Exudyn's side builds with equals what our scenes resolve to by default."""
    from ancf.scenes import SCENES
    for case in ("princeton", "cantilever3d", "plate-static"):
        p = SCENES[p3.SCENE[case]].resolve({})
        assert p3.mismatches(p, p3.expected(case)) == [], case


def test_tip_difference_is_relative_to_the_displacement():
    """A tip 3 mm off Exudyn's, whose tip moved (-0.3, -0.4, 0) m, differs by 0.6 %."""
    e = {"tip_x": 1.7, "tip_y": -0.4, "tip_z": 0.0}
    o = {"tip_x": 1.7, "tip_y": -0.4, "tip_z": 0.003}
    assert math.isclose(p3.tip_difference(o, e, 2.0), 0.003 / 0.5, rel_tol=TOL)
    assert p3.tip_difference(e, e, 2.0) == 0.0
    assert p3.tip_difference(o | {"tip_z": None}, e, 2.0) is None
