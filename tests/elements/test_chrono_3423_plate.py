"""The ANCF 3423 shell on ``chrono_shell.Plate``'s mesh (the scene ``plate-square``).

A simple support fixes only the nodes' z-positions (the bilinear edge is w = 0 from its two
nodes; the fibre d is left free, as the 3443's r_z).  The assembled tangent at the
reference equals ``reference_stiffness`` (one element's K scattered; round-off, 1e-12 of
max|K|); the linear centre deflection on 8 x 8 elements is within 1 % of Navier's series
(the chapter's tolerance, ``ancf.checks.chrono_elements.PLATE_TOL``) and Newton's nonlinear
one within 1e-3 of the linear one (w / h ~ 0.02: the nonlinear stiffening is ~(w/h)^2),
its residual at rtol 1e-10 or at the round-off floor of ``solve_static``.
"""
from __future__ import annotations

import numpy as np

from ancf.checks import chrono_elements as ce
from ancf.elements.ancf3423 import Shell3423
from ancf.models import chrono_shell as cs

N = 8


def _scene():
    p = ce.plate_parameters()
    return p, cs.simply_supported_square(Shell3423, N, p["a"], p["h"], p["E"], p["nu"], p["p"])


def test_3423_simple_support_fixes_only_the_edge_z_positions():
    plate, _ = ce.square_plate("3423", N)
    fixed = plate.simply_supported("x0")
    np.testing.assert_array_equal(fixed, plate.coordinate(plate.edge_nodes("x0"), 0, 2))
    assert plate.ncoord == 6 and len(plate.edge_nodes("x0")) == N + 1


def test_3423_plate_tangent_is_the_scattered_element_tangent():
    plate, _ = ce.square_plate("3423", 4)
    K = cs.assemble(plate, plate.reference())[1].toarray()
    K0 = cs.reference_stiffness(plate).toarray()
    assert np.abs(K - K0).max() <= 1e-12 * np.abs(K0).max()


def test_3423_plate_centre_deflection_within_navier_tolerance():
    p, (plate, u) = _scene()
    w = u[plate.coordinate(cs.centre_node(plate), 0, 2)]
    assert abs(w / ce.navier_w() - 1) <= ce.PLATE_TOL
    _, fixed = ce.square_plate("3423", N)
    sol = cs.solve_static(plate, cs.pressure(plate, p["p"]), fixed)
    assert sol.residual <= max(1e-10, sol.floor)  # rtol, or the round-off floor
    assert abs(ce.centre_deflection(plate, sol.e) / w - 1) <= 1e-3
