"""Would a Newton predictor that follows the belt cut the plate march's iterations?
(issue 36's "a better Newton predictor"; the floor of :mod:`benchmarks.belt3d_floor`
counts residual evaluations.)

    python -m benchmarks.belt3d_predictor [--steps 40] [--out reports/benchmarks]

From states of the belt3d scene's Model 2 run at :data:`STARTS`, ``--steps`` steps of
damped full Newton on the march's residual (:class:`benchmarks.belt3d_newton.OneStep`):
the exact iteration matrix at every iterate, each increment shortened as the march's
backtracking does (lengths 1, 1/2, ... 1/128 until |r| falls by the factor
1 - 1e-4 lam), converged when beta' lam |d|_inf <= tol (1 + |z|_inf).  Each step is solved
from two predictors of its acceleration:

* ``last step``: the last step's acceleration (the march's predictor);
* ``shifted``: the belt's acceleration field moved along the belt by one step's travel.
  In a steady running belt q(X, t + h) = q(X + c h, t), with c = rdot . r_x / |r_x|^2
  the material speed (m of reference length per s, the mean over the nodes), so every
  node's (r, r_x, r_y) acceleration is the field's at X + c h, evaluated with the plate's
  shape functions in the node's element.

Both solve to the same acceleration (their difference is reported); the trajectory
follows the first.  Writes ``belt3d_predictor.json`` (keys ``schema``, ``started``,
``command``, ``machine``, ``settings``, ``starts``: per start ``t``, ``material_speed``,
``steps``: per step ``r0`` (|r| at each predictor), ``iterations``, ``residuals``,
``difference``; ``totals``) and ``belt3d_predictor.md``.
"""
from __future__ import annotations

import argparse
from pathlib import Path

import numpy as np

from ancf.belts.forces import gather
from ancf.common.threads import one_blas_thread
from ancf.elements.basis import plate36_S, plate36_x, plate36_y
from benchmarks import peers
from benchmarks.belt3d_newton import OneStep

STARTS = (0.4, 1.0)  # s: 10 and 25 m/s belt speed
PREDICTORS = ("last step", "shifted")
MAX_ITER, MAX_BACKTRACKS = 25, 8
#: the element's nodes at x = 0 (shape functions 0 and 9) and at x = a (3 and 6), with y
LEFT, RIGHT = ((0, 0.0), (9, 1.0)), ((3, 0.0), (6, 1.0))


def material_speed(E, V) -> float:
    """c (m/s of reference length): the mean of rdot . r_x / |r_x|^2 over the nodes."""
    nel = E.shape[0]
    return float(np.mean([V[e, k] @ E[e, k + 1] / (E[e, k + 1] @ E[e, k + 1])
                          for e in range(nel) for k in (0, 9)]))


def shifted(drive, x, v, acc, h: float) -> tuple[np.ndarray, float]:
    """(the shifted predictor of the step's acceleration, c) at state (x, v, acc)."""
    nel, b = drive.spec.n_elements, drive.spec.width
    E, V, A = (np.empty((nel, 12, 3)) for _ in range(3))
    gather(x, drive.vidx, E, V, v)
    gather(acc, drive.vidx, A, np.empty_like(V), v)
    c = material_speed(E, V)
    p = acc.copy()
    for e, a in enumerate(np.asarray(drive.lengths, float)):
        for k, y in LEFT if c > 0 else RIGHT:  # each node once: upstream of its element
            at = [np.array([(0.0 if k in (0, 9) else a) + c * h]), np.array([y * b]),
                  np.array([a]), np.array([b])]
            for j, shape in enumerate((plate36_S, plate36_x, plate36_y)):
                p[drive.vidx[e, 3 * (k + j): 3 * (k + j) + 3]] = np.ravel(shape(*at)) @ A[e]
    return p, c


def damped_newton(one: OneStep, acc1, tol: float) -> tuple[int | None, int, np.ndarray]:
    """(iterations or None, residual evaluations, the acceleration) of one step."""
    m = one.drive.n
    r, x1 = one.residual(acc1, want_J=True)[:2]
    count = 1
    for it in range(MAX_ITER):
        d, rn, lam = one.newton_increment(r), np.linalg.norm(r), 1.0
        for _ in range(MAX_BACKTRACKS):
            rt, xt = one.residual(acc1 + lam * d, want_J=True)[:2]
            count += 1
            if np.linalg.norm(rt) <= (1 - 1e-4 * lam) * rn:
                break
            lam *= 0.5
        acc1 = acc1 + lam * d
        if one.bp * lam * np.max(np.abs(d[:m])) <= tol * (1 + np.max(np.abs(x1[:m]))):
            return it + 1, count, acc1
        r, x1 = rt, xt
    return None, count, acc1


def from_start(drive, x, v, t: float, h: float, nsteps: int, tol: float) -> dict:
    """``nsteps`` steps from (x, v) at t, each from both predictors."""
    one, steps, c = OneStep(drive, x, v, t, h), [], None
    for s in range(nsteps):
        acc = one.st[2].copy()
        guess, c = shifted(drive, one.st[0], one.st[1], acc, h)
        runs = [damped_newton(one, g.copy(), tol) for g in (acc, guess)]
        steps.append({"r0": [float(np.linalg.norm(one.residual(g)[0])) for g in (acc, guess)],
                      "iterations": [n for n, _, _ in runs], "residuals": [k for _, k, _ in runs],
                      "difference": float(np.max(np.abs(runs[0][2] - runs[1][2]))
                                          / np.max(np.abs(runs[0][2])))})
        if runs[0][0] is None:
            break
        one.accept(runs[0][2])
        keep = tuple(q.copy() for q in one.st)
        one = OneStep(drive, keep[0], keep[1], t + (s + 1) * h, h)
        one.st = keep
    done = [s for s in steps if None not in s["iterations"]]
    return {"t": t, "material_speed": c, "steps": steps,
            "totals": {"iterations": [sum(s["iterations"][i] for s in done) for i in (0, 1)],
                       "residuals": [sum(s["residuals"][i] for s in done) for i in (0, 1)]}}


def _table(res: dict) -> str:
    lines = [f"# A Newton predictor that follows the belt\n\nGenerated by "
             f"`{res['command'].strip()}` on {res['started']} ({res['machine']['cpu_model']}). "
             "Damped full Newton on the march's residual, belt3d Model 2, h = "
             f"{res['settings']['h']:g} s, from the last step's acceleration and from the "
             "belt's acceleration field shifted by one step's travel (module docstring).\n",
             "| start (s) | material speed c (m/s) | steps | residual norm at the predictor, "
             "mean | iterations | residual evaluations | saved |", "|---|---|---|---|---|---|---|"]
    for s in res["starts"]:
        tot, n = s["totals"], len(s["steps"])
        r0 = [np.mean([st["r0"][i] for st in s["steps"]]) for i in (0, 1)]
        saved = 1 - tot["residuals"][1] / tot["residuals"][0]
        lines.append(f"| {s['t']:g} | {s['material_speed']:.2f} | {n} | {r0[0]:.2g} → "
                     f"{r0[1]:.2g} | {tot['iterations'][0]} → {tot['iterations'][1]} | "
                     f"{tot['residuals'][0]} → {tot['residuals'][1]} | {100 * saved:.0f} % |")
    return "\n".join(lines) + "\n"


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--steps", type=int, default=40)
    ap.add_argument("--out", default=str(peers.ROOT / "reports" / "benchmarks"))
    a = ap.parse_args(argv)
    if not 1 <= a.steps <= 200:
        ap.error(f"--steps must be in [1, 200] (got {a.steps})")
    one_blas_thread()
    from ancf.scenes import SCENES
    out, res = SCENES["belt3d"].execute({"model": 2, "t_end": max(STARTS)})
    run, drive = res.extra["result"], res.extra["drive"]
    h, tol = float(out["params"]["dt"]), float(out["params"]["newton_tol"])
    result = peers.record("belt3d_predictor", argv or [], {"model": 2, "h": h, "tol": tol,
                                                           "steps": a.steps})
    result["starts"] = []
    for t in STARTS:
        k = int(np.argmin(np.abs(run.t - t)))
        result["starts"].append(from_start(drive, run.q[k], run.v[k], float(run.t[k]), h,
                                           a.steps, tol))
    peers.write(Path(a.out), "belt3d_predictor", result, _table(result))
    print(_table(result))
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
