"""Why the plate belt's march cannot take longer steps: Newton's iterations of one
step, from a running state of the belt3d scene (Model 2), at several step sizes.

    python -m benchmarks.belt3d_newton [--t 0.6] [--steps 3] [--out reports/benchmarks]

From the state at ``--t`` (a run of the scene to that time), each step size h takes
``--steps`` steps of the generalised-alpha recurrence (:mod:`ancf.solvers.alpha_march`)
by full Newton: the exact iteration matrix evaluated and factored at every iterate, the
increment applied undamped, at most :data:`MAX_ITER` iterations; the march's own test
beta' |d|_inf <= tol (1 + |z|_inf) (tol: the scene's 1e-7) says when a step has
converged.  It prints |r| and beta' |d|_inf per iteration and the contact points that
changed branch (out, clamped, linear, saturated: :func:`ancf.belts.contact3d.
contact_state3d`) since the iterate before.  Also: the iteration matrix against central
differences of the residual along random directions of the belt's and of the pulley's
coordinates (the matrix is exact if the difference falls with the step).

Writes ``belt3d_newton.json`` (keys ``schema``, ``started``, ``command``, ``machine``,
``settings``, ``t``, ``tol``,
``fd_check`` (per block, step: relative difference), ``steps``: per h a list of steps,
each a list of iterations {``r``, ``bp_d``, ``switched``} and ``converged``) and
``belt3d_newton.md``.
"""
from __future__ import annotations

import argparse
from pathlib import Path

import numpy as np
from numba import njit

from ancf.belts.contact3d import contact_state3d
from ancf.belts.dynamics import BeltOptions, _March
from ancf.belts.forces import gather, moved_centres
from ancf.common.dispatch import as_struct
from ancf.solvers import banded
from ancf.solvers.alpha_march import _evaluate
from benchmarks import peers

STEPS_H = (1e-4, 2e-4, 5e-4)  # s: the scene's step, twice and five times it
MAX_ITER = 12


@njit(cache=True)
def _residual(system, acc1, st, h, k, cf, bp, gp, want_J, count, r, x1, v1, a1):
    """The march's residual (and iteration matrix's force part if want_J) at acc1."""
    _evaluate(as_struct(system), acc1, st, h, k, cf, bp, gp, want_J, count, r, True, x1, v1,
              a1)


class OneStep:
    """The march's system at a state, its residual and its full Newton step."""

    def __init__(self, drive, x, v, t: float, h: float):
        self.drive, self.h = drive, h
        self.m = _March(drive, BeltOptions(dt=h), np.array([t, t + h]), 0)
        a0 = self.m.initial_acceleration(x, v)
        self.st = (x.copy(), v.copy(), a0, a0.copy())
        am, af, gamma, beta = self.m.cf
        self.bp = h * h * beta * (1 - af) / (1 - am)
        self.gp = h * gamma * (1 - af) / (1 - am)
        self.count = np.zeros(6, dtype=np.int64)
        self.m.system.drive.h[0] = h

    def residual(self, acc1, want_J=False):
        """(r, x1, v1) at acc1; with want_J the iteration matrix (band, border, corner)."""
        n = acc1.size
        r, x1, v1, a1 = np.zeros(n), np.empty(n), self.st[1].copy(), np.empty(n)
        _residual(self.m.system, acc1, self.st, self.h, 1, self.m.cf, self.bp, self.gp, want_J,
                  self.count, r, x1, v1, a1)
        return r, x1, v1, a1

    def matrix(self):
        """The iteration matrix of the last residual with want_J: a function d -> S d."""
        s, nb = self.m.system, self.drive.n
        S, col, row = s.S + s.Mb, s.col.copy(), s.row.copy()
        corner = np.diag(s.drive.inertia) + s.corner

        def times(d):
            return np.r_[banded.matvec(S, s.kl, d[:nb].copy()) + col.T @ d[nb:],
                         row @ d[:nb] + corner @ d[nb:]]
        return S, col, row, corner, times

    def newton_increment(self, r):
        """The bordered solve of S d = -r (band LU with pivoting, Schur complement)."""
        S, col, row, corner, _ = self.matrix()
        s, nb = self.m.system, self.drive.n
        B, piv = S.copy(), np.zeros(nb, dtype=np.int64)
        banded.lu(B, s.kl, piv, True)
        U = np.array([banded_solve(B, s.kl, piv, c) for c in col])
        y = banded_solve(B, s.kl, piv, -r[:nb])
        th = np.linalg.solve(corner - row @ U.T, -r[nb:] - row @ y)
        return np.r_[y - U.T @ th, th]

    def accept(self, acc1):
        x1, v1, a1 = self.residual(acc1)[1:]
        x, v, acc, a = self.st
        x[:], v[:], acc[:], a[:] = x1, v1, acc1, a1


def banded_solve(B, kl, piv, b):
    out = np.array(b, dtype=float)
    banded.solve(B, kl, piv, out)
    return out


def branches(one: OneStep, x1, v1) -> np.ndarray:
    """Every contact point's branch (nel, nq, np) at (x1, v1), the step's end time."""
    d, t1 = one.drive, one.m.ts[1]
    E, V = np.empty((d.spec.n_elements, 12, 3)), np.empty((d.spec.n_elements, 12, 3))
    gather(x1, d.vidx, E, V, v1)
    o, odot = moved_centres(one.m.system.drive, one.m.system.tabs[:, 1])
    return contact_state3d(E, V, d.S0, o, d.axes, d.radii, d.omegas(t1, v1), odot, d.prm)[5]


def fd_check(one: OneStep, seed: int = 0) -> dict:
    """Relative difference |S d - (r(acc + e d) - r(acc - e d)) / 2e| / |...| per block of
    directions d (the belt's coordinates, the pulleys') and step e (a fraction of the
    largest acceleration of the block)."""
    acc = one.st[2].copy()
    one.residual(acc, want_J=True)
    times = one.matrix()[4]
    nb, rng, out = one.drive.n, np.random.default_rng(seed), {}
    for name, sl in (("belt", slice(0, nb)), ("pulleys", slice(nb, None))):
        d = np.zeros(acc.size)
        d[sl] = rng.standard_normal(d[sl].size)
        scale = np.abs(acc[sl]).max() + 1.0
        row = {}
        for frac in (1e-4, 1e-6, 1e-8):
            e = frac * scale
            fd = (one.residual(acc + e * d)[0] - one.residual(acc - e * d)[0]) / (2 * e)
            row[f"{frac:g}"] = float(np.linalg.norm(times(d) - fd) / np.linalg.norm(fd))
        out[name] = row
    return out


def newton_steps(drive, x, v, t: float, h: float, nsteps: int, tol: float) -> list:
    """``nsteps`` steps of full Newton from (x, v) at t (module docstring)."""
    one, steps = OneStep(drive, x, v, t, h), []
    m = drive.n
    for _ in range(nsteps):
        acc1, its, prev, ok = one.st[2].copy(), [], None, False
        scale = tol * (1 + np.max(np.abs(one.st[0][:m])))
        for _ in range(MAX_ITER):
            r, x1, v1, _ = one.residual(acc1, want_J=True)
            br = branches(one, x1, v1)
            d = one.newton_increment(r)
            bpd = float(one.bp * np.max(np.abs(d[:m])))
            its.append({"r": float(np.linalg.norm(r)), "bp_d": bpd,
                        "switched": 0 if prev is None else int(np.sum(br != prev))})
            prev = br
            acc1 = acc1 + d
            if bpd <= scale:
                ok = True
                break
        steps.append({"iterations": its, "converged": ok})
        if not ok:
            break
        one.accept(acc1)
        t += h
        one = OneStep(drive, *one.st[:2], t, h)
    return steps


def _table(res: dict) -> str:
    lines = ["| h (s) | step | iterations | converged | residual norm per iteration | contact points switched per iteration |",
             "|---|---|---|---|---|---|"]
    for h, steps in res["steps"].items():
        for i, s in enumerate(steps):
            its = s["iterations"]
            lines.append(f"| {h} | {i + 1} | {len(its)} | {s['converged']} | "
                         + ", ".join(f"{it['r']:.1e}" for it in its) + " | "
                         + ", ".join(str(it["switched"]) for it in its[1:]) + " |")
    fd = "; ".join(f"{k}: " + ", ".join(f"e = {e} of the largest: {v:.1e}" for e, v in row.items())
                   for k, row in res["fd_check"].items())
    return (f"# The plate belt's Newton iteration at several steps\n\nGenerated by "
            f"`python -m benchmarks.belt3d_newton` on {res['started']} ({res['machine']['cpu_model']}). "
            f"From the belt3d scene's Model 2 state at t = {res['t']} s, full Newton (exact "
            f"matrix at every iterate, undamped), the march's test beta' |d| <= "
            f"{res['tol']:g} (1 + |z|).\n\nIteration matrix against central differences "
            f"(relative, by the step e): {fd}.\n\n" + "\n".join(lines) + "\n")


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--t", type=float, default=0.6)
    ap.add_argument("--steps", type=int, default=3)
    ap.add_argument("--out", default=str(peers.ROOT / "reports" / "benchmarks"))
    a = ap.parse_args(argv)
    from ancf.scenes import SCENES
    p = {"model": 2, "t_end": a.t}
    out, res = SCENES["belt3d"].execute(p)
    run, drive = res.extra["result"], res.extra["drive"]
    tol = float(out["params"]["newton_tol"])
    x, v = run.q[-1].copy(), run.v[-1].copy()
    result = peers.record("belt3d_newton", argv or [], {"model": 2, "newton_tol": tol},
                          t=a.t, tol=tol)
    result["fd_check"] = fd_check(OneStep(drive, x, v, a.t, STEPS_H[0]))
    result["steps"] = {f"{h:g}": newton_steps(drive, x, v, a.t, h, a.steps, tol)
                       for h in STEPS_H}
    peers.write(Path(a.out), "belt3d_newton", result, _table(result))
    print(_table(result))
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
