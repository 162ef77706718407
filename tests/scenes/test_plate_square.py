"""plate-square with Chrono's shells (issue 35): ``element`` = ancf3443 or ancf3833.

The scene (the registry's class, batched ``continuum3d.static_batch`` tangent, assembled on
``chrono_shell.Plate``'s mesh) against ``chrono_shell``'s own reference stiffness (the
module's ``internal_force_jacobians`` of one element, scattered) with the same supports and
pressure: one linear solve each, so the centre deflections agree to round-off (1e-9
relative); a mesh of 2 more elements per side differs by > 1e-3.
"""
from __future__ import annotations

import numpy as np
import pytest
import scipy.sparse.linalg as spla

from ancf.cli import main
from ancf.models import chrono_shell as cs
from ancf.scenes import SCENES


def _chrono_centre(element: str, n: int, p: dict) -> float:
    """chrono_shell's linear centre deflection (m) of the simply supported square."""
    plate = cs.Plate(element, n, n, p["a"], p["a"], p["h"], p["E"], p["nu"])
    f = plate.free([plate.simply_supported(e) for e in cs.EDGES] + [plate.in_plane_rigid()])
    K = cs.reference_stiffness(plate)[f][:, f].tocsc()
    u = np.zeros(plate.ndof)
    u[f] = spla.spsolve(K, cs.pressure(plate, p["p"])[f])
    return float(u[plate.coordinate(cs.centre_node(plate), 0, 2)])


@pytest.mark.parametrize("element", ["ancf3443", "ancf3833"])
def test_scene_matches_the_chrono_shell_model(element):
    out, _ = SCENES["plate-square"].execute({"element": element, "n_elements": 4})
    p, w = out["params"], out["results"]["center_deflection_m"]
    ref = _chrono_centre(element[4:], 4, p)
    assert w > 0 and w == pytest.approx(ref, rel=1e-9)
    assert abs(_chrono_centre(element[4:], 6, p) - w) > 1e-3 * w


def test_default_element_is_plate36_unchanged():
    a = SCENES["plate-square"].execute({"n_elements": 4})[0]["results"]
    b = SCENES["plate-square"].execute({"n_elements": 4, "element": "plate36"})[0]["results"]
    assert a == b


@pytest.mark.parametrize("element", ["ancf3243", "ancf3843", "linear3d"])
def test_an_element_the_scene_cannot_model_is_one_error_line(element, capsys):
    assert main(["run", "plate-square", "--set", f"element={element}"]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert err == [f"error: element = {element!r} is out of range; allowed: one of "
                   "plate36, ancf3443, ancf3833"]


def test_modes_take_plate36_only(capsys):
    assert main(["modes", "plate-square", "--set", "element=ancf3443"]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and err[0].startswith("error: element = 'ancf3443' is out of range")
