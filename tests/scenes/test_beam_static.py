"""``ancf.scenes.beam_static.build``: the mesh and assembly are built once per structure
and shared by the runs of a sweep (issue 37: 0.84 ms of the 8-element cantilever's
2.5 ms), each run with its own q0; every structural parameter gives its own model."""
from __future__ import annotations

import numpy as np
import pytest

from ancf.scenes import SCENES
from ancf.scenes import beam_static as bs

BASE = dict(element="linear", integration="thesis", n_elements=4, E=2.07e11, nu=0.3, L=2.0,
            h=0.1, b=0.1, ks=5.0 / 6.0)


def test_same_structure_shares_the_model_not_q0():
    mesh, q0, asm = bs.build(BASE)
    mesh2, q02, asm2 = bs.build(dict(BASE))
    assert asm2 is asm and mesh2 is mesh
    assert q02 is not q0 and np.array_equal(q0, q02)
    q0 += 1.0
    assert not np.array_equal(bs.build(BASE)[1], q0)


@pytest.mark.parametrize("key, value", [("n_elements", 5), ("L", 2.5), ("h", 0.2), ("b", 0.2),
                                        ("E", 1e11), ("nu", 0.2), ("ks", 0.9), ("rho", 7800.0),
                                        ("integration", "exact"), ("element", "omar-shabana")])
def test_each_structural_parameter_builds_its_own_model(key, value):
    assert bs.build({**BASE, key: value})[2] is not bs.build(BASE)[2]


def test_a_cached_model_gives_the_fresh_models_answer():
    """The second run of the cantilever (cached model) equals the first bit for bit, and a
    different E right after does not reuse the first model's stiffness."""
    run = SCENES["cantilever"].execute
    first, again = (run({"n_elements": "6"})[0]["results"] for _ in range(2))
    assert (first["tip_x"], first["tip_y"]) == (again["tip_x"], again["tip_y"])
    stiffer = run({"n_elements": "6", "E": "3e11"})[0]["results"]
    assert abs(stiffer["tip_y"]) < abs(first["tip_y"])


def test_runs_share_the_reduced_pattern_of_the_same_constraints():
    """``ancf.core.pattern.shared``: two runs of one structure share one pattern; a clamp
    that fixes one more slope (another T) gets its own, with one column fewer per coordinate
    fixed (omar-shabana, ``clamp_x_slope``)."""
    run = SCENES["cantilever"].execute
    a, b = (run({"n_elements": "5", "element": "omar-shabana"})[1] for _ in range(2))
    fixed = run({"n_elements": "5", "element": "omar-shabana", "clamp_x_slope": "fixed"})[1]
    assert a.extra["pattern"] is b.extra["pattern"]
    assert fixed.extra["pattern"] is not a.extra["pattern"]
    assert fixed.extra["pattern"].n == a.extra["pattern"].n - 2


def test_cantilever_clamp_is_built_once_per_clamp():
    """setup shares the elimination between runs of one clamp; it fixes r and dr/dy of
    the first node (and dr/dx with clamp_x_slope = fixed) at their reference values."""
    from ancf.scenes import cantilever
    p = SCENES["cantilever"].resolve({"element": "omar-shabana"})
    mesh, q0, _, elim, _ = cantilever.setup(p)
    assert cantilever.setup(dict(p))[3] is elim
    fixed = cantilever.setup({**p, "clamp_x_slope": "fixed"})[3]
    for e, slots in ((elim, ("r", "r_y")), (fixed, ("r", "r_x", "r_y"))):
        want = {mesh.dof(0, s, k): q0[mesh.dof(0, s, k)] for s in slots for k in (0, 1)}
        assert e.fixed == want
