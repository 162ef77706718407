"""Plate-pulley contact in 3D (thesis 4.5, Eqs 4.43-4.45): Jacobians, the point law,
analytic wrapped strips, the planar reduction to ancf/belts/contact2d.py, the bounding test,
input.

Finite-difference tolerance as in tests/belts/test_contact.py: within one branch of the law
the forces are smooth, linear in the velocities and pulley speeds (linear branch) and
with curvature ~ 1/|N| ~ 10 m^-1 in the positions, so the central difference with
H = 1e-6 has truncation ~ 1e-10 relative; each Jacobian column must match to RTOL of
its norm plus ROUND_MARGIN eps max|Q| / H.  No stencil point may change the branch
of any point (out, clamped, linear, saturated).  On the saturated branch the
friction's direction v_s / |v_s| turns on the scale |v_s|, so the states keep |v_s|
far above H (checked).
"""
from __future__ import annotations

import numpy as np
import pytest

from ancf.belts import friction
from ancf.belts.contact2d import contact_forces, contact_points, contact_state
from ancf.belts.contact3d import (SUPPORTED_RULES, contact_forces3d, contact_points3d,
                            contact_state3d)
from ancf.elements._generated import plate36_S

H = 1e-6
RTOL = 1e-6
ROUND_MARGIN = 1e3
EPS = np.finfo(np.float64).eps

R0 = 0.1                         # pulley radius, m (Table 4.1, Model 1)
D0 = 2e-3                        # penetration of the wrapped strips, m
WIDTH = 0.08                     # strip width, m (Table 4.1, Model 1)
KP, CP, MU = 1e7, 2000.0, 0.3    # N/m^3, N s/m^3, -
POS = (0, 3, 6, 9)               # position rows of nodes A, B, C, D


def _outputs(nel, npul):
    return dict(Q=np.zeros((nel, 36)), Kq=np.zeros((nel, 36, 36)), Cv=np.zeros((nel, 36, 36)),
                Qw=np.zeros((nel, npul, 36)), T=np.zeros(npul), dTq=np.zeros((npul, nel, 36)),
                dTv=np.zeros((npul, nel, 36)), dTw=np.zeros(npul))


def _forces(E, V, S0, w, pul, omegas, prm, want_J=True):
    out = _outputs(E.shape[0], pul["radii"].size)
    out["pairs"] = contact_forces3d(E, V, S0, w, pul["centres"], pul["axes"], pul["radii"],
                                    omegas, pul["odot"], prm, want_J, **out)
    return out


def _state(E, V, S0, pul, omegas, prm):
    return contact_state3d(E, V, S0, pul["centres"], pul["axes"], pul["radii"], omegas,
                           pul["odot"], prm)


def _frame(axis):
    """Orthonormal (e1, e2, p) with p along ``axis`` (right-handed)."""
    p = np.asarray(axis, float) / np.linalg.norm(axis)
    e1 = np.cross(p, [0.3, -0.5, 0.8])
    e1 /= np.linalg.norm(e1)
    return e1, np.cross(p, e1), p


def _wrap(nel, rho, centre, axis, arc=2 * np.pi, theta0=0.0, width=WIDTH, omega_b=0.0,
          axial=0.0, drift=np.zeros(3), rule=25):
    """A strip of ``nel`` plate elements (one across the width) wrapped over ``arc`` (rad)
    on the cylinder of radius ``rho`` (m) about ``axis`` through ``centre``: x along the
    circumference (counter-clockwise about the axis), y along the axis.  Node slopes
    r_x of magnitude 4 tan(dth/4) rho / l (the Bezier arc closest to the circle, as
    tests/belts/test_contact.py), r_y = p.  Moving rigidly: rotation omega_b (rad/s) about
    the axis, axial speed (m/s), translation ``drift`` (m/s)."""
    e1, e2, p = _frame(axis)
    th = theta0 + np.linspace(0.0, arc, nel + 1)
    dth = th[1] - th[0]
    l = np.full(nel, rho * dth)
    u = np.cos(th)[:, None] * e1 + np.sin(th)[:, None] * e2
    tang = np.cross(p, u)
    slope = 4 * np.tan(dth / 4) * rho / l[0] * tang
    py = np.broadcast_to(p, u.shape)

    def node(i, y):  # (3 slots, 3) at node i of the circumference, height y
        return np.stack([centre + rho * u[i] + y * p, slope[i], py[i]])

    E = np.stack([np.concatenate([node(i, 0.0), node(i + 1, 0.0), node(i + 1, width),
                                  node(i, width)]) for i in range(nel)])
    V = omega_b * np.cross(p, E - np.where(np.isin(np.arange(12), POS)[:, None], centre, 0.0))
    V[:, POS] += axial * p + drift
    S0, w = contact_points3d(l, np.full(nel, width), rule)
    return E, V, S0, w, l


def _pulleys(centres, axes, radii, odot=None):
    centres = np.asarray(centres, float)
    return dict(centres=centres, axes=np.asarray(axes, float), radii=np.asarray(radii, float),
                odot=np.zeros_like(centres) if odot is None else np.asarray(odot, float))


# ------------------------------------------------------------------ rules
@pytest.mark.parametrize("rule", SUPPORTED_RULES)
def test_rule_weights_sum_to_the_element_area_and_positions_to_one(rule):
    a, b = np.array([0.05, 0.2, 0.013]), np.array([0.08, 0.01, 0.04])
    S0, w = contact_points3d(a, b, rule)
    assert S0.shape == (3, rule, 12) and w.shape == (3, rule)
    np.testing.assert_allclose(w.sum(axis=1), a * b, rtol=4 * rule * EPS)
    np.testing.assert_allclose(S0[:, :, POS].sum(axis=-1), 1.0, rtol=0, atol=64 * EPS)
    # the moments the kernel recovers the sides from: int S_1 = a^2 b / 24, int S_2 = a b^2 / 24
    np.testing.assert_allclose(np.einsum("eq,eq->e", w, S0[:, :, 1]), a**2 * b / 24, rtol=1e-13)
    np.testing.assert_allclose(np.einsum("eq,eq->e", w, S0[:, :, 2]), a * b**2 / 24, rtol=1e-13)


@pytest.mark.parametrize("bad", [16, 36, 64, 100, 9, "81", None, 81.5, True])
def test_unsupported_rules_are_refused_by_name(bad):
    with pytest.raises(ValueError, match=r"contact_points3d: rule must be one of \(25, 49, 81\)"):
        contact_points3d(np.ones(3), np.ones(3), bad)


@pytest.mark.parametrize("lengths,widths", [([0.1, -0.1], [0.1, 0.1]), ([0.1], [np.nan]),
                                            ([[0.1]], [[0.1]]), ([0.1, 0.2], [0.1])])
def test_bad_sides_are_refused(lengths, widths):
    with pytest.raises(ValueError, match="contact_points3d"):
        contact_points3d(lengths, widths, 25)


# ------------------------------------------------------------------ Jacobians
AXIS = np.array([0.2, -0.3, 0.9])      # a tilted pulley axis


def _fd_state(case):
    """4 elements wrapped over 1.6 rad at radius R0 + gap, off-centre from pulley 0 (pulley
    1 far away, along another axis), random perturbations; both pulley centres move."""
    rng = np.random.default_rng(case["seed"])
    e1, e2, p = _frame(AXIS)
    pul = _pulleys([[0.02, -0.01, 0.03], [0.6, 0.3, -0.2]], [AXIS, [1.0, 0.0, 0.0]], [R0, 0.05],
                   odot=[[0.3, -0.2, 0.1], [0.0, 0.5, 0.0]])
    offset = case["offset"][0] * e1 + case["offset"][1] * e2 + 0.01 * p
    E, V, S0, w, _ = _wrap(4, R0 + case["gap"], pul["centres"][0] + offset, AXIS, arc=1.6,
                           theta0=-0.3, width=0.05, omega_b=case["omega_b"],
                           axial=case["axial"], drift=pul["odot"][0])
    E = E + 1e-4 * rng.standard_normal(E.shape)
    V = V + case["v_noise"] * rng.standard_normal(V.shape)
    omegas = np.array([case["omega"], 3.0])
    kp, cp, *values = case["prm"]
    prm = friction.contact_record(kp, cp, case.get("law", friction.LAW), *values)
    return E, V, S0, w, pul, omegas, prm


def _creep_rate(mu, nu):
    return friction.contact_record(KP, CP, "creep-rate", mu, nu)


# the strip (over -0.3 .. 1.3 rad) at R0 + GAP from a centre off by 2 mm towards -0.5 rad:
# |N| ~ R0 + GAP - 2 mm cos(theta - 0.5), in contact over 0.5 -+ 0.64 rad (0.4 mm deep),
# so the first and last elements are partly in contact
GAP = 1.6e-3
OFFSET = tuple(-2e-3 * np.array([np.cos(0.5), np.sin(0.5)]))
CASES = {  # gap (m), offset in the pulley plane (m), rotation (rad/s), axial and noise (m/s)
    "none": dict(seed=0, gap=2e-3, offset=(0.0, 0.0), omega_b=5.0, axial=0.2, v_noise=0.1,
                 omega=4.0, prm=[KP, CP, MU, 1e2]),
    "linear": dict(seed=0, gap=GAP, offset=OFFSET, omega_b=5.0, axial=0.2,
                   v_noise=0.05, omega=5.0, prm=[KP, CP, MU, 1e2]),
    "sticking": dict(seed=0, gap=GAP, offset=OFFSET, omega_b=0.0, axial=0.0, v_noise=0.0,
                     omega=0.0, prm=[KP, CP, MU, 1e5]),  # v_s = 0: the linear branch is smooth
    "saturated": dict(seed=0, gap=GAP, offset=OFFSET, omega_b=5.0, axial=0.2,
                      v_noise=0.05, omega=2.0, prm=[KP, CP, MU, 1e8]),
    "mixed-clamped": dict(seed=1, gap=GAP, offset=OFFSET, omega_b=5.0, axial=0.0,
                          v_noise=0.5, omega=4.5, prm=[KP, 5e6, MU, 1e6]),
    "coulomb": dict(seed=1, gap=GAP, offset=OFFSET, omega_b=5.0, axial=0.0, v_noise=0.5,
                    omega=4.5, prm=[KP, 5e6, MU, 0.2], law="coulomb"),
}


def _check(fd, exact, scale, name):
    """Column-wise: ||fd_j - exact_j|| <= RTOL ||exact_j|| + ROUND_MARGIN eps scale / H.
    Returns the largest error relative to max(||exact_j||, atol)."""
    err = np.abs(fd - exact).reshape(-1, exact.shape[-1])
    ref = np.abs(exact).reshape(-1, exact.shape[-1])
    err, ref = np.linalg.norm(err, axis=0), np.linalg.norm(ref, axis=0)
    atol = ROUND_MARGIN * EPS * scale / H
    assert np.all(err <= RTOL * ref + atol), (name, err, ref, atol)
    return float(np.max(err / np.maximum(ref, max(atol, 1e-300))))


@pytest.mark.parametrize("case", list(CASES))
def test_jacobians_match_central_differences(case):
    E, V, S0, w, pul, omegas, prm = _fd_state(CASES[case])
    base = _forces(E, V, S0, w, pul, omegas, prm)
    st = _state(E, V, S0, pul, omegas, prm)
    labels = st[5]
    nel, npul = E.shape[0], pul["radii"].size
    fd = _outputs(nel, npul)

    def diff(make):  # central difference of (Q, T); the branches must not change
        res = []
        for sgn in (1.0, -1.0):
            Ep, Vp, om = make(sgn * H)
            assert np.array_equal(_state(Ep, Vp, S0, pul, om, prm)[5], labels), \
                f"{case}: a kink within one step"
            o = _forces(Ep, Vp, S0, w, pul, om, prm, want_J=False)
            res.append((o["Q"], o["T"]))
        return (res[0][0] - res[1][0]) / (2 * H), (res[0][1] - res[1][1]) / (2 * H)

    for e in range(nel):
        for j in range(36):
            k, c = divmod(j, 3)
            for X, K, dT in ((E, "Kq", "dTq"), (V, "Cv", "dTv")):
                def make(h, X=X):
                    Xp = X.copy()
                    Xp[e, k, c] += h
                    return (Xp, V, omegas) if X is E else (E, Xp, omegas)
                dQ, dTp = diff(make)
                fd[K][e, :, j] = dQ[e]
                assert np.all(dQ[np.arange(nel) != e] == 0.0)  # elements do not couple
                fd[dT][:, e, j] = dTp
    for p in range(npul):
        def make(h):
            om = omegas.copy()
            om[p] += h
            return E, V, om
        dQ, dTp = diff(make)
        fd["Qw"][:, p, :] = dQ
        fd["dTw"][p] = dTp[p]
    # round-off scales: the largest nodal force, and for the moment the larger of |T| and
    # that force at the lever R0 (with v_s = 0, T is 0 but its derivatives are not)
    sQ = np.abs(base["Q"]).max()
    sT = max(np.abs(base["T"]).max(), R0 * sQ)
    errs = {name: _check(fd[name], base[name], sQ, name) for name in ("Kq", "Cv", "Qw")}
    errs.update({name: _check(fd[name], base[name], sT, name) for name in ("dTq", "dTv")})
    errs["dTw"] = _check(fd["dTw"][:, None], base["dTw"][:, None], sT, "dTw")
    print(case, {k: f"{v:.1e}" for k, v in errs.items()})

    counts = {b: int(np.sum(labels == b)) for b in range(5)}
    assert not labels[:, :, 1].any()  # pulley 1 is far
    if case == "none":
        assert base["pairs"] > 0 and counts[0] == labels.size and not base["Q"].any()
    else:
        partly = np.sum(np.any(labels[:, :, 0] != 0, axis=1) & np.any(labels[:, :, 0] == 0, axis=1))
        assert partly >= 2, labels[:, :, 0]
    vsn = np.linalg.norm(st[4], axis=-1)
    if case == "linear":
        assert counts[2] > 0 and counts[3] == 0, counts
    if case == "sticking":
        assert counts[2] > 0 and counts[3] == 0 and vsn[labels == 2].max() <= 1e-12, counts
    if case == "saturated":
        assert counts[3] > 0 and counts[2] == 0 and vsn[labels == 3].min() > 1e3 * H, counts
    if case == "mixed-clamped":
        assert min(counts[1], counts[2], counts[3]) > 0, counts
        assert vsn[labels == 3].min() > 1e3 * H
    if case == "coulomb":
        assert min(counts[1], counts[friction.SMOOTH]) > 0 and counts[2] + counts[3] == 0, counts


@pytest.mark.parametrize("case", list(CASES))
def test_point_law_follows_eqs_4_43_and_4_44(case):
    """contact_state3d against the equations written out in numpy, every branch."""
    E, V, S0, w, pul, omegas, prm = _fd_state(CASES[case])
    kp, cp, mu, q = CASES[case]["prm"]
    r, d, Fn, ft, vs, _ = _state(E, V, S0, pul, omegas, prm)
    p = pul["axes"] / np.linalg.norm(pul["axes"], axis=-1, keepdims=True)
    rdot = np.einsum("eqk,ekd->eqd", S0, V)[:, :, None, :]
    rn = np.einsum("eqk,ekd->eqd", S0, E)[:, :, None, :] - pul["centres"]
    N = rn - np.sum(rn * p, axis=-1, keepdims=True) * p               # (4.44)
    dist = np.linalg.norm(N, axis=-1)
    n = N / dist[..., None]
    d_ref = pul["radii"] - dist                                          # (4.43)
    ddot = -np.sum(n * (rdot - pul["odot"]), axis=-1)
    Fn_ref = np.where(d_ref >= 0, np.maximum(kp * d_ref + cp * ddot, 0.0), 0.0)
    u = pul["odot"] + (omegas * pul["radii"])[:, None] * np.cross(p, n)
    wrel = rdot - u
    vs_ref = wrel - np.sum(wrel * n, axis=-1, keepdims=True) * n
    vsn = np.linalg.norm(vs_ref, axis=-1)
    if CASES[case].get("law") == "coulomb":
        g = mu * Fn_ref * np.tanh(vsn / q) / np.where(vsn > 0, vsn, 1.0)
        ft_ref = -g[..., None] * vs_ref
    else:
        lin = q * vsn <= mu * Fn_ref
        ft_ref = np.where(lin[..., None], -q * vs_ref,
                          -(mu * Fn_ref / np.where(lin, 1.0, vsn))[..., None] * vs_ref)
    ft_ref = np.where((Fn_ref > 0)[..., None], ft_ref, 0.0)
    pairs = ((r[:, :, None], rn + pul["centres"]), (d, d_ref), (Fn, Fn_ref), (vs, vs_ref),
             (ft, ft_ref))
    for got, ref in pairs:  # 64 ulps of the largest value: sums of 12 products, a sqrt
        np.testing.assert_allclose(np.broadcast_to(got, ref.shape), ref, rtol=0,
                                   atol=64 * EPS * np.abs(ref).max())


def test_forces_are_added_and_jacobians_only_on_request():
    E, V, S0, w, pul, omegas, prm = _fd_state(CASES["mixed-clamped"])
    full = _forces(E, V, S0, w, pul, omegas, prm)
    out = {k: np.ones_like(v) for k, v in _outputs(E.shape[0], pul["radii"].size).items()}
    contact_forces3d(E, V, S0, w, pul["centres"], pul["axes"], pul["radii"], omegas,
                     pul["odot"], prm, False, **out)
    for k in ("Q", "T"):  # 1 + x - 1 loses at most an ulp of max(1, |x|)
        atol = 4 * EPS * max(1.0, np.abs(full[k]).max())
        np.testing.assert_allclose(out[k] - 1.0, full[k], rtol=0, atol=atol)
    assert all(np.all(out[k] == 1.0) for k in ("Kq", "Cv", "Qw", "dTq", "dTv", "dTw"))


def test_a_common_translation_of_plate_and_pulley_changes_nothing():
    """Moving centre: the law depends on rdot - odot only (u = odot + omega R t)."""
    E, V, S0, w, pul, omegas, prm = _fd_state(CASES["mixed-clamped"])
    U = np.array([0.7, -0.4, 1.1])  # m/s
    moved = dict(pul, odot=pul["odot"] + U)
    V2 = V.copy()
    V2[:, POS] += U
    a, b = _forces(E, V, S0, w, pul, omegas, prm), _forces(E, V2, S0, w, moved, omegas, prm)
    for k in ("Q", "T", "Kq", "Cv", "Qw", "dTq", "dTv", "dTw"):
        np.testing.assert_allclose(b[k], a[k], rtol=0, atol=1e-11 * max(1.0, np.abs(a[k]).max()))


# ------------------------------------------------------------------ wrapped strips
RHO = R0 - D0
N_WRAP = 24
WRAP_RTOL = 1e-5
PULLEY = _pulleys([[0.03, -0.02, 0.01]], [AXIS], [R0])


def _deviation(E, l, width, centre, rho, n=81):
    """max | |N(r)| - rho | over the strip's mid surface (m), sampled densely."""
    g = np.linspace(0.0, 1.0, n)
    X, Y = (v.ravel() for v in np.meshgrid(g, g, indexing="ij"))
    r = np.einsum("eqk,ekd->eqd", plate36_S(X * l[:, None], Y * width, l[:, None], width), E)
    p = AXIS / np.linalg.norm(AXIS)
    rn = r - centre
    N = rn - (rn @ p)[..., None] * p
    return np.abs(np.linalg.norm(N, axis=-1) - rho).max()


def test_wrapped_strip_geometry_is_a_cylinder_within_the_tolerance():
    """Precondition: the strip's mid surface deviates from its cylinder by far less than
    WRAP_RTOL of the penetration, so k_p d is k_p D0 to WRAP_RTOL."""
    E, _, _, _, l = _wrap(N_WRAP, RHO, PULLEY["centres"][0], AXIS)
    assert _deviation(E, l, WIDTH, PULLEY["centres"][0], RHO) <= 0.1 * WRAP_RTOL * D0


@pytest.mark.parametrize("rule", SUPPORTED_RULES)
def test_strip_at_rest_presses_k_p_d0_times_the_area(rule):
    """Full wrap: total normal force k_p D0 x area, no net force, no moment, no friction;
    half wrap: the resultant int f dA = k_p D0 (2 rho) width along the mean normal."""
    prm = _creep_rate(MU, 1e5)
    E, V, S0, w, _ = _wrap(N_WRAP, RHO, PULLEY["centres"][0], AXIS, rule=rule)
    out = _forces(E, V, S0, w, PULLEY, np.zeros(1), prm, want_J=False)
    _, d, Fn, ft, _, _ = _state(E, V, S0, PULLEY, np.zeros(1), prm)
    area = 2 * np.pi * RHO * WIDTH
    np.testing.assert_allclose(w.sum(), area, rtol=1e-13)
    np.testing.assert_allclose(np.sum(w * Fn[:, :, 0]), KP * D0 * area, rtol=WRAP_RTOL)
    force = out["Q"].reshape(E.shape)[:, POS].sum(axis=(0, 1))   # positions sum to one
    assert np.linalg.norm(force) <= WRAP_RTOL * KP * D0 * area, force
    assert abs(out["T"][0]) <= WRAP_RTOL * MU * KP * D0 * area * RHO and not ft.any()

    e1, e2, _ = _frame(AXIS)
    E, V, S0, w, _ = _wrap(N_WRAP // 2, RHO, PULLEY["centres"][0], AXIS, arc=np.pi, rule=rule)
    out = _forces(E, V, S0, w, PULLEY, np.zeros(1), prm, want_J=False)
    force = out["Q"].reshape(E.shape)[:, POS].sum(axis=(0, 1))
    np.testing.assert_allclose(force, KP * D0 * 2 * RHO * WIDTH * e2, rtol=0,
                               atol=WRAP_RTOL * KP * D0 * 2 * RHO * WIDTH)


@pytest.mark.parametrize("omega", [9.0, 11.0], ids=["belt-faster", "pulley-faster"])
@pytest.mark.parametrize("ratio,branch", [(0.1, 2), (0.999, 2), (1.001, 3), (100.0, 3)])
def test_sliding_strip_follows_the_creep_rate_law(omega, ratio, branch):
    """The strip turns at omega_b and slides along the axis at AXIAL: v_s = (omega_b rho -
    omega R) t + AXIAL p everywhere; nu_s is set so that nu_s |v_s| = ratio mu k_p D0.
    The friction opposes the sliding, and the pulley's moment is the friction's
    circumferential part times |N| = R - D0, over the area."""
    omega_b, axial = 10.0, 0.05
    E, V, S0, w, _ = _wrap(N_WRAP, RHO, PULLEY["centres"][0], AXIS, omega_b=omega_b, axial=axial)
    e1, e2, p = _frame(AXIS)
    vt = omega_b * RHO - omega * R0
    speed = np.hypot(vt, axial)
    nu = ratio * MU * KP * D0 / speed
    prm = _creep_rate(MU, nu)
    out = _forces(E, V, S0, w, PULLEY, np.array([omega]), prm, want_J=False)
    r, _, Fn, ft, vs, br = _state(E, V, S0, PULLEY, np.array([omega]), prm)
    rn = r - PULLEY["centres"][0]
    n = rn - (rn @ p)[..., None] * p
    n /= np.linalg.norm(n, axis=-1, keepdims=True)
    vs_ref = vt * np.cross(p, n) + axial * p
    np.testing.assert_allclose(vs[:, :, 0], vs_ref, rtol=0, atol=WRAP_RTOL * speed)
    np.testing.assert_allclose(Fn, KP * D0, rtol=WRAP_RTOL)
    assert np.all(br == branch)
    mag = nu * speed if branch == 2 else MU * KP * D0
    np.testing.assert_allclose(ft[:, :, 0], -mag * vs_ref / speed, rtol=0, atol=WRAP_RTOL * mag)
    # opposes: antiparallel to v_s at every point
    dot = np.sum(ft[:, :, 0] * vs[:, :, 0], axis=-1)
    assert np.all(dot < 0)
    np.testing.assert_allclose(-dot, np.linalg.norm(ft[:, :, 0], axis=-1) *
                               np.linalg.norm(vs[:, :, 0], axis=-1), rtol=1e-12)
    area = 2 * np.pi * RHO * WIDTH
    torque = -(-mag * vt / speed) * RHO * area    # N m on the pulley
    np.testing.assert_allclose(out["T"][0], torque, rtol=WRAP_RTOL)
    assert np.sign(out["T"][0]) == np.sign(vt)     # the belt drags the pulley along
    # action and reaction: the belt's axial force is -mu-law x area, its moment about p is -T
    Qn = out["Q"].reshape(E.shape)
    np.testing.assert_allclose(Qn[:, POS].sum(axis=(0, 1)) @ p, -mag * axial / speed * area,
                               rtol=WRAP_RTOL)
    X = E - np.where(np.isin(np.arange(12), POS)[:, None], PULLEY["centres"][0], 0.0)
    np.testing.assert_allclose(np.sum(Qn * np.cross(p, X)), -torque, rtol=WRAP_RTOL)


# ------------------------------------------------------------------ planar reduction
def test_plane_motion_reduces_to_the_2d_law_per_unit_width():
    """A strip on a pulley with axis z, moving in the x-y plane: per unit width the
    normal force, friction, sliding speed, moment and nodal forces equal those of
    ancf/belts/contact2d.py for the same centre line, with k_p, c_p, nu_s divided by the width."""
    n, b, nel = 7, 0.04, 6
    prm2 = friction.contact_record(1e6, 50.0, "creep-rate", MU, 1e3)  # N/m^2, N s/m^2, kg/(m s)
    prm3 = friction.contact_record(1e6 / b, 50.0 / b, "creep-rate", MU, 1e3 / b)  # per metre
    rng = np.random.default_rng(11)
    centre = np.array([0.02, -0.01])
    # a 2D arc of the belt: ring nodes of radius R0 off-centre, perturbed, with a velocity field
    th = np.linspace(-0.4, 1.4, nel + 1)
    dth = th[1] - th[0]
    l = np.full(nel, R0 * dth)
    u = np.stack([np.cos(th), np.sin(th)], axis=-1)
    tang = u @ np.array([[0.0, 1.0], [-1.0, 0.0]])
    rI = (centre - 1.5e-3 * np.array([np.cos(0.5), np.sin(0.5)]) + (R0 + 1e-3) * u
          + 1e-4 * rng.standard_normal(u.shape))  # in contact over 0.5 -+ 0.84 rad
    slope = 4 * np.tan(dth / 4) * R0 / l[0] * tang + 1e-3 * rng.standard_normal(u.shape)
    vI = 8.0 * R0 * tang + 0.2 * rng.standard_normal(u.shape)
    vx = 0.5 * rng.standard_normal(u.shape)
    E2 = np.concatenate([np.stack([rI[:-1], slope[:-1], u[:-1]], 1),
                         np.stack([rI[1:], slope[1:], u[1:]], 1)], axis=1)
    V2 = np.concatenate([np.stack([vI[:-1], vx[:-1], 0 * u[:-1]], 1),
                         np.stack([vI[1:], vx[1:], 0 * u[1:]], 1)], axis=1)
    z0 = 0.3

    def lift(X2, z, slope_y):  # (nel, 6, 2) -> (nel, 12, 3): nodes A, B, C, D of the strip
        def node(j, zj):  # r = (r2, zj), r_x = (r2_x, 0), r_y = (0, 0, slope_y)
            out = np.zeros((X2.shape[0], 3, 3))
            out[:, :2, :2] = X2[:, 3 * j:3 * j + 2]
            out[:, 0, 2], out[:, 2, 2] = zj, slope_y
            return out
        return np.concatenate([node(0, z[0]), node(1, z[0]), node(1, z[1]), node(0, z[1])], axis=1)

    E3 = lift(E2, (z0, z0 + b), 1.0)
    V3 = lift(V2, (0.0, 0.0), 0.0)
    omegas = np.array([6.0])
    S2, w2, _ = contact_points(l, n)
    S3, w3 = contact_points3d(l, np.full(nel, b), n * n)
    pul = _pulleys([[*centre, -1.0]], [[0.0, 0.0, 1.0]], [R0])
    out2 = dict(Q=np.zeros((nel, 12)), Kq=np.zeros((nel, 12, 12)), Cv=np.zeros((nel, 12, 12)),
                Qw=np.zeros((nel, 1, 12)), T=np.zeros(1), dTq=np.zeros((1, nel, 12)),
                dTv=np.zeros((1, nel, 12)), dTw=np.zeros(1))
    contact_forces(E2, V2, S2, w2, centre[None], pul["radii"], omegas, prm2, True, **out2)
    out3 = _forces(E3, V3, S3, w3, pul, omegas, prm3)
    _, d2, Fn2, phi2, vt2 = contact_state(E2, V2, S2, centre[None], pul["radii"], omegas, prm2)
    r3, d3, Fn3, ft3, vs3, br = _state(E3, V3, S3, pul, omegas, prm3)
    assert min(np.sum(br == 0), np.sum(br == 2), np.sum(br == 3)) > 0  # out, linear, saturated
    grid = (nel, n, n)
    for j in range(n):  # every row of points across the width
        tol = 1e-12
        np.testing.assert_allclose(d3.reshape(grid)[:, :, j], d2[:, :, 0], rtol=0, atol=tol * R0)
        np.testing.assert_allclose(b * Fn3.reshape(grid)[:, :, j], Fn2[:, :, 0], rtol=0,
                                   atol=tol * Fn2.max())
        t3 = np.cross([0.0, 0.0, 1.0], np.pad(r3.reshape(*grid, 3)[:, :, j, :2] - centre,
                                              ((0, 0), (0, 0), (0, 1))))
        t3 /= np.linalg.norm(t3, axis=-1, keepdims=True)
        ft = ft3.reshape(*grid, 3)[:, :, j]
        vs = vs3.reshape(*grid, 3)[:, :, j]
        np.testing.assert_allclose(b * np.sum(ft * t3, -1), phi2[:, :, 0], rtol=0,
                                   atol=tol * Fn2.max())
        np.testing.assert_allclose(np.sum(vs * t3, -1), vt2[:, :, 0], rtol=0, atol=tol)
        assert np.all(ft[..., 2] == 0) and np.all(np.abs(vs[..., 2]) <= tol)
    np.testing.assert_allclose(out3["T"], out2["T"], rtol=1e-12)
    np.testing.assert_allclose(out3["dTw"], out2["dTw"], rtol=1e-12)
    # nodal forces: A + D of the strip are node I of the belt, B + C node J (r and r_x)
    Q3, Q2 = out3["Q"].reshape(nel, 12, 3), out2["Q"].reshape(nel, 6, 2)
    for k3, k2 in ((0, 0), (1, 1), (3, 3), (4, 4)):
        pair = Q3[:, k3, :2] + Q3[:, {0: 9, 1: 10, 3: 6, 4: 7}[k3], :2]
        np.testing.assert_allclose(pair, Q2[:, k2], rtol=0, atol=1e-11 * np.abs(Q2).max())
    assert np.abs(Q3[..., 2]).max() <= 1e-12 * np.abs(Q2).max()


# ------------------------------------------------------------------ bounding test
def test_bernstein_control_points_reproduce_the_plate_field():
    """Premise of the bounding test: sum_ij B_i(x/a) B_j(y/b) P_ij = S e for any a x b
    element, with P from the unit-square controls and the r_x (r_y) columns scaled by
    a (b); the Bernstein weights are >= 0 and sum to one (the convex hull)."""
    from math import comb

    from ancf.belts.contact3d import _CONTROLS
    rng = np.random.default_rng(5)
    a, b = 0.17, 0.06
    xi, eta = rng.uniform(0, 1, 300), rng.uniform(0, 1, 300)
    def b3(i, t):
        return comb(3, i) * t**i * (1 - t) ** (3 - i)

    bern = np.stack([b3(i, xi) * b3(j, eta) for i in range(4) for j in range(4)], axis=1)
    assert np.all(bern >= 0) and np.allclose(bern.sum(axis=1), 1.0, rtol=0, atol=1e-15)
    scale = np.tile([1.0, a, b], 4)
    np.testing.assert_allclose(bern @ (_CONTROLS * scale), plate36_S(xi * a, eta * b, a, b),
                               rtol=0, atol=1e-14)


def _random_elements(rng, nel):
    """Plates of 0.02-0.2 m x 0.02-0.1 m in random orientation near two pulleys, corner
    positions perturbed by up to 20 % of the sides, slopes turned up to 45 degrees and
    stretched 0.5-1.5: warped elements grazing the pulleys."""
    a, b = rng.uniform(0.02, 0.2, nel), rng.uniform(0.02, 0.1, nel)
    Qr = np.linalg.qr(rng.standard_normal((nel, 3, 3)))[0]
    ex, ey = Qr[:, :, 0], Qr[:, :, 1]
    rA = rng.uniform(-0.2, 0.2, (nel, 3))
    size = np.maximum(a, b)[:, None]
    corners = [rA, rA + a[:, None] * ex, rA + a[:, None] * ex + b[:, None] * ey,
               rA + b[:, None] * ey]
    corners = [c + 0.2 * size * rng.uniform(-1, 1, (nel, 3)) for c in corners]

    def slope(v):
        turn = np.cross(v, rng.standard_normal((nel, 3)))
        turn *= np.tan(rng.uniform(0, np.pi / 4, nel))[:, None] / np.linalg.norm(turn, axis=1,
                                                                                   keepdims=True)
        s = v + turn
        return rng.uniform(0.5, 1.5, nel)[:, None] * s / np.linalg.norm(s, axis=1, keepdims=True)

    E = np.stack([x for c in corners for x in (c, slope(ex), slope(ey))], axis=1)
    return E, rng.standard_normal(E.shape), a, b


def test_bounding_test_never_skips_a_pair_in_contact():
    rng = np.random.default_rng(7)
    E, V, a, b = _random_elements(rng, 400)
    pul = _pulleys([[0.0, 0.0, 0.0], [0.12, 0.05, -0.03]], [[0.0, 0.0, 2.0], [0.6, 0.0, 0.8]],
                   [0.1, 0.04], odot=[[0.1, 0.0, 0.0], [0.0, -0.2, 0.3]])
    omegas, prm = np.array([3.0, -2.0]), _creep_rate(MU, 1e5)
    S0, w = contact_points3d(a, b, 25)
    # pair by pair: a skipped pair has its whole mid surface outside the cylinder
    g = np.linspace(0.0, 1.0, 41)
    X, Y = (v.ravel() for v in np.meshgrid(g, g, indexing="ij"))
    surf = np.einsum("eqk,ekd->eqd", plate36_S(X * a[:, None], Y * b[:, None], a[:, None],
                                               b[:, None]), E)
    skipped, margin = 0, []
    for p in range(2):
        ax = pul["axes"][p] / np.linalg.norm(pul["axes"][p])
        rn = surf - pul["centres"][p]
        gap = np.linalg.norm(rn - (rn @ ax)[..., None] * ax, axis=-1).min(axis=1) - pul["radii"][p]
        for e in range(E.shape[0]):
            one = {k: v[p:p + 1] for k, v in pul.items()}
            pair = _forces(E[e:e + 1], V[e:e + 1], S0[e:e + 1], w[e:e + 1], one, omegas[p:p + 1],
                           prm, want_J=False)
            if pair["pairs"] == 0:
                skipped += 1
                margin.append(gap[e] / max(a[e], b[e]))
    assert skipped > 0 and min(margin) > 0, (skipped, min(margin))
    assert min(margin) < 0.05  # some skipped elements graze the pulley
    # all pairs at once against the unbounded per-point state
    out = _forces(E, V, S0, w, pul, omegas, prm, want_J=False)
    r, _, Fn, ft, _, _ = _state(E, V, S0, pul, omegas, prm)
    ax = pul["axes"] / np.linalg.norm(pul["axes"], axis=-1, keepdims=True)
    rn = r[:, :, None, :] - pul["centres"]
    N = rn - np.sum(rn * ax, axis=-1, keepdims=True) * ax
    n = N / np.linalg.norm(N, axis=-1, keepdims=True)
    f = Fn[..., None] * n + ft
    Q = np.einsum("eq,eqk,eqpd->ekd", w, S0, f).reshape(out["Q"].shape)
    T = -np.einsum("eq,eqpd->p", w, np.cross(rn, f) * ax[None, None])
    assert np.sum(Fn > 0) > 0 and out["pairs"] == E.shape[0] * 2 - skipped
    np.testing.assert_allclose(out["Q"], Q, rtol=0, atol=1e-12 * np.abs(Q).max())
    np.testing.assert_allclose(out["T"], T, rtol=1e-11)
    shift = np.zeros(E.shape[1:])
    shift[POS, 0] = 10 * pul["radii"].max()  # positions only, the slopes stay
    far = _forces(E + shift, V, S0, w, pul, omegas, prm, want_J=False)
    assert far["pairs"] == 0 and not far["Q"].any()
