"""plate-square with Chrono's shells (issue 35): ``element`` = ancf3423, ancf3443 or ancf3833.

The scene (the registry's class, batched ``continuum3d.static_batch`` tangent, assembled on
``chrono_shell.Plate``'s mesh) against ``chrono_shell``'s own reference stiffness (the
module's ``internal_force_jacobians`` of one element, the 3423's ``Shell3423``, scattered) with the same supports and
pressure: one linear solve each, so the centre deflections agree to round-off (1e-9
relative); a mesh of 2 more elements per side differs by > 1e-3.  ``ancf modes`` on the
shells: the same frequencies as ``chrono_shell.modes`` (1e-8 relative, two eigensolvers),
six rigid modes when free, and modes about Newton's equilibrium under the pressure.
"""
from __future__ import annotations

import numpy as np
import pytest
import scipy.sparse.linalg as spla

from ancf.cli import main
from ancf.models import chrono_shell as cs
from ancf.scenes import SCENES, modes, plate_square


def _chrono_centre(element: str, n: int, p: dict) -> float:
    """chrono_shell's linear centre deflection (m) of the simply supported square."""
    plate = cs.Plate(element, n, n, p["a"], p["a"], p["h"], p["E"], p["nu"])
    f = plate.free([plate.simply_supported(e) for e in cs.EDGES] + [plate.in_plane_rigid()])
    K = cs.reference_stiffness(plate)[f][:, f].tocsc()
    u = np.zeros(plate.ndof)
    u[f] = spla.spsolve(K, cs.pressure(plate, p["p"])[f])
    return float(u[plate.coordinate(cs.centre_node(plate), 0, 2)])


@pytest.mark.parametrize("element", ["ancf3423", "ancf3443", "ancf3833"])
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
                   "plate36, ancf3423, ancf3443, ancf3833"]


def _chrono_modes(element: str, n: int, p: dict, count: int) -> np.ndarray:
    """chrono_shell's lowest ``count`` frequencies (Hz) of the simply supported square."""
    plate = cs.Plate(element, n, n, p["a"], p["a"], p["h"], p["E"], p["nu"], rho=p["rho"])
    return cs.modes(plate, [plate.simply_supported(e) for e in cs.EDGES]
                    + [plate.in_plane_rigid()], count)


#: relative: two eigensolvers (ancf modes's, chrono_shell's ARPACK) on the same K and M
SAME_MODES = 1e-8


@pytest.mark.parametrize("element", ["ancf3423", "ancf3443", "ancf3833"])
def test_modes_of_a_shell_match_the_chrono_shell_model(element):
    out, _ = modes.execute("plate-square", {"element": element, "n_elements": 4}, count=6)
    f = np.array(out["results"]["frequencies_hz"])
    ref = _chrono_modes(element[4:], 4, out["params"], 6)
    np.testing.assert_allclose(f, ref, rtol=SAME_MODES)
    assert out["results"]["sampling"] == "shell nodes" and out["results"]["rigid_body_modes"] == 0
    assert np.shape(out["results"]["mode_shapes"])[1:] == (len(out["results"]["sample_points"]), 3)


@pytest.mark.parametrize("element", ["ancf3423", "ancf3833"])
def test_a_free_shell_plate_has_six_rigid_modes(element):
    out, _ = modes.execute("plate-square", {"element": element, "n_elements": 2,
                                            "supports": "free"}, count=8)
    assert out["converged"] and out["results"]["rigid_body_modes"] == 6


def test_shell_modes_about_the_equilibrium_under_the_pressure():
    """Newton's equilibrium (w about h/47) stiffens the plate little: the lowest frequency
    within 1 % of the reference state's, and its centre deflection the linear run's within
    1 % (the same small-deflection plate)."""
    for element in ("ancf3423", "ancf3833"):
        _equilibrium_agrees({"element": element, "n_elements": 4})


def _equilibrium_agrees(p: dict) -> None:
    out, res = modes.execute("plate-square", p, count=2, about="equilibrium")
    r = out["results"]
    assert out["converged"] and r["newton_iterations"] >= 1
    assert r["frequencies_hz"][0] == pytest.approx(r["lowest_frequency_reference_hz"], rel=1e-2)
    lin = SCENES["plate-square"].execute(p)[0]["results"]["center_deflection_m"]
    c = plate_square._centre_dof({**out["params"], **p}, None)
    assert res.extra["q"][c] - res.extra["q0"][c] == pytest.approx(lin, rel=1e-2)


def test_shell_modes_through_the_api_carry_the_mode_vectors():
    """``ancf.modes``: the global mode vectors over the plate's coordinates; no mesh of
    plate36's kind (``q`` None, as the shells' ``ancf run``)."""
    import ancf
    m = ancf.modes("plate-square", element="ancf3833", n_elements=2, count=3)
    plate = cs.Plate("3833", 2, 2, 1.0, 1.0, 0.01, 1.0, 0.3)
    assert m.extra["vectors"].shape == (plate.ndof, 3) and m.q is None
