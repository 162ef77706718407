"""``ancf modes --about equilibrium`` checks its equilibrium as ``ancf run`` does (issue 33
item 2): the equilibrium is the scene's run (or, for the linear plate, its nonlinear
equilibrium) with the run's checks: an inverted element is no equilibrium (exit 3), the
strain range, the thin-plate range and the scene's own ``warn`` give the run's warnings.
Only the stability check's refusal is the modes' to report (negative eigenvalues)."""
from __future__ import annotations

import json

import pytest

#: the run's strain-range warnings begin so (2D area, 3D chord length)
AREA = "changes its area by a factor"
LENGTH = "changes its length by a factor"
THIN = "beyond the linear thin-plate range"


def _json(cli, *argv):
    rc, out, err = cli(*argv, "--json")
    return rc, json.loads(out), err


def _pair(cli, scene, *sets):
    """(run's (rc, json), modes about the equilibrium's (rc, json)) at the same --set."""
    args = [a for s in sets for a in ("--set", s)]
    run = _json(cli, "run", scene, *args)
    modes = _json(cli, "modes", scene, *args, "--about", "equilibrium", "--count", "2")
    return run[:2], modes[:2]


def test_an_inverted_element_is_no_equilibrium_to_vibrate_about(cli):
    """The issue's example: F = -1e12 N crushes the bar (run: exit 3, element 3 of 4
    inverted, det F = -9.92); modes answered 7835 Hz, exit 0.  The load is also 2.3e5
    times Euler's (4.26e6 N): an equilibrium both inverted and unstable is refused for
    the inversion (exit 3), not answered as an unstable one (exit 0, the next tests)."""
    (rc_run, run), (rc, modes) = _pair(cli, "axial-bar", "F=-1e12")
    assert rc_run == rc == 3 and modes["results"]["frequencies_hz"] is None
    assert "inverted" in run["message"]
    assert modes["message"] == "No equilibrium to vibrate about: " + run["message"]


@pytest.mark.parametrize("scene, sets, warning", [
    ("cantilever", ("F=-5e8",), AREA),             # the issue's: area x 5.09 (strained 7x)
    ("axial-bar", ("F=1e11",), AREA),              # stretched: area x 4.66
    ("simply-supported", ("F=-1e9",), AREA),       # bent: area x 4.6
    ("beam3d-cantilever", ("F=-1e12",), LENGTH),   # chord x 9.92 (the scene's own warn)
    pytest.param("plate-strip", ("F=-5e9", "load_steps=100"), LENGTH,  # a side x 2.33
                 marks=pytest.mark.slow),           # 2 x 14 s
])
def test_the_strain_range_warning_is_the_runs(cli, scene, sets, warning):
    (rc_run, run), (rc, modes) = _pair(cli, scene, *sets)
    assert rc_run == rc == 0
    ours = [w for w in run["warnings"] if warning in w]
    assert len(ours) == 1 and ours[0] in modes["warnings"]


@pytest.mark.parametrize("p, depth", [(1e12, 245.0), (1e9, 24.4)])
def test_a_plate_deflected_beyond_the_thin_plate_range_is_warned(cli, p, depth):
    """The issue's p = 1e12 Pa (the run's linear solve: 2.15e7 thicknesses deep) and 1e9:
    the nonlinear equilibrium modes vibrates about is judged by the run's thin-plate check
    (|w| <= 0.3 h), its own depth in thicknesses stated (3 digits)."""
    (_, run), (rc, modes) = _pair(cli, "plate-square", f"p={p}")
    assert any(THIN in w for w in run["warnings"])
    thin = [w for w in modes["warnings"] if THIN in w]
    assert rc == 0 and len(thin) == 1 and f"= {depth:.3g} h" in thin[0]


def test_the_defaults_gain_no_warning(cli):
    """Within the ranges nothing is added: the default cantilever and plate about their
    equilibria warn of nothing, as their runs."""
    for scene in ("cantilever", "plate-square"):
        (rc, modes) = _json(cli, "modes", scene, "--about", "equilibrium", "--count", "2")[:2]
        assert rc == 0 and modes["warnings"] == []


def test_an_unstable_equilibrium_is_reported_by_the_modes_not_refused(cli):
    """Beyond Euler's load (4.26e6 N) the straight bar is unstable: run refuses it (exit 3),
    modes reports the negative eigenvalue and warns (the Euler crossing needs it)."""
    (rc_run, run), (rc, modes) = _pair(cli, "axial-bar", "F=-4.5e6", "n_elements=16")
    assert rc_run == 3 and "stable equilibrium" in run["message"]
    assert rc == 0 and modes["results"]["frequencies_hz"][0] < 0
    assert any("the equilibrium is unstable" in w for w in modes["warnings"])


def test_a_stability_check_switched_off_is_warned_as_in_the_run(cli):
    (_, run), (_, modes) = _pair(cli, "cantilever", "stability_check=off")
    assert run["warnings"] == modes["warnings"] == [
        "stability of the equilibrium not checked (stability_check = off)"]
