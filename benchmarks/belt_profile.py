"""Where a belt-drive run spends its time: call counts times per-call costs.

The compiled march has no clock inside, so the split is estimated: each kernel is
timed on its own (median of repeated calls at the run's last state, warm) and
multiplied by the number of calls the run's counters report:

* elastic forces: the belt element kernel, with the tangent on Jacobian evaluations, and
  the belt's strain-rate damping where it has any, with the part of the iteration matrix
  the drive's ``run.damping_jacobian`` asks for (``rate``: dQ_d/dz' only, as the march;
  an axial damping so in the elastic kernel's pass, as the march);
* contact: the contact kernel (with the friction law's state where it has one), with its
  Jacobians on Jacobian evaluations;
* linear algebra: per factorisation the band LU plus the solve for the border
  column, per Newton iteration one bordered solve;
* the rest (gathering, scattering, the recurrence, Python around the march) is the
  integration time minus these.

``python -m benchmarks.belt_profile [N ...]`` prints the split of the default 1 s run;
``python -m benchmarks.belt_profile --file drive.toml [--set key=value ...]`` that of a
drive file's run (``ancf run belt-drive``; e.g. ``--set run.t_end=0.3``).
"""
from __future__ import annotations

import argparse
import sys
import time

import numpy as np

from ancf.belts.contact2d import contact_forces_moving
from ancf.elements.dufva2d import damping_parts, gradient_tangent, gradient_tangent_damped
from ancf.solvers import banded
from ancf.belts.forces import gather

REPEATS = 300


def _per_call(fn) -> float:
    fn()
    samples = []
    for _ in range(5):
        t0 = time.perf_counter()
        for _ in range(REPEATS):
            fn()
        samples.append((time.perf_counter() - t0) / REPEATS)
    return float(np.median(samples))


def kernel_costs(drive, x, v, omegas) -> dict:
    """Seconds per call of each kernel at system state (x, v)."""
    nel, npul = drive.mesh.n_elements, drive.radii.size
    E, V = np.empty((nel, 6, 2)), np.empty((nel, 6, 2))
    gather(x, drive.vidx, E, V, v)
    eld = drive.element.kernel_data()
    g, K = np.zeros((nel, 12)), np.zeros((nel, 12, 12))
    Q, Kq, Cv = np.zeros((nel, 12)), np.zeros((nel, 12, 12)), np.zeros((nel, 12, 12))
    Qw, T, dT = np.zeros((nel, npul, 12)), np.zeros(npul), np.zeros((npul, nel, 12))
    z = None if drive.z is None else np.zeros_like(drive.z)
    h = 1e-4 if z is not None else 0.0
    o, odot = drive.moved(x, v)
    damping = drive.strain_damping
    rate = drive.damping_jacobian == 1  # DAMPING_JACOBIANS: dQ_d/dz' alone

    def contact(J):
        return lambda: contact_forces_moving(E, V, drive.S0, drive.w, o, odot, drive.radii,
                                             omegas, drive.prm, z, h, J, Q, Kq, Cv, Qw, T, dT,
                                             dT, T)

    def elastic(J):
        def fn():  # as the march (ancf.belts.forces._forces2d)
            if damping[0] != 0.0 and damping[1] == 0.0:
                gradient_tangent_damped(E, V, eld, damping[0], J, J and not rate, J, g, K, Cv)
                return
            gradient_tangent(E, eld, J, g, K)
            if damping.any():
                damping_parts(E, V, eld, damping, J and not rate, J, g, K, Cv)
        return fn
    return {"elastic": _per_call(elastic(False)), "elastic_tangent": _per_call(elastic(True)),
            "contact": _per_call(contact(False)), "contact_jacobian": _per_call(contact(True)),
            **linear_algebra_costs(drive)}


def linear_algebra_costs(drive) -> dict:
    """Seconds per band LU (unpivoted, as the march's kept factors) and per band solve of
    the drive's band pattern (the mass matrix stands in for the iteration matrix: same band)."""
    A0 = drive.Mb.copy()
    kl, piv, b = drive.pattern.kl, np.zeros(drive.n, dtype=np.int64), np.ones(drive.n)
    A = A0.copy()
    banded.lu(A, kl, piv, False)

    def factor():
        B = A0.copy()
        banded.lu(B, kl, piv, False)
    return {"lu": _per_call(factor), "solve": _per_call(lambda: banded.solve(A, kl, piv, b.copy()))}


def breakdown(r: dict, costs: dict) -> dict:
    """Estimated seconds in elastic forces, contact, linear algebra and the rest, from a
    belt-drive result ``r`` (its counters; belt2d or belt3d) and per-call costs with the keys
    of :func:`kernel_costs`."""
    nfev, njev, nlu, nit = r["nfev"], r["njev"], r["nlu"], r["newton_iterations"]
    out = {"elastic_s": (nfev - njev) * costs["elastic"] + njev * costs["elastic_tangent"],
           "contact_s": (nfev - njev) * costs["contact"] + njev * costs["contact_jacobian"],
           "linear_algebra_s": nlu * (costs["lu"] + costs["solve"]) + nit * costs["solve"]}
    out["other_s"] = r["integration_cpu_s"] - sum(out.values())
    return out


def split(out: dict, res) -> dict:
    """The counts, per-call costs (us) and the split of a belt scene's run (the pair
    ``Scene.execute`` returns), the kernels timed at the run's last state."""
    run, drive = res.extra["result"], res.extra["drive"]
    costs = kernel_costs(drive, run.q[-1], run.v[-1], drive.omegas(float(run.t[-1]), run.v[-1]))
    r = out["results"]
    return {"counts": {k: r[k] for k in ("steps", "nfev", "njev", "nlu", "newton_iterations")},
            "integration_cpu_s": r["integration_cpu_s"],
            "per_call_us": {k: c * 1e6 for k, c in costs.items()}, **breakdown(r, costs)}


def profile(n: int) -> dict:
    from ancf.scenes import SCENES
    return {"n": n, **split(*SCENES["belt2d"].execute({"n_elements": n}))}


def profile_file(path: str, sets: list) -> dict:
    """:func:`split` of ``ancf run belt-drive --file path --set ...``."""
    from ancf.scenes import SCENES
    from ancf.scenes.belt_drive import SEP
    return {"file": path, **split(*SCENES["belt-drive"].execute({"file": path,
                                                                  "set": SEP.join(sets)}))}


def _line(label: str, p: dict) -> str:
    return (f"{label}: integration {p['integration_cpu_s']:.3f} s; elastic {p['elastic_s']:.3f}, "
            f"contact {p['contact_s']:.3f}, linear algebra {p['linear_algebra_s']:.3f}, "
            f"other {p['other_s']:.3f} s; counts {p['counts']}; per call (us) "
            + ", ".join(f"{k} {v:.1f}" for k, v in p["per_call_us"].items()))


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(prog="python -m benchmarks.belt_profile",
                                 description=__doc__.split("\n")[0])
    ap.add_argument("n", type=int, nargs="*", help="belt2d element counts (default 20 40)")
    ap.add_argument("--file", help="a drive file instead of belt2d")
    ap.add_argument("--set", action="append", default=[], help="overrides of the file")
    args = ap.parse_args(argv)
    if args.file:
        print(_line(args.file, profile_file(args.file, args.set)))
        return 0
    for n in args.n or [20, 40]:
        print(_line(f"n = {n}", profile(n)))
    return 0


if __name__ == "__main__":
    sys.exit(main())
