"""The bristle friction law with its state carried per contact point (issue 21, item 2):
the planar contact kernel's exact Jacobians with a state against central differences; a
straight belt piece pressed onto a pulley and pushed along it, whose friction holds k_t z
while it sticks and mu F_n once it slides (computed here independently, point by point);
the state's accept/reject semantics in the compiled march; and the refusals where no state
is carried (3D drives, BDF)."""
from __future__ import annotations

import dataclasses
import re

import numpy as np
import pytest

from ancf.belts import friction
from ancf.belts.contact2d import contact_forces_moving, contact_points, contact_state
from ancf.belts.drive_file import load
from ancf.belts.drive_model import build
from ancf.belts.dynamics import BeltOptions, _March
from ancf.belts.system import accept_state
from ancf.common.paths import REPO
from ancf.solvers.alpha_march import DONE, NEWTON_FAILED

from test_contact import CASES, ROUND_MARGIN, _fd_state, _outputs

THREAD = REPO / "examples" / "thread_benchmark.toml"
KT, DT, MU = 4e8, 25749.6, 0.5          # THREAD's bristle per unit length (the example file)
STEP = 5e-5                              # s, THREAD's step
H, RTOL, EPS = 1e-6, 1e-6, np.finfo(float).eps


def _bristle(kp, cp, kt=KT, dt=DT, mu=MU):
    return friction.contact_record(kp, cp, "bristle", mu, kt, dt)


def _forces(E, V, S0, w, centres, radii, omegas, prm, z, h, want_J=True):
    out = _outputs(E.shape[0], radii.size)
    contact_forces_moving(E, V, S0, w, centres, np.zeros_like(centres), radii, omegas, prm, z,
                          h, want_J, *out.values())
    return out


def _labels(E, V, S0, centres, radii, omegas, prm, z0, h):
    """Per point and pulley: 0 out, 1 clamped, 2 stick, +-3 slip (the sign of the trial
    force w = k_t (z0 + h v_t) + d_t v_t), from contact_state's F_n and v_t."""
    _, d, Fn, _, vt = contact_state(E, V, S0, centres, radii, omegas, prm)
    c = KT * h + DT
    w = KT * z0 + c * vt
    return np.where(d < 0, 0, np.where(Fn <= 0, 1, np.where(np.abs(w) <= MU * Fn, 2,
                                                            3 * np.sign(w))))


@pytest.mark.parametrize("z_scale", [1e-7, 3e-6])
def test_kernel_jacobians_with_a_state_match_central_differences(z_scale):
    """Kq, Cv, Qw, dTq, dTv, dTw of contact_forces_moving with the bristle law, a random
    state z0 and the step h fixed, equal central differences of (Q, T) column by column
    (the contract of tests/belts/test_contact.py: RTOL of the column plus round-off); the
    states mix sticking and sliding points (small z0) or slide mostly (large z0)."""
    case = CASES["mixed-clamped"]
    E, V, S0, w, centres, radii, omegas, prm0 = _fd_state(case)
    prm = _bristle(prm0[0], prm0[1])
    nel, ng, npul = w.shape[0], w.shape[1], radii.size
    rng = np.random.default_rng(7)
    z = np.zeros((2, nel, ng, npul))
    z[0] = z_scale * rng.standard_normal((nel, ng, npul))
    base = _forces(E, V, S0, w, centres, radii, omegas, prm, z.copy(), STEP)
    labels = _labels(E, V, S0, centres, radii, omegas, prm, z[0], STEP)
    fd = _outputs(nel, npul)

    def diff(E1, V1, om1, E2, V2, om2):
        for args in ((E1, V1, om1), (E2, V2, om2)):
            lab = _labels(args[0], args[1], S0, centres, radii, args[2], prm, z[0], STEP)
            assert np.array_equal(lab, labels), "a kink within one step"
        a = _forces(E1, V1, S0, w, centres, radii, om1, prm, z.copy(), STEP, False)
        b = _forces(E2, V2, S0, w, centres, radii, om2, prm, z.copy(), STEP, False)
        return (a["Q"] - b["Q"]) / (2 * H), (a["T"] - b["T"]) / (2 * H)

    for e in range(nel):
        for j in range(12):
            k, c = divmod(j, 2)
            dE = np.zeros_like(E)
            dE[e, k, c] = H
            dQ, dT = diff(E + dE, V, omegas, E - dE, V, omegas)
            fd["Kq"][e, :, j], fd["dTq"][:, e, j] = dQ[e], dT
            dQ, dT = diff(E, V + dE, omegas, E, V - dE, omegas)
            fd["Cv"][e, :, j], fd["dTv"][:, e, j] = dQ[e], dT
    for p in range(npul):
        dw = np.zeros(npul)
        dw[p] = H
        dQ, dT = diff(E, V, omegas + dw, E, V, omegas - dw)
        fd["Qw"][:, p, :], fd["dTw"][p] = dQ, dT[p]
    sQ, sT = np.abs(base["Q"]).max(), np.abs(base["T"]).max()
    for name, scale in (("Kq", sQ), ("Cv", sQ), ("Qw", sQ), ("dTq", sT), ("dTv", sT),
                        ("dTw", sT)):
        got, want = base[name].reshape(-1, base[name].shape[-1]), fd[name].reshape(
            -1, fd[name].shape[-1])
        err = np.linalg.norm(got - want, axis=0)
        ref = np.linalg.norm(got, axis=0)
        assert np.all(err <= RTOL * ref + ROUND_MARGIN * EPS * scale / H), (name, err, ref)
    counts = {b: int(np.sum(labels == b)) for b in (2, 3, -3)}
    if z_scale < 1e-6:
        assert counts[2] > 0 and counts[3] + counts[-3] > 0, counts
    else:
        assert counts[3] > 0 and counts[-3] > 0, counts


# ------------------------------------------------------------------ stick, then slip
R_PULLEY, L_PIECE, PEN = 50.0, 0.02, 1e-5    # m: a flat-ish pulley, a short piece, pressed
KP = 3.2e8                                  # N/m^2
CANCEL = 64 * EPS * R_PULLEY / PEN          # round-off of the penetration, relative


def _piece(shift):
    """One straight element, centre shifted by ``shift`` (m) along x, lying horizontally
    PEN into the top of a pulley of radius R_PULLEY centred at the origin: E (1, 6, 2)."""
    y = R_PULLEY - PEN
    E = np.zeros((1, 6, 2))
    E[0, 0], E[0, 3] = (shift - L_PIECE / 2, y), (shift + L_PIECE / 2, y)
    E[0, 1] = E[0, 4] = (1.0, 0.0)
    E[0, 2] = E[0, 5] = (0.0, 1.0)
    return E


def _expected(xi, w, shift, vx, zpts):
    """Per contact point (at x = shift - L/2 + xi L: the straight cubic), independently:
    F_n = k_p d, n, t = I~ n, v_t = t . (vx, 0); the bristle's trial
    w = k_t (z + h v_t) + d_t v_t: stick f = -w, z + h v_t; else f = -mu F_n sign w,
    z = mu F_n sign w / k_t.  Returns the total force on the piece (2,), N, the new z,
    and the total normal force, N."""
    F, znew, Fn_total = np.zeros(2), np.zeros_like(zpts), 0.0
    for g, x in enumerate(shift - L_PIECE / 2 + xi * L_PIECE):
        r = np.array([x, R_PULLEY - PEN])
        rho = np.linalg.norm(r)
        n = r / rho
        t = np.array([-n[1], n[0]])
        Fn = KP * (R_PULLEY - rho)
        vt = t[0] * vx
        trial = KT * (zpts[g] + STEP * vt) + DT * vt
        if abs(trial) <= MU * Fn:
            f, znew[g] = -trial, zpts[g] + STEP * vt
        else:
            f, znew[g] = -MU * Fn * np.sign(trial), MU * Fn * np.sign(trial) / KT
        F += w[0, g] * (Fn * n + f * t)
        Fn_total += w[0, g] * Fn
    return F, znew, Fn_total


def test_a_pushed_piece_sticks_on_its_bristles_then_slides_at_mu_fn():
    """A straight piece pressed 10 um into a pulley (at rest) and pushed along x at
    2 mm/s: the kernel's force and state at every step equal the point-by-point
    computation above.  Pushed 2 um (20 steps of 50 us, below the slip distance
    mu F_n / k_t ~ 4 um) and held, the friction is the springs' k_t z over the piece,
    z = the 2 um it moved; pushed on to 18 um and held, it is mu F_n over the piece
    (the springs stay at the Coulomb limit)."""
    S0, w, xi = contact_points(np.array([L_PIECE]), 5)
    centres, radii, omegas = np.zeros((1, 2)), np.array([R_PULLEY]), np.zeros(1)
    prm = _bristle(KP, 0.0)
    z = np.zeros((2, 1, 5, 1))
    zref, shift, held = np.zeros(5), 0.0, []
    for vx, n in ((2e-3, 20), (0.0, 1), (2e-3, 160), (0.0, 1)):
        for _ in range(n):
            shift += STEP * vx
            E = _piece(shift)
            V = np.zeros_like(E)
            V[0, 0, 0] = V[0, 3, 0] = vx
            out = _forces(E, V, S0, w, centres, radii, omegas, prm, z, STEP, False)
            Q = out["Q"][0]
            F = np.array([Q[0] + Q[6], Q[1] + Q[7]])  # the position shape functions sum to 1
            Fref, zref, Fn_total = _expected(xi, w, shift, vx, zref)
            # d = R - |r - o| cancels: eps R / PEN ~ 1e-9 relative in F_n and in the slip
            np.testing.assert_allclose(F, Fref, rtol=0, atol=CANCEL * abs(Fref[1]))
            np.testing.assert_allclose(z[1, 0, :, 0], zref, rtol=CANCEL, atol=1e-22)
            accept_state(prm, z, np.array([STEP]), np.zeros((0, 1, 5, 1)), np.zeros(0), -1)
        held.append((F[0], Fn_total, z[0, 0, :, 0].copy()))
    (stick, _, z_stick), (slid, Fn_slid, z_slid) = held[1], held[3]
    moved = 20 * STEP * 2e-3
    assert np.all(KT * moved < MU * KP * (R_PULLEY - np.hypot(L_PIECE / 2, R_PULLEY - PEN)))
    # v_t = t . v = -vx cos(x / R): the pulley's tangent turns by x / R < 2e-4 on the piece
    np.testing.assert_allclose(z_stick, -moved, rtol=(L_PIECE / R_PULLEY) ** 2)
    assert stick == pytest.approx(-KT * moved * L_PIECE, rel=1e-6)
    assert slid == pytest.approx(-MU * Fn_slid, rel=1e-5)
    assert np.all(np.abs(z_slid) < 18e-6 / 3)  # slid: far less than it moved


# ------------------------------------------------------------------ accept and reject
def _thread_march(max_iter):
    d = load(THREAD, ["belt.damping_axial=0"])
    drive = build(d)
    ts = np.linspace(0.0, 2 * STEP, 3)
    m = _March(drive, BeltOptions(dt=STEP, max_iter=max_iter), ts, 3)
    return drive, m, ts


@pytest.mark.slow
def test_the_state_is_accepted_on_converged_steps_only():
    """The THREAD drive at its laid state, belt creeping along its path at 1 mm/s over a
    resting driver, its bristles bent 1-1.5 um (k_t z < mu F_n: sticking): a step whose Newton iteration fails (max_iter = 1) writes trial
    states but leaves z0 as it was; a converged step makes the trial the state and keeps
    the state it started from, and the step, in the output slot (the step's friction at
    that sample's state: the driven pulley's moment from it equals the step's)."""
    drive, m, ts = _thread_march(1)
    x = drive.state(drive.q0)
    n1 = drive.n + drive.k
    v = np.zeros(n1)
    slopes = drive.q0.reshape(-1, 3, 2)[:, 1]  # r_x: along the belt
    qd = np.zeros_like(drive.q0).reshape(-1, 3, 2)
    qd[:, 0] = 1e-3 * slopes / np.linalg.norm(slopes, axis=1)[:, None]
    v[: drive.n] = drive.pattern.restrict(qd.ravel())
    z0 = 1e-6 * (1 + 0.5 * np.random.default_rng(3).random(drive.z.shape[1:]))
    drive.z[0] = z0
    a = m.initial_acceleration(x, v)
    st = (x.copy(), v.copy(), a, a.copy())
    slot = np.array([-1, 1, 2])
    X, V = np.zeros((3, n1)), np.zeros((3, n1))
    m.opt = dataclasses.replace(m.opt, newton_tol=1e-14)
    status, k = m.run(st, 0, 1, slot, X, V, 1e9)
    assert status == NEWTON_FAILED and k == 0
    assert np.array_equal(drive.z[0], z0) and not np.array_equal(drive.z[1], z0)
    assert not m.system.zs.any()
    m.opt = BeltOptions(dt=STEP)
    status, k = m.run(st, 0, 1, slot, X, V, 1e9)
    assert status == DONE and k == 1
    assert np.array_equal(drive.z[0], drive.z[1]) and not np.array_equal(drive.z[0], z0)
    assert np.array_equal(m.system.zs[1], z0) and m.system.hs[1] == STEP
    assert np.abs(drive.z[0]).max() > 0
    from ancf.scenes.belt_drive import pulley_moments
    j = drive.n + drive.rig.free[1]  # the driven pulley: I theta'' = T_c - T_a - c theta'
    T = pulley_moments(drive, X[1], V[1], ts[1], (m.system.zs[1], m.system.hs[1]))[1]
    balance = drive.rig.inertia[0] * st[2][j] + drive.rig.damping[0] * V[1][j] + \
        drive.laws(ts[1:2])[1, 0]
    assert abs(T) > 1.0 and T == pytest.approx(balance, rel=1e-5)


# ------------------------------------------------------------------ where no state is carried
def test_bdf_refuses_a_law_with_a_state():
    """The plate belt carries the bristle state now (tests/belts/test_belt3d_bristle.py,
    refused only with a tensioner arm there); the BDF cross-check does not."""
    from ancf.belts.bdf import _FirstOrder
    with pytest.raises(ValueError, match="generalised-alpha march only"):
        _FirstOrder(build(load(THREAD, ["belt.damping_axial=0"])))


def test_every_planar_drive_compiles_one_march(tmp_path):
    """THREAD's bristle drive, the thesis drive (creep-rate), a Coulomb variant of it and the
    serpentine (a tensioner arm) reach the compiled march as one numba type (the law chosen
    at run time by the contact record), so the march compiles once for all (38 CPU-s cold
    for the stateless laws' second type before); a stateless drive's state is empty."""
    import numba
    thesis = REPO / "examples" / "thesis_table_3_1.toml"
    coulomb = tmp_path / "coulomb.toml"
    coulomb.write_text(re.sub(r"\[friction\][^\[]*",
                              "[friction]\nlaw = 'coulomb'\nmu = 0.3\nv_reg = 0.01\n\n",
                              thesis.read_text()))
    files = [THREAD, thesis, coulomb, REPO / "examples" / "serpentine.toml"]
    kernels = [build(load(f)).kernel() for f in files]
    assert len({numba.typeof(k) for k in kernels}) == 1
    assert friction.has_state(kernels[0].prm) and kernels[0].z.size
    assert all(k.z.size == 0 and not friction.has_state(k.prm) for k in kernels[1:])
    assert kernels[2].prm.law == friction.CODES["coulomb"]
