"""3D plate-pulley contact kernel (thesis 4.5, Eqs 4.43-4.45): one call of
:func:`ancf.belts.contact3d.contact_forces3d` with and without the exact Jacobians.

The state is a Model 1 belt (Table 4.1: R = 0.1 m, width 0.08 m, k_p, c_p, nu_s, mu)
of 20 ``plate36`` elements, one across the width, laid on the two-pulley path (spans
pi R, belt length 4 pi R) 1 mm into the pulleys, its nodes running at 2 m/s along the
path (node slopes at rest), the pulleys' surfaces 10 % slower; 81 contact points per
element (the thesis's number), 2 pulleys.
No wall-clock thresholds are asserted; the machine is recorded by conftest.py.
"""
from __future__ import annotations

import numpy as np
import pytest

from ancf.belts.contact3d import contact_forces3d, contact_points3d, contact_state3d
from ancf.belts.friction import contact_record

N_ELEMENTS, RULE, ROUNDS = 20, 81, 200
R, WIDTH, PEN, SPEED = 0.10, 0.08, 1e-3, 2.0          # m, m, m, m/s
PRM = contact_record(1.0e7, 2000.0, "creep-rate", 1.2, 1.0e5)  # k_p, c_p; mu, nu_s (Table 4.1)


def _path(s):
    """Point, unit tangent and speed direction on the two-pulley path at arc length s
    (m): lower span left to right, right pulley, upper span, left pulley (z = 0)."""
    span = np.pi * R
    s = s % (2 * span + 2 * np.pi * R)
    rho = R - PEN
    if s < span:
        return np.array([s, -rho, 0.0]), np.array([1.0, 0.0, 0.0])
    s -= span
    if s < np.pi * R:
        th = -np.pi / 2 + s / R
        return (np.array([span + rho * np.cos(th), rho * np.sin(th), 0.0]),
                np.array([-np.sin(th), np.cos(th), 0.0]))
    s -= np.pi * R
    if s < span:
        return np.array([span - s, rho, 0.0]), np.array([-1.0, 0.0, 0.0])
    th = np.pi / 2 + (s - span) / R
    return (np.array([rho * np.cos(th), rho * np.sin(th), 0.0]),
            np.array([-np.sin(th), np.cos(th), 0.0]))


def contact_case():
    length = 4 * np.pi * R
    l = length / N_ELEMENTS
    nodes = [_path(i * l) for i in range(N_ELEMENTS + 1)]
    ez = np.array([0.0, 0.0, 1.0])

    def node(i, z):
        r, t = nodes[i]
        return np.stack([r + (z - WIDTH / 2) * ez, t, ez]), np.stack([SPEED * t, 0 * t, 0 * t])

    E, V = np.zeros((N_ELEMENTS, 12, 3)), np.zeros((N_ELEMENTS, 12, 3))
    for e in range(N_ELEMENTS):
        for slot, (i, z) in enumerate(((e, 0.0), (e + 1, 0.0), (e + 1, WIDTH), (e, WIDTH))):
            E[e, 3 * slot:3 * slot + 3], V[e, 3 * slot:3 * slot + 3] = node(i, z)
    S0, w = contact_points3d(np.full(N_ELEMENTS, l), np.full(N_ELEMENTS, WIDTH), RULE)
    pulleys = dict(centres=np.array([[0.0, 0.0, 0.0], [np.pi * R, 0.0, 0.0]]),
                   axes=np.array([[0.0, 0.0, 1.0], [0.0, 0.0, 1.0]]), radii=np.full(2, R),
                   omegas=np.full(2, 0.9 * SPEED / R), centre_velocities=np.zeros((2, 3)))
    return E, V, S0, w, pulleys


def _outputs(nel, npul):
    return dict(Q=np.zeros((nel, 36)), Kq=np.zeros((nel, 36, 36)), Cv=np.zeros((nel, 36, 36)),
                Qw=np.zeros((nel, npul, 36)), T=np.zeros(npul), dTq=np.zeros((npul, nel, 36)),
                dTv=np.zeros((npul, nel, 36)), dTw=np.zeros(npul))


@pytest.mark.parametrize("want_J", [False, True], ids=["forces", "forces+jacobians"])
def test_contact_forces3d(benchmark, want_J):
    benchmark.group = "3D plate-pulley contact, one call (thesis 4.5)"
    E, V, S0, w, pul = contact_case()
    args = (E, V, S0, w, pul["centres"], pul["axes"], pul["radii"], pul["omegas"],
            pul["centre_velocities"], PRM, want_J)

    def setup():  # fresh outputs each round: the kernel adds to them
        return args, _outputs(N_ELEMENTS, 2)

    pairs = benchmark.pedantic(contact_forces3d, setup=setup, rounds=ROUNDS, warmup_rounds=2)
    out = _outputs(N_ELEMENTS, 2)
    contact_forces3d(*args, **out)
    assert 0 < pairs <= 2 * N_ELEMENTS and np.all(np.isfinite(out["Q"]))
    assert np.all(out["T"] > 0)  # the belt is faster: it drags both pulleys along
    branch = contact_state3d(E, V, S0, *args[4:10])[5]
    benchmark.extra_info.update({"n_elements": N_ELEMENTS, "points_per_element": RULE,
                                 "pulleys": 2, "jacobians": want_J, "pairs_evaluated": int(pairs),
                                 "points_linear": int(np.sum(branch == 2)),
                                 "points_saturated": int(np.sum(branch == 3))})
