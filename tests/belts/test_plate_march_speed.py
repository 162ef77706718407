"""The plate belt's march (issue 36 item 5): the contact kernel's culling changes no
force and no derivative, and a step on the iteration matrix kept from earlier steps
(modified Newton) ends where one on a fresh matrix at every iteration does, within the
Newton tolerance.

Tolerances.  Culling: a skipped pair or point has no force, so the sums differ only in
their grouping (points are buffered BATCH at a time): RULE ulps (the points per
element) of the largest entry of each output.  Newton: a step is converged when beta' |d|_inf <= tol (1 + |z_n|_inf)
(ancf.solvers.alpha_march) with the increments contracting by at most REFRESH_RATIO =
1/2, so the accepted iterate lies within beta' |d| / (1 - 1/2) <= 2 tol (1 + |z_n|_inf)
of the step's solution in the positions; two iterations each so close lie within twice
that.
"""
from dataclasses import replace

import numpy as np
import pytest

from ancf.belts.contact3d import contact_forces3d, contact_state3d
from ancf.belts.drive3d import Belt3DDrive
from ancf.belts.dynamics import BeltOptions, _March
from ancf.belts.pretension import settle
from ancf.scenes import belt3d as b3
from ancf.solvers.alpha_march import DONE, REFRESH_RATIO

EPS = np.finfo(np.float64).eps
NEL, RULE = 12, 25   # plates and contact points of the small Model 2 belt
DEEPER = 2e-4        # m: pulleys grown by this much press into the laid belt's wrap
OUT = ("Q", "Kq", "Cv", "Qw", "T", "dTq", "dTv", "dTw")
STEPS = 150          # steps of the running belt before the step compared
DT = 1e-4            # s, the belt3d scene's step
#: the system's arrays that hold the kept factors of the bordered iteration matrix
FACTORS = ("S", "piv", "U", "row", "col", "corner", "schur", "spiv")


def _drive(**changes):
    p = b3.SCENE.resolve({"n_elements": NEL, "contact_points": RULE})
    return Belt3DDrive(replace(b3.spec(p), **changes))


def _contact(drive, E, V, radii, omegas, cull):
    nel, npul = E.shape[0], radii.size
    out = dict(Q=np.zeros((nel, 36)), Kq=np.zeros((nel, 36, 36)), Cv=np.zeros((nel, 36, 36)),
               Qw=np.zeros((nel, npul, 36)), T=np.zeros(npul), dTq=np.zeros((npul, nel, 36)),
               dTv=np.zeros((npul, nel, 36)), dTw=np.zeros(npul))
    centres, axes = drive.centres, drive.axes
    pairs = contact_forces3d(E, V, drive.S0, drive.w, centres, axes, radii, omegas,
                             np.zeros((npul, 3)), drive.prm, True, *(out[k] for k in OUT),
                             cull)
    return pairs, out


def test_culling_gives_the_forces_and_jacobians_of_every_point():
    drive = _drive()
    E = drive.element_coords(drive.q0)
    V = np.random.default_rng(36).uniform(-0.5, 0.5, E.shape)
    radii, omegas = drive.radii + DEEPER, np.array([40.0, -25.0])
    culled, a = _contact(drive, E, V, radii, omegas, True)
    every, b = _contact(drive, E, V, radii, omegas, False)
    _, d, Fn, _, _, _ = contact_state3d(E, V, drive.S0, drive.centres, drive.axes, radii, omegas,
                                        np.zeros((2, 3)), drive.prm)
    assert every == NEL * 2 and 0 < culled < every  # pairs skipped ...
    assert (Fn > 0).any() and (d < 0).any()          # ... and points out of contact
    for k in OUT:
        assert np.abs(b[k]).max() > 0, k
        np.testing.assert_allclose(a[k], b[k], rtol=0, atol=RULE * EPS * np.abs(b[k]).max(),
                                   err_msg=k)


@pytest.fixture(scope="module")
def running():
    """A small Model 2 belt whose driver spins up from 1 ms to 20 ms, marched 150 steps (to
    15 ms): the march (its kept factors) and the state it reached."""
    drive = _drive(t0=1e-3, t1=0.02, omega_final=100.0)
    x0, pre = settle(drive)
    assert pre.converged
    opt = BeltOptions(dt=DT)
    ts = np.arange(STEPS + 2) * DT
    m = _March(drive, opt, ts, 1)
    a0 = m.initial_acceleration(x0, np.zeros_like(x0))
    st = (x0.copy(), np.zeros_like(x0), a0, a0.copy())
    out = np.zeros((1, x0.size))
    status, k = m.run(st, 0, STEPS, np.full(ts.size, -1), out, out, np.inf)
    assert status == DONE and k == STEPS
    return drive, m, st


def _one_step(m, st, ratio, fresh):
    """The next step from st (copied), the matrix refreshed when the increments contract
    by less than ``ratio``, its factors made anew at the step's start if ``fresh`` (else
    the march's kept ones); the step's end positions, its Newton iterations and the
    matrices it formed."""
    s = tuple(v.copy() for v in st)
    kept = {k: getattr(m.system, k).copy() for k in FACTORS}
    hf, opt = m.hf.copy(), m.opt
    if fresh:
        m.hf[0] = np.nan
    m.opt = replace(opt, refresh_ratio=ratio)
    before = m.count.copy()
    out = np.zeros((1, s[0].size))
    status, _ = m.run(s, STEPS, STEPS + 1, np.full(m.ts.size, -1), out, out, np.inf)
    done = m.count - before
    for k in FACTORS:
        getattr(m.system, k)[...] = kept[k]
    m.hf[:], m.opt = hf, opt
    assert status == DONE
    return s[0], done[3], done[1]


def test_kept_factors_end_the_step_at_the_newton_solution(running):
    drive, m, st = running
    assert abs(st[1][-1]) > 1.0  # the driven pulley turns
    x_kept, it_kept, mats_kept = _one_step(m, st, REFRESH_RATIO, False)
    x_fresh, it_fresh, mats_fresh = _one_step(m, st, 1e-9, True)
    # the kept step starts on the kept factors; the fresh one forms a matrix at its start
    # and after every increment but the first (nothing to compare that one with)
    assert mats_kept < it_kept and mats_fresh == it_fresh - 1
    bound = 4 * m.opt.newton_tol * (1 + np.abs(st[0][: drive.n]).max())
    assert np.abs(x_kept - st[0]).max() > 1e3 * bound  # the step moves the belt
    assert not np.array_equal(x_kept, x_fresh)
    assert np.abs(x_kept - x_fresh).max() <= bound
