"""The belt's strain-rate damping (issue 21 item 1): the Dufva element's damping forces
Q_d = int (dEA eps' deps/de + dEI kappa' dkappa/de) dx (ancf.elements.dufva2d.damping_forces)
against Exudyn's ANCFCable2D definition evaluated independently here, their exact
Jacobians against central differences, the drive's iteration matrix with damping on,
and a ring's breathing oscillation decaying at the rate the damping predicts."""
from __future__ import annotations

import numpy as np
import pytest

from ancf.belts.drive2d import Belt2DSpec, BeltDrive, Rig
from ancf.belts.drive_file import load
from ancf.belts.drive_model import build
from ancf.belts.dynamics import BeltOptions, simulate
from ancf.belts.forces import evaluate_record
from ancf.belts.friction import LAW
from ancf.common.paths import REPO
from ancf.core.mesh import BeamMesh
from ancf.core.quadrature import RectangularSection, gauss01
from ancf.elements import _generated as shape_gen
from ancf.elements.dufva2d import (DufvaBelt2D, damping_forces, damping_parts,
                                   gradient_tangent, gradient_tangent_damped,
                                   measures_damping)

EXAMPLES = REPO / "examples"
SECTION = RectangularSection(0.02, 0.005)
ITILDE = np.array([[0.0, -1.0], [1.0, 0.0]])


def _element(n=3, L=0.6, nx=5):
    m = BeamMesh(L, n, DufvaBelt2D.slots)
    q0 = m.reference()
    return m, q0, DufvaBelt2D(m.lengths, q0[m.dofmap], SECTION, E=2e8, nu=0.3, rho=1200.0,
                              alpha2=0.02, nx=nx)


def _state(m, q0, rng, shear_free=False):
    """A large deformation E and a velocity V (nel, 6, 2): coordinates moved by ~0.05,
    velocities ~1; with ``shear_free`` every node's r_y = I~ r_x/|r_x| and its rate the
    rate of that (sin gamma = 0 and d sin gamma/dt = 0 at the nodes)."""
    q = q0 + 0.05 * rng.standard_normal(q0.size)
    v = rng.standard_normal(q0.size)
    if shear_free:
        Q, W = q.reshape(-1, 3, 2), v.reshape(-1, 3, 2)
        for k in range(Q.shape[0]):
            rx, vx = Q[k, 1], W[k, 1]
            n = np.linalg.norm(rx)
            Q[k, 2] = ITILDE @ rx / n
            W[k, 2] = ITILDE @ (vx - rx * (rx @ vx) / n**2) / n
    E = np.ascontiguousarray(q[m.dofmap].reshape(-1, 6, 2))
    V = np.ascontiguousarray(v[m.dofmap].reshape(-1, 6, 2))
    return E, V


def _forces(el, E, V, d, want_J=False):
    nel = E.shape[0]
    g = np.zeros((nel, 12))
    K, C = (np.zeros((nel, 12, 12)), np.zeros((nel, 12, 12))) if want_J else (None, None)
    damping_forces(E, V, el.kernel_data(), np.array(d, dtype=float), want_J, g,
                   K if want_J else np.zeros((0, 0, 0)), C if want_J else np.zeros((0, 0, 0)))
    return g, K, C


def _exudyn(el, E, V, dEA, dEI, nx=5):
    """Exudyn's ANCFCable2D damping forces (CObjectANCFCable2D.cpp, ComputeODE2LHS):
    axialForce = dEA (r_x . r_x')/|r_x| times d|r_x|/de, bendingMoment = dEI kappa'
    times dkappa/de with kappa = (r_x x r_xx)/|r_x|^2, on the position and slope r_x
    coordinates of our element (numpy, the same Gauss points); (nel, 12) with the r_y
    entries zero (the cable has none)."""
    xi, wx = gauss01(nx)
    out = np.zeros((E.shape[0], 12))
    cross = lambda u, w: u[0] * w[1] - u[1] * w[0]  # noqa: E731
    for e, le in enumerate(el.lengths):
        for z, w in zip(xi, wx):
            X = np.array([z * le])
            Sx = el.shapes["x"](X, 0.0 * X, le)[0]
            Sxx = shape_gen.cubic2d_xx(X, 0.0 * X, le)[0]
            Sx[[2, 5]] = Sxx[[2, 5]] = 0.0  # the r_y shape functions are not the cable's
            rx, rxx, vx, vxx = Sx @ E[e], Sxx @ E[e], Sx @ V[e], Sxx @ V[e]
            g, f = rx @ rx, cross(rx, rxx)
            eps_t = rx @ vx / np.sqrt(g)
            kap_t = ((cross(vx, rxx) + cross(rx, vxx)) * g - f * 2 * (rx @ vx)) / g**2
            deps = np.outer(Sx, rx / np.sqrt(g))
            df = np.outer(Sx, [rxx[1], -rxx[0]]) + np.outer(Sxx, [-rx[1], rx[0]])
            dkap = (df * g - f * 2 * np.outer(Sx, rx)) / g**2
            out[e] += w * le * (dEA * eps_t * deps + dEI * kap_t * dkap).ravel()
    return out


@pytest.mark.slow
def test_axial_damping_is_exudyns():
    """Axial damping alone at a random large deformation and velocity: every coordinate's
    force equals Exudyn's formula evaluated independently (1e-12 of the largest; the
    cable's axial strain |r_x| - 1 is ours)."""
    m, q0, el = _element()
    E, V = _state(m, q0, np.random.default_rng(1))
    ours = _forces(el, E, V, (1.0, 0.0))[0]
    theirs = _exudyn(el, E, V, 1.0, 0.0)
    assert np.abs(ours - theirs).max() <= 1e-12 * np.abs(theirs).max()


def test_bending_damping_is_exudyns_without_shear():
    """Bending damping alone on a shear-free state (sin gamma = 0 at the nodes and not
    changing): kappa = (r_x x r_xx)/|r_x|^2, so the forces on the positions r equal
    Exudyn's (1e-12 of the largest); on the slopes ours has the shear sine's part."""
    m, q0, el = _element()
    E, V = _state(m, q0, np.random.default_rng(2), shear_free=True)
    ours = _forces(el, E, V, (0.0, 1e-3))[0]
    theirs = _exudyn(el, E, V, 0.0, 1e-3)
    r = [0, 1, 6, 7]
    assert np.abs(ours[:, r]).max() > 0
    assert np.abs(ours[:, r] - theirs[:, r]).max() <= 1e-12 * np.abs(theirs[:, r]).max()


def test_uniform_stretch_rate_pulls_the_ends_with_dea_times_rate():
    """A straight bar stretched at the uniform rate lambda' (r = lambda x, r' = lambda' x):
    eps' = lambda', so the assembled damping force is -dEA lambda' at the first node's x
    and +dEA lambda' at the last's, zero elsewhere (1e-12 dEA lambda')."""
    m, q0, el = _element(n=4, L=0.8)
    lam, rate, dEA = 1.03, 0.7, 2.5
    Q = q0.reshape(-1, 3, 2).copy()
    W = np.zeros_like(Q)
    Q[:, 0, 0] *= lam
    Q[:, 1, 0] = lam
    W[:, 0, 0] = rate * q0.reshape(-1, 3, 2)[:, 0, 0]
    W[:, 1, 0] = rate
    E = np.ascontiguousarray(Q.ravel()[m.dofmap].reshape(-1, 6, 2))
    V = np.ascontiguousarray(W.ravel()[m.dofmap].reshape(-1, 6, 2))
    g = _forces(el, E, V, (dEA, 0.0))[0]
    out = np.zeros(m.n_dofs)
    np.add.at(out, m.dofmap, g)
    ref = np.zeros(m.n_dofs)
    ref[m.dof(0, "r", 0)], ref[m.dof(m.n_nodes - 1, "r", 0)] = -dEA * rate, dEA * rate
    assert np.abs(out - ref).max() <= 1e-12 * dEA * rate


@pytest.mark.parametrize("d", [(1.0, 0.0), (0.0, 1e-3), (1.0, 1e-3)])
def test_damping_jacobians_match_central_differences(d):
    """dQ_d/de and dQ_d/de' against central differences (h = 1e-6) at a random large
    deformation and velocity: within 1e-7 of the largest entry (the differences' error);
    dQ_d/de' is also exact: Q_d = (dQ_d/de') e'."""
    m, q0, el = _element()
    E, V = _state(m, q0, np.random.default_rng(3))
    g, K, C = _forces(el, E, V, d, True)
    h = 1e-6
    for by, J in (("E", K), ("V", C)):
        FD = np.zeros_like(J)
        for b in range(12):
            plus, minus = (E.copy(), V.copy()), (E.copy(), V.copy())
            i = by == "V"
            plus[i][:, b // 2, b % 2] += h
            minus[i][:, b // 2, b % 2] -= h
            FD[:, :, b] = (_forces(el, *plus, d)[0] - _forces(el, *minus, d)[0]) / (2 * h)
        assert np.abs(FD - J).max() <= 1e-7 * np.abs(J).max(), by
    CV = np.einsum("eab,eb->ea", C, V.reshape(-1, 12))
    assert np.abs(CV - g).max() <= 1e-12 * np.abs(g).max()


@pytest.mark.parametrize("axial", ["green", "engineering"])
def test_axial_damping_loops_are_the_general_kernels_bit_for_bit(axial):
    """An axial damping alone (dEI = 0) goes by the axial strain's own loops: its forces,
    dQ_d/de and dQ_d/de' (damping_parts) and those with the elastic forces in one pass
    (gradient_tangent_damped) are, sum for sum, the general kernel's (measures_damping,
    through the point Jacobians) after the elastic kernel's, for every choice of the
    Jacobians asked for."""
    m, q0, el = _element(n=4)
    el = DufvaBelt2D(m.lengths, q0[m.dofmap], SECTION, E=2e8, nu=0.3, rho=1200.0,
                     alpha2=0.02, nx=5, axial=axial)
    E, V = _state(m, q0, np.random.default_rng(5))
    data, d = el.kernel_data(), np.array([0.7, 0.0])
    for want_K, want_Kd, want_C in [(True, True, True), (False, True, True),
                                    (True, False, True), (False, False, False)]:
        out = [[np.zeros((4, 12)), np.zeros((4, 12, 12)), np.zeros((4, 12, 12))]
               for _ in range(3)]
        for i, damping in enumerate((measures_damping, damping_parts)):
            gradient_tangent(E, data, want_K, out[i][0], out[i][1])
            damping(E, V, data, d, want_Kd, want_C, *out[i])
        gradient_tangent_damped(E, V, data, d[0], want_K, want_Kd, want_C, *out[2])
        assert np.abs(out[0][1]).max() > 0 or not (want_K or want_Kd)
        for ours in out[1:]:
            for a, b in zip(ours, out[0]):
                assert a.tobytes() == b.tobytes(), (want_K, want_Kd, want_C)


def test_zero_damping_adds_nothing():
    m, q0, el = _element()
    g, K, C = _forces(el, *_state(m, q0, np.random.default_rng(4)), (0.0, 0.0), True)
    assert not g.any() and not K.any() and not C.any()


# ------------------------------------------------------------ a ring's breathing mode
class _Circle:
    """A circular belt path of radius R (m) about the origin (laid_belt's interface)."""

    def __init__(self, R):
        self.R, self.length = R, 2 * np.pi * R

    def __call__(self, s):
        ang = np.atleast_1d(s) / self.R
        return (self.R * np.stack([np.cos(ang), np.sin(ang)], -1),
                np.stack([-np.sin(ang), np.cos(ang)], -1))


def _ring(dEA, R0=0.1, strain=1e-3, n=24):
    """A free belt ring of stress-free radius R0 (m) laid at R0 (1 + strain) and let go:
    no pulley within reach (one far away, fixed), EA = 2e4 N, rho A = 0.12 kg/m, bending
    lowered (alpha2 = 1e-4)."""
    spec = Belt2DSpec(path=_Circle(R0 * (1 + strain)), belt_length=2 * np.pi * R0, n_elements=n,
                      E=2e8, nu=0.3, rho=1200.0, b=0.02, h=0.005, ks=5 / 6, alpha1=1.0,
                      alpha2=1e-4, nx=5, k_p=1e6, c_p=0.0, friction=(LAW, 0.0, 0.0),
                      gauss_points=5)
    rig = Rig(names=("far",), centres=np.array([[10.0, 10.0]]), radii=np.array([0.01]),
              free=np.array([-1]), inertia=np.zeros(0), damping=np.zeros(0),
              laws=(lambda t: np.zeros(np.shape(t)),))
    return BeltDrive(spec, rig, damping=(dEA, 0.0))


def _decay_rate(drive, periods=8.0, dt=1e-5):
    """(decay rate 1/s, period s) of the ring's mean radial speed: the log of its
    successive extreme values (parabola-refined) fitted against their times."""
    EA, rhoA, R0 = 2e4, 0.12, drive.spec.belt_length / (2 * np.pi)
    T = 2 * np.pi * R0 * np.sqrt(rhoA / EA)
    t = np.arange(0.0, periods * T, dt)
    res = simulate(drive, t, BeltOptions(dt=dt, rho_inf=1.0))
    assert res.converged, res.message
    q = np.array([drive.belt(x) for x in res.q]).reshape(t.size, -1, 3, 2)
    w = np.array([drive.belt(v) for v in res.v]).reshape(t.size, -1, 3, 2)
    r = q[:, :, 0]
    vr = np.mean(np.einsum("tnd,tnd->tn", r / np.linalg.norm(r, axis=-1, keepdims=True),
                           w[:, :, 0]), axis=1)
    a = np.abs(vr)
    k = np.flatnonzero((a[1:-1] > a[:-2]) & (a[1:-1] >= a[2:])) + 1
    y0, y1, y2 = np.log(a[k - 1]), np.log(a[k]), np.log(a[k + 1])
    shift = 0.5 * (y0 - y2) / (y0 - 2 * y1 + y2)
    tk, yk = t[k] + shift * dt, y1 - 0.25 * (y0 - y2) * shift
    slope = np.polyfit(tk, yk, 1)[0]
    return -slope, 2 * np.mean(np.diff(tk))


@pytest.mark.slow
def test_ring_breathing_decays_at_the_rate_of_the_damping():
    """A free ring (stress-free radius R0 = 0.1 m) let go 0.1 % stretched breathes
    radially: rho A u'' + dEA u'/R0^2 + EA u/R0^2 = 0 (eps = u/R0), so its mean radial
    speed decays at sigma = dEA/(2 rho A R0^2) with the period 2 pi R0 sqrt(rho A/EA)
    (here dEA = 0.2 N s: 83.33 1/s, 1.539 ms).  The march (rho_inf = 1: no algorithmic
    damping, dt = 1e-5 s, 24 elements) within 1 % of both (0.04 % seen); without the
    damping the decay is below 0.5 % of it (0.004 1/s seen)."""
    dEA, rhoA, EA, R0 = 0.2, 0.12, 2e4, 0.1
    sigma, period = _decay_rate(_ring(dEA))
    assert sigma == pytest.approx(dEA / (2 * rhoA * R0**2), rel=1e-2)
    assert period == pytest.approx(2 * np.pi * R0 * np.sqrt(rhoA / EA), rel=1e-2)
    assert abs(_decay_rate(_ring(0.0))[0]) < 5e-3 * dEA / (2 * rhoA * R0**2)


# ------------------------------------------------- the drive's residual and its matrix
def _drive_terms(drive, x, v, bp, gp):
    """The drive's residual and the force part of its iteration matrix (dense, n + k)."""
    n, k = drive.n, drive.k
    kd, laws = drive.kernel(), drive.laws(np.array([0.4]))[:, 0].copy()
    mat, col, row, corner = (drive.pattern.zeros_matrix(), np.zeros((k, n)), np.zeros((k, n)),
                             np.zeros((k, k)))
    r = np.zeros(n + k)
    evaluate_record(x, v, laws, kd, True, bp, gp, r, mat, col, row, corner)
    D = np.zeros((n + k, n + k))
    D[:n, :n] = drive.pattern.as_csr(mat).toarray()
    D[:n, n:], D[n:, :n], D[n:, n:] = col.T, row, corner
    return r, D


def _damping_part(on, off, x, v):
    """The damped drive's residual less the undamped one's."""
    return _drive_terms(on, x, v, 0.0, 0.0)[0] - _drive_terms(off, x, v, 0.0, 0.0)[0]


@pytest.mark.slow
@pytest.mark.parametrize("by", ["x", "v"])
def test_drive_matrix_takes_the_damping_exactly(by):
    """The serpentine drive at a perturbed moving state with dEA = 0.5 N s, dEI = 1e-3
    N m^2 s: the damping's part of the residual (damped less undamped drive, the contact
    terms cancelling exactly) and of the iteration matrix by coordinates (beta', gamma' =
    1, 0) and by velocities (0, 1) against central differences (h = 1e-7): within 1e-6
    of the largest entry."""
    d = load(EXAMPLES / "serpentine.toml", ["belt.damping_bending=1e-3"])
    on, off = build(d), build(load(EXAMPLES / "serpentine.toml", ["belt.damping_axial=0"]))
    n, k = on.n, on.k
    rng = np.random.default_rng(0)
    x = on.state(on.q0)
    x[:n] += 2e-4 * rng.normal(size=n)
    v = 0.3 * rng.normal(size=n + k)
    bp, gp = (1.0, 0.0) if by == "x" else (0.0, 1.0)
    (r1, D1), (r0, D0) = _drive_terms(on, x, v, bp, gp), _drive_terms(off, x, v, bp, gp)
    assert np.abs(r1 - r0).max() > 0
    FD = np.zeros_like(D1)
    h = 1e-7
    for c in range(n):
        plus, minus = (x.copy(), v.copy()), (x.copy(), v.copy())
        plus[by == "v"][c] += h
        minus[by == "v"][c] -= h
        FD[:, c] = (_damping_part(on, off, *plus) - _damping_part(on, off, *minus)) / (2 * h)
    J = D1 - D0
    assert np.abs(FD - J).max() <= 1e-6 * np.abs(J).max()
