"""beam3d-cantilever (and the scenes built on it) with Chrono's beams (issue 35).

The scene with ``element`` = ancf3243 or ancf3333 against ``ancf.models.chrono_beam`` on
the same mesh: Newton on its own assembly (``chrono_beam.assemble``, the module's
exact rules) with the scene's clamp (every coordinate of node 0 but r_x) and tip force,
no load steps.  Both stop at |R| <= 1e-10 |F|, so the tip positions agree to ~1e-10
relative; the tolerance is 1e-8, and a mesh of one element more differs by > 1e-4.
"""
from __future__ import annotations

import numpy as np
import pytest

from ancf.cli import main
from ancf.models import chrono_beam as cb
from ancf.scenes import SCENES

CASE = {"n_elements": 3, "load_angle_deg": 30.0, "rtol": 1e-10}


def _chrono_tip(p: dict, element: str, n: int) -> np.ndarray:
    """The tip position (m) of chrono_beam's beam of n elements under the scene's load."""
    b = cb.Beam(element=element, n=n, L=p["L"], H=p["h"], W=p["b"], rho=0.0, E=p["E"],
                nu=p["nu"], k1=p["ks"], k2=p["ks"])
    a = np.radians(p["load_angle_deg"])
    F = cb.tip_load(b, force=(0.0, p["F"] * np.cos(a), p["F"] * np.sin(a)))
    fixed = [i for i in range(b.ncoord) if not (element == "3243" and 3 <= i < 6)]  # r_x free
    free = np.setdiff1d(np.arange(F.size), fixed)
    e = b.reference()
    for _ in range(40):
        Q, K = cb.assemble(b, e)
        r = Q[free] - F[free]
        if np.linalg.norm(r) <= 1e-10 * np.linalg.norm(F):
            break
        e[free] -= np.linalg.solve(K[np.ix_(free, free)], r)
    return cb.tip_frame(b, e)[0]


@pytest.mark.parametrize("element", ["ancf3243", "ancf3333"])
def test_scene_matches_the_chrono_beam_model(element):
    out, _ = SCENES["beam3d-cantilever"].execute({"element": element, **CASE})
    p, r = out["params"], out["results"]
    tip = np.array([r["tip_x"], r["tip_y"], r["tip_z"]])
    ref = _chrono_tip(p, element[4:], CASE["n_elements"])
    assert out["converged"] and abs(tip[1]) > 0.1 * p["L"]
    np.testing.assert_allclose(tip, ref, rtol=1e-8)
    other = _chrono_tip(p, element[4:], CASE["n_elements"] + 1)
    assert np.abs(other - tip).max() > 1e-4 * abs(tip[1])


@pytest.mark.parametrize("scene", ["princeton-beam", "beam3d-bending"])
def test_published_beam_scenes_take_chrono_beams(scene):
    for element in ("ancf3243", "ancf3333"):
        out, _ = SCENES[scene].execute({"element": element, "n_elements": 2})
        assert out["converged"] and out["params"]["element"] == element


@pytest.mark.parametrize("element", ["ancf3443", "ancf3843", "plate36"])
def test_an_element_the_scene_cannot_model_is_one_error_line(element, capsys):
    assert main(["run", "beam3d-cantilever", "--set", f"element={element}"]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert err == [f"error: element = {element!r} is out of range; allowed: one of "
                   "linear3d, belt3d, ancf3243, ancf3333"]
