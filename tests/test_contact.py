"""Belt-pulley contact (thesis 3.2): Jacobians, bounding test, analytic rings, input.

Finite-difference tolerance: within one branch of the law the forces are smooth; in
the velocities and the pulley speeds they are linear (F_n, v_t and phi are linear in
rdot and omega), so the central difference is exact but for round-off; in the
coordinates the error is h^2/6 f''' with f''' ~ f' / rho^2 (n turns on the scale of
|r - o| ~ 0.1 m), i.e. (1e-6 / 0.1)^2 ~ 1e-10 relative for h = 1e-6 (m, m/s, rad/s,
or - for slopes).  Round-off adds ~ eps |f| / h absolutely.  So each Jacobian column
must match to RTOL = 1e-6 of its norm plus ROUND_MARGIN eps max|f| / h.  Every state
is checked not to lie within one step of a kink: the branch of every point (out,
clamped, linear, saturated with the sign of v_t) is the same at every stencil point.
"""
from __future__ import annotations

import numpy as np
import pytest

from ancf.contact import SUPPORTED_POINTS, contact_forces, contact_points, contact_state
from ancf.elements._generated import cubic2d_S

H = 1e-6
RTOL = 1e-6
ROUND_MARGIN = 1e3
EPS = np.finfo(np.float64).eps
I_TILDE = np.array([[0.0, -1.0], [1.0, 0.0]])

R0 = 0.1                    # pulley radius, m
D0 = 2e-3                   # ring penetration, m
KP, CP, MU = 1e6, 50.0, 0.3  # N/m^2, N s/m^2, -


def _outputs(nel, npul):
    return dict(Q=np.zeros((nel, 12)), Kq=np.zeros((nel, 12, 12)), Cv=np.zeros((nel, 12, 12)),
                Qw=np.zeros((nel, npul, 12)), T=np.zeros(npul), dTq=np.zeros((npul, nel, 12)),
                dTv=np.zeros((npul, nel, 12)), dTw=np.zeros(npul))


def _forces(E, V, S0, w, centres, radii, omegas, prm, want_J=True):
    out = _outputs(E.shape[0], radii.size)
    out["pairs"] = contact_forces(E, V, S0, w, centres, radii, omegas, prm, want_J, **out)
    return out


def _ring(nel, rho, centre, omega_b=0.0, gauss_points=7):
    """A closed unstretched ring of ``nel`` elements and radius ``rho`` (m) about ``centre``,
    rotating rigidly at ``omega_b`` (rad/s).  Node slopes of magnitude 4 tan(dth/4) rho / l
    make each cubic the Bezier arc closest to the circle (radial error ~ rho dth^6 / 2^10)."""
    th = np.linspace(0.0, 2 * np.pi, nel + 1)
    dth = th[1] - th[0]
    l = np.full(nel, rho * dth)
    u = np.stack([np.cos(th), np.sin(th)], axis=-1)
    slope = 4 * np.tan(dth / 4) * rho / l[0] * (u @ I_TILDE.T)
    nodes = np.stack([centre + rho * u, slope, u], axis=1)  # (nel + 1, 3, 2): r, r_x, r_y
    E = np.concatenate([nodes[:-1], nodes[1:]], axis=1)
    V = omega_b * np.concatenate([(E[:, :1] - centre), E[:, 1:3], E[:, 3:4] - centre, E[:, 4:]],
                                 axis=1) @ I_TILDE.T
    S0, w, _ = contact_points(l, gauss_points)
    return E, V, S0, w, l


def _branches(state, prm):
    """Per point and pulley: 0 out, 1 clamped, 2 linear, +-3 saturated (sign of v_t)."""
    _, d, Fn, phi, vt = state
    sat = (Fn > 0) & (prm[3] * np.abs(vt) >= prm[2] * Fn)
    return np.where(d < 0, 0, np.where(Fn <= 0, 1, np.where(sat, 3 * np.sign(vt), 2)))


# ------------------------------------------------------------------ Jacobians
def _fd_state(case):
    """8 elements on a ring of radius R0 + gap, offset from pulley 0 (pulley 1 far
    away), with random perturbations and a random velocity field on a rigid rotation."""
    rng = np.random.default_rng(case["seed"])
    centres = np.array([[0.02, -0.01], [0.6, 0.3]])
    radii = np.array([R0, 0.05])
    E, V, S0, w, _ = _ring(8, R0 + case["gap"], centres[0] + case["offset"], case["omega_b"])
    E = E + 1e-4 * rng.standard_normal(E.shape)
    V = V + case["v_noise"] * rng.standard_normal(V.shape)
    omegas = np.array([case["omega"], 3.0])
    return E, V, S0, w, centres, radii, omegas, np.array(case["prm"], dtype=float)


CASES = {
    "none": dict(seed=0, gap=2e-3, offset=np.zeros(2), omega_b=5.0, v_noise=0.1,
                 omega=4.0, prm=[KP, CP, MU, 10.0]),
    "linear": dict(gap=0.0, seed=1, offset=np.array([0.0018, 0.0009]), omega_b=5.0, v_noise=0.05, omega=5.0,
                   prm=[KP, CP, MU, 10.0]),
    "saturated": dict(gap=0.0, seed=2, offset=np.array([0.0018, 0.0009]), omega_b=5.0, v_noise=0.05,
                      omega=5.0, prm=[KP, CP, MU, 1e7]),
    "mixed-clamped": dict(gap=0.0, seed=3, offset=np.array([-0.0007, 0.0019]), omega_b=5.0, v_noise=0.5,
                          omega=3.0, prm=[KP, 5e3, MU, 1e3]),
}


def _check(fd, exact, scale, name):
    """Column-wise: ||fd_j - exact_j|| <= RTOL ||exact_j|| + ROUND_MARGIN eps scale / H."""
    err = np.abs(fd - exact).reshape(-1, exact.shape[-1])
    ref = np.abs(exact).reshape(-1, exact.shape[-1])
    err, ref = np.linalg.norm(err, axis=0), np.linalg.norm(ref, axis=0)
    atol = ROUND_MARGIN * EPS * scale / H
    assert np.all(err <= RTOL * ref + atol), (name, err, ref, atol)


@pytest.mark.parametrize("case", list(CASES))
def test_jacobians_match_central_differences(case):
    E, V, S0, w, centres, radii, omegas, prm = _fd_state(CASES[case])
    base = _forces(E, V, S0, w, centres, radii, omegas, prm)
    labels = _branches(contact_state(E, V, S0, centres, radii, omegas, prm), prm)
    nel, npul = E.shape[0], radii.size
    fd = _outputs(nel, npul)

    def diff(make):  # central difference of (Q, T); the branches must not change
        res = []
        for sgn in (1.0, -1.0):
            args = make(sgn * H)
            assert np.array_equal(_branches(contact_state(*args[:3], centres, radii, args[3], prm),
                                            prm), labels), f"{case}: state within one step of a kink"
            o = _forces(*args[:3], w, centres, radii, args[3], prm, want_J=False)
            res.append((o["Q"], o["T"]))
        return (res[0][0] - res[1][0]) / (2 * H), (res[0][1] - res[1][1]) / (2 * H)

    for e in range(nel):
        for j in range(12):
            k, c = divmod(j, 2)
            for X, K, dT in ((E, "Kq", "dTq"), (V, "Cv", "dTv")):
                def make(h, X=X):
                    Xp = X.copy()
                    Xp[e, k, c] += h
                    return (Xp, V, S0, omegas) if X is E else (E, Xp, S0, omegas)
                dQ, dTp = diff(make)
                fd[K][e, :, j] = dQ[e]
                assert np.all(dQ[np.arange(nel) != e] == 0.0)  # elements do not couple
                fd[dT][:, e, j] = dTp
    for p in range(npul):
        def make(h):
            om = omegas.copy()
            om[p] += h
            return E, V, S0, om
        dQ, dTp = diff(make)
        fd["Qw"][:, p, :] = dQ
        fd["dTw"][p] = dTp[p]
    sQ, sT = np.abs(base["Q"]).max(), np.abs(base["T"]).max()
    for name in ("Kq", "Cv", "Qw"):
        _check(fd[name], base[name], sQ, name)
    for name in ("dTq", "dTv"):
        _check(fd[name], base[name], sT, name)
    _check(fd["dTw"][:, None], base["dTw"][:, None], sT, "dTw")

    counts = {b: int(np.sum(labels == b)) for b in (0, 1, 2, 3, -3)}
    if case == "none":
        assert base["pairs"] > 0 and counts[0] == labels.size and not base["Q"].any()
    else:
        partly = np.sum(np.any(labels[:, :, 0] != 0, axis=1) & np.any(labels[:, :, 0] == 0, axis=1))
        assert partly >= 2, labels[:, :, 0]
    if case == "linear":
        vt = contact_state(E, V, S0, centres, radii, omegas, prm)[4][labels == 2]
        assert counts[2] > 0 and np.any(vt > 0) and np.any(vt < 0), counts
    if case == "saturated":
        assert counts[3] > 0 and counts[-3] > 0 and counts[2] == 0, counts
    if case == "mixed-clamped":
        assert min(counts[1], counts[2], counts[3] + counts[-3]) > 0, counts


def test_forces_are_added_and_jacobians_only_on_request():
    E, V, S0, w, centres, radii, omegas, prm = _fd_state(CASES["mixed-clamped"])
    full = _forces(E, V, S0, w, centres, radii, omegas, prm)
    out = {k: np.ones_like(v) for k, v in _outputs(E.shape[0], radii.size).items()}
    contact_forces(E, V, S0, w, centres, radii, omegas, prm, False, **out)
    np.testing.assert_allclose(out["Q"] - 1.0, full["Q"], rtol=0, atol=4 * EPS * np.abs(full["Q"]).max())
    np.testing.assert_allclose(out["T"] - 1.0, full["T"], rtol=0, atol=4 * EPS * np.abs(full["T"]).max())
    assert all(np.all(out[k] == 1.0) for k in ("Kq", "Cv", "Qw", "dTq", "dTv", "dTw"))
