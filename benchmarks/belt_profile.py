"""Where a belt-drive run spends its time: call counts times per-call costs.

The compiled march has no clock inside, so the split is estimated: each kernel is
timed on its own (median of repeated calls at the run's last state, warm) and
multiplied by the number of calls the run's counters report:

* elastic forces: the belt element kernel, with the tangent on Jacobian evaluations;
* contact: the contact kernel, with its Jacobians on Jacobian evaluations;
* linear algebra: per factorisation the band LU plus the solve for the border
  column, per Newton iteration one bordered solve;
* the rest (gathering, scattering, the recurrence, Python around the march) is the
  integration time minus these.

``python -m benchmarks.belt_profile [N ...]`` prints the split of the default 1 s run.
"""
from __future__ import annotations

import sys
import time

import numpy as np

from ancf.belts.contact2d import contact_forces
from ancf.elements.dufva2d import gradient_tangent
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

    def contact(J):
        return lambda: contact_forces(E, V, drive.S0, drive.w, drive.centres, drive.radii, omegas,
                                      drive.prm, J, Q, Kq, Cv, Qw, T, dT, dT, T)
    return {"elastic": _per_call(lambda: gradient_tangent(E, eld, False, g, K)),
            "elastic_tangent": _per_call(lambda: gradient_tangent(E, eld, True, g, K)),
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


def profile(n: int) -> dict:
    from ancf.scenes import SCENES
    out, res = SCENES["belt2d"].execute({"n_elements": n})
    run, drive = res.extra["result"], res.extra["drive"]
    omegas = np.array([float(drive.omega_driver(run.t[-1])), float(run.v[-1, -1])])
    costs = kernel_costs(drive, run.q[-1], run.v[-1], omegas)
    return {"n": n, "counts": {k: out["results"][k] for k in ("steps", "nfev", "njev", "nlu",
                                                             "newton_iterations")},
            "integration_cpu_s": out["results"]["integration_cpu_s"],
            "per_call_us": {k: v * 1e6 for k, v in costs.items()},
            **breakdown(out["results"], costs)}


def main(argv=None) -> int:
    for n in [int(a) for a in (sys.argv[1:] if argv is None else argv)] or [20, 40]:
        p = profile(n)
        print(f"n = {n}: integration {p['integration_cpu_s']:.3f} s; elastic {p['elastic_s']:.3f}, "
              f"contact {p['contact_s']:.3f}, linear algebra {p['linear_algebra_s']:.3f}, "
              f"other {p['other_s']:.3f} s; counts {p['counts']}; per call (us) "
              + ", ".join(f"{k} {v:.1f}" for k, v in p["per_call_us"].items()))
    return 0


if __name__ == "__main__":
    sys.exit(main())
