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

from ancf.belts import friction
from ancf.belts.contact2d import SUPPORTED_POINTS, contact_forces, contact_points, contact_state
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


def _creep_rate(mu, nu):
    return friction.contact_record(KP, CP, "creep-rate", mu, nu)


def _branches(state, prm):
    """Per point and pulley: 0 out, 1 clamped, 2 linear (or the smooth law's one branch),
    +-3 saturated (sign of v_t)."""
    _, d, Fn, phi, vt = state
    creep = prm.law == friction.CODES["creep-rate"]
    sat = creep & (Fn > 0) & (prm.nu_s * np.abs(vt) >= prm.mu * Fn)
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
    kp, cp, *values = case["prm"]
    prm = friction.contact_record(kp, cp, case.get("law", friction.LAW), *values)
    return E, V, S0, w, centres, radii, omegas, prm


CASES = {  # ring gap (m), offset from pulley 0 (m), rotation and noise (rad/s, m/s), prm
    "none": dict(seed=0, gap=2e-3, offset=np.zeros(2), omega_b=5.0, v_noise=0.1,
                 omega=4.0, prm=[KP, CP, MU, 10.0]),
    "linear": dict(seed=1, gap=0.0, offset=np.array([0.0018, 0.0009]), omega_b=5.0,
                   v_noise=0.05, omega=5.0, prm=[KP, CP, MU, 10.0]),
    "saturated": dict(seed=2, gap=0.0, offset=np.array([0.0018, 0.0009]), omega_b=5.0,
                      v_noise=0.05, omega=5.0, prm=[KP, CP, MU, 1e7]),
    "mixed-clamped": dict(seed=3, gap=0.0, offset=np.array([-0.0007, 0.0019]), omega_b=5.0,
                          v_noise=0.5, omega=3.0, prm=[KP, 5e3, MU, 1e3]),
    "coulomb": dict(seed=3, gap=0.0, offset=np.array([-0.0007, 0.0019]), omega_b=5.0,
                    v_noise=0.5, omega=3.0, prm=[KP, 5e3, MU, 0.2], law="coulomb"),
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
            state = contact_state(*args[:3], centres, radii, args[3], prm)
            assert np.array_equal(_branches(state, prm), labels), f"{case}: a kink within one step"
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
    if case == "coulomb":
        assert min(counts[1], counts[2]) > 0 and counts[3] + counts[-3] == 0, counts


@pytest.mark.parametrize("case", list(CASES))
def test_point_law_follows_eqs_3_20_to_3_25(case):
    """contact_state against the equations written out in numpy, every branch."""
    E, V, S0, w, centres, radii, omegas, prm = _fd_state(CASES[case])
    kp, cp, mu, q = CASES[case]["prm"]
    r, d, Fn, phi, vt = contact_state(E, V, S0, centres, radii, omegas, prm)
    rdot = np.einsum("egk,ekd->egd", S0, V)
    a = np.einsum("egk,ekd->egd", S0, E)[:, :, None, :] - centres
    dist = np.linalg.norm(a, axis=-1)
    n = a / dist[..., None]
    t = n @ I_TILDE.T
    d_ref = radii - dist
    ddot = -np.sum(n * rdot[:, :, None], axis=-1)
    Fn_ref = np.where(d_ref >= 0, np.maximum(kp * d_ref + cp * ddot, 0.0), 0.0)
    vt_ref = np.sum(t * (rdot[:, :, None] - (omegas * radii)[:, None] * t), axis=-1)
    phi_ref = (-mu * Fn_ref * np.tanh(vt_ref / q) if CASES[case].get("law") == "coulomb"
               else -np.sign(vt_ref) * np.minimum(q * np.abs(vt_ref), mu * Fn_ref))
    pairs = ((r[:, :, None], a + centres), (d, d_ref), (Fn, Fn_ref), (vt, vt_ref), (phi, phi_ref))
    for got, ref in pairs:  # 64 ulps of the largest value: sums of 6 products, a sqrt
        np.testing.assert_allclose(np.broadcast_to(got, ref.shape), ref, rtol=0,
                                   atol=64 * EPS * np.abs(ref).max())


def test_forces_are_added_and_jacobians_only_on_request():
    E, V, S0, w, centres, radii, omegas, prm = _fd_state(CASES["mixed-clamped"])
    full = _forces(E, V, S0, w, centres, radii, omegas, prm)
    out = {k: np.ones_like(v) for k, v in _outputs(E.shape[0], radii.size).items()}
    contact_forces(E, V, S0, w, centres, radii, omegas, prm, False, **out)
    for k in ("Q", "T"):  # 1 + x - 1 loses at most an ulp of max(1, |x|)
        atol = 4 * EPS * max(1.0, np.abs(full[k]).max())
        np.testing.assert_allclose(out[k] - 1.0, full[k], rtol=0, atol=atol)
    assert all(np.all(out[k] == 1.0) for k in ("Kq", "Cv", "Qw", "dTq", "dTv", "dTw"))


# ------------------------------------------------------------------ analytic rings
RHO = R0 - D0   # ring radius, m
N_RING = 20
RING_RTOL = 1e-5
PULLEY = np.array([[0.03, -0.02]])


def _ring_deviation(E, l, centre, rho, n=201):
    """max | |r(x) - centre| - rho | along the ring's centreline (m), sampled densely."""
    x = np.linspace(0.0, 1.0, n)[None, :] * l[:, None]
    r = np.einsum("exk,ekd->exd", cubic2d_S(x, 0.0, l[:, None]), E)
    return np.abs(np.linalg.norm(r - centre, axis=-1) - rho).max()


def _ring_case(omega_b, omega, nu, offset=np.zeros(2), gauss_points=7):
    E, V, S0, w, l = _ring(N_RING, RHO, PULLEY[0] + offset, omega_b, gauss_points)
    prm = _creep_rate(MU, nu)
    args = (E, V, S0, PULLEY, np.array([R0]), np.array([omega]), prm)
    return E, l, w, _forces(E, V, S0, w, *args[3:], want_J=False), contact_state(*args)


def _virtual_work(E, Q, mode):
    """Q . de for de = mode(E - o) on positions and mode(E) on slopes (a rigid field)."""
    X = E.copy()
    X[:, [0, 3]] -= PULLEY[0]
    return np.sum(Q.reshape(E.shape) * (X @ mode.T))


def test_ring_geometry_is_a_circle_within_the_ring_tolerance():
    """Precondition of the ring tests: the Hermite ring deviates from its circle by far
    less than RING_RTOL of the penetration, so k_p d is k_p D0 to RING_RTOL."""
    E, _, _, _, l = _ring(N_RING, RHO, PULLEY[0])
    assert _ring_deviation(E, l, PULLEY[0], RHO) <= 0.1 * RING_RTOL * D0


def test_ring_at_rest_presses_k_p_d0_per_unit_length_without_torque():
    E, _, w, out, (_, _, Fn, phi, _) = _ring_case(0.0, 0.0, 100.0)
    total = KP * D0 * 2 * np.pi * RHO  # N
    np.testing.assert_allclose(np.sum(w * Fn[:, :, 0]), total, rtol=RING_RTOL)
    np.testing.assert_allclose(_virtual_work(E, out["Q"], np.eye(2)), total * RHO, rtol=RING_RTOL)
    force = out["Q"].reshape(E.shape)[:, [0, 3]].sum(axis=(0, 1))  # S1 + S4 = 1: int f dx
    assert np.linalg.norm(force) <= RING_RTOL * total, force
    assert abs(out["T"][0]) <= RING_RTOL * MU * total * RHO and not phi.any()


@pytest.mark.parametrize("omega", [9.0, 11.0], ids=["belt-faster", "pulley-faster"])
@pytest.mark.parametrize("ratio,branch", [(0.1, "linear"), (0.999, "linear"),
                                          (1.001, "saturated"), (100.0, "saturated")])
def test_rotating_ring_slides_by_the_tri_linear_law(omega, ratio, branch):
    """nu_s is set so that nu_s |v_t| = ratio mu k_p D0 (either side of saturation)."""
    omega_b = 10.0  # rad/s
    v_expected = omega_b * RHO - omega * R0  # m/s: belt speed minus pulley surface speed
    nu = ratio * MU * KP * D0 / abs(v_expected)
    E, _, w, out, (_, _, Fn, phi, vt) = _ring_case(omega_b, omega, nu)
    phi_expected = (-nu * v_expected if branch == "linear"
                    else -np.sign(v_expected) * MU * KP * D0)
    assert (nu * abs(v_expected) < MU * KP * D0) == (branch == "linear")
    np.testing.assert_allclose(vt, v_expected, rtol=RING_RTOL)
    np.testing.assert_allclose(Fn, KP * D0, rtol=RING_RTOL)
    np.testing.assert_allclose(phi, phi_expected, rtol=RING_RTOL)
    torque = -phi_expected * RHO * 2 * np.pi * RHO  # N m on the pulley
    np.testing.assert_allclose(out["T"][0], torque, rtol=RING_RTOL)
    # action and reaction: the moment of the belt's forces about o is -T
    np.testing.assert_allclose(_virtual_work(E, out["Q"], I_TILDE), -torque, rtol=RING_RTOL)


ECC_OFFSET = np.array([4e-4, 3e-4])  # m, < D0: the whole ring stays in contact
ECC_RTOL = 1e-4


def test_gauss_rules_agree_on_the_eccentric_ring():
    """Total force int f dx of a ring off-centre by c: against a periodic trapezoidal
    integral of k_p d n over the exact circle (error ~ 2 max deviation / |c|, checked
    below ECC_RTOL / 10), and the three rules against each other."""
    theta = np.linspace(0.0, 2 * np.pi, 4096, endpoint=False)
    a = ECC_OFFSET + RHO * np.stack([np.cos(theta), np.sin(theta)], axis=-1)
    dist = np.linalg.norm(a, axis=-1)
    ref = np.mean((KP * (R0 - dist) / dist)[:, None] * a, axis=0) * 2 * np.pi * RHO
    forces = []
    for ng in SUPPORTED_POINTS:
        E, l, _, out, _ = _ring_case(0.0, 0.0, 100.0, ECC_OFFSET, ng)
        forces.append(out["Q"].reshape(E.shape)[:, [0, 3]].sum(axis=(0, 1)))
    dev = _ring_deviation(E, l, PULLEY[0] + ECC_OFFSET, RHO)
    assert 2 * dev / np.linalg.norm(ECC_OFFSET) <= 0.1 * ECC_RTOL
    for f in forces:
        assert np.linalg.norm(f - ref) <= ECC_RTOL * np.linalg.norm(ref), (f, ref)
        assert np.linalg.norm(f - forces[-1]) <= ECC_RTOL * np.linalg.norm(ref), (f, forces[-1])


# ------------------------------------------------------------------ bounding test
def _random_elements(rng, nel):
    """Elements of length 0.02-0.2 m near two pulleys, slopes turned up to 60 degrees
    from the chord and stretched 0.5-1.5: curved elements grazing the pulleys."""
    l = rng.uniform(0.02, 0.2, nel)
    rI = rng.uniform(-0.2, 0.2, (nel, 2))
    chord = rng.uniform(0, 2 * np.pi, nel)
    rJ = rI + l[:, None] * np.stack([np.cos(chord), np.sin(chord)], axis=-1)

    def slope():
        ang = chord + rng.uniform(-np.pi / 3, np.pi / 3, nel)
        return rng.uniform(0.5, 1.5, nel)[:, None] * np.stack([np.cos(ang), np.sin(ang)], axis=-1)

    ry = rng.standard_normal((nel, 2))
    E = np.stack([rI, slope(), ry, rJ, slope(), ry], axis=1)
    return E, rng.standard_normal(E.shape), l


def test_bounding_test_never_skips_a_pair_in_contact():
    rng = np.random.default_rng(7)
    E, V, l = _random_elements(rng, 400)
    centres, radii = np.array([[0.0, 0.0], [0.12, 0.05]]), np.array([0.1, 0.04])
    omegas, prm = np.array([3.0, -2.0]), _creep_rate(MU, 100.0)
    S0, w, _ = contact_points(l, 7)
    # pair by pair: a skipped pair has its whole centreline outside the pulley
    x = np.linspace(0.0, 1.0, 401)[None, :] * l[:, None]
    curve = np.einsum("exk,ekd->exd", cubic2d_S(x, 0.0, l[:, None]), E)
    skipped, margin = 0, []
    for p in range(radii.size):
        gap = np.linalg.norm(curve - centres[p], axis=-1).min(axis=1) - radii[p]  # (nel,)
        for e in range(E.shape[0]):
            pair = _forces(E[e:e + 1], V[e:e + 1], S0[e:e + 1], w[e:e + 1], centres[p:p + 1],
                           radii[p:p + 1], omegas[p:p + 1], prm, want_J=False)
            if pair["pairs"] == 0:
                skipped += 1
                margin.append(gap[e] / l[e])
    assert skipped > 0 and min(margin) > 0, (skipped, min(margin))
    assert min(margin) < 0.05  # some skipped elements graze the pulley
    # all pairs at once against the unbounded per-point state
    out = _forces(E, V, S0, w, centres, radii, omegas, prm, want_J=False)
    r, _, Fn, phi, _ = contact_state(E, V, S0, centres, radii, omegas, prm)
    a = r[:, :, None, :] - centres                                   # (nel, ng, np, 2)
    n = a / np.linalg.norm(a, axis=-1, keepdims=True)
    f = Fn[..., None] * n + phi[..., None] * (n @ I_TILDE.T)
    Q = np.einsum("eg,egk,egpd->ekd", w, S0, f).reshape(out["Q"].shape)
    T = -np.einsum("eg,egp,egp->p", w, phi, np.linalg.norm(a, axis=-1))
    assert np.sum(Fn > 0) > 0 and out["pairs"] == E.shape[0] * radii.size - skipped
    np.testing.assert_allclose(out["Q"], Q, rtol=0, atol=1e-12 * np.abs(Q).max())
    np.testing.assert_allclose(out["T"], T, rtol=1e-12)
    shift = np.zeros(E.shape[1:])
    shift[[0, 3], 0] = 10 * radii.max()  # positions only, the slopes stay
    far = _forces(E + shift, V, S0, w, centres, radii, omegas, prm, want_J=False)
    assert far["pairs"] == 0 and not far["Q"].any()


# ------------------------------------------------------------------ input
@pytest.mark.parametrize("bad", [2, 6, 9, "7", None])
def test_unsupported_gauss_points_are_refused_by_name(bad):
    with pytest.raises(ValueError, match=r"gauss_points must be one of \(3, 4, 5, 7, 11\)"):
        contact_points(np.ones(3), bad)
