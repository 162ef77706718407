"""Where a 3D belt-drive run (scene ``belt3d``) spends its time: call counts times
per-call costs, as :mod:`benchmarks.belt_profile` does for the planar drive.

Each kernel is timed on its own at the run's last state (median of repeated warm
calls) and multiplied by the run's counters:

* elastic forces: ``plate36.gradient_tangent``, with the tangent on Jacobian evaluations;
* contact: ``contact3d.contact_forces3d`` (all pulleys), with its Jacobians on Jacobian
  evaluations;
* linear algebra: per factorisation the band LU plus the solve for the border
  column, per Newton iteration one bordered solve;
* the rest (gathering, combining and scattering into the band matrix, the recurrence,
  Python around the march) is the integration time minus these.

``python -m benchmarks.belt3d_profile [T_END ...]`` prints the split of the default
Model 2 run (20 plates, 81 contact points) for each T_END (default: 0.3 s and the
scene's full 1.2 s).
"""
from __future__ import annotations

import sys

import numpy as np

from ancf.belts.contact3d import contact_forces3d
from ancf.elements import plate36
from ancf.belts.forces import gather, moved_centres
from benchmarks.belt_profile import _per_call, breakdown, linear_algebra_costs

T_ENDS = (0.3, 1.2)
COUNTS = ("steps", "nfev", "njev", "nlu", "newton_iterations", "rejected_steps", "contact_pairs")
RESULTS = ("slip_driven", "T_tight_N", "T_slack_N")


def kernel_costs3d(drive, x, v, t: float) -> dict:
    """Seconds per call of each kernel at system state (x, v) and time t (s)."""
    nel, npul = drive.spec.n_elements, drive.radii.size
    E, V = np.empty((nel, 12, 3)), np.empty((nel, 12, 3))
    gather(x, drive.vidx, E, V, v)
    eld = drive.element.kernel_data()
    g, K = np.zeros((nel, 36)), np.zeros((nel, 36, 36))
    omegas = np.array([float(drive.omega_driver(t)), float(v[-1])])
    centres, odot = moved_centres(drive.kernel(), drive.laws(t)[:, 0])
    out = (np.zeros((nel, 36)), np.zeros((nel, 36, 36)), np.zeros((nel, 36, 36)),
           np.zeros((nel, npul, 36)), np.zeros(npul), np.zeros((npul, nel, 36)),
           np.zeros((npul, nel, 36)), np.zeros(npul))

    def contact(J):
        return lambda: contact_forces3d(E, V, drive.S0, drive.w, centres, drive.axes, drive.radii,
                                        omegas, odot, drive.prm, J, *out)
    return {"elastic": _per_call(lambda: plate36.gradient_tangent(E, eld, False, g, K)),
            "elastic_tangent": _per_call(lambda: plate36.gradient_tangent(E, eld, True, g, K)),
            "contact": _per_call(contact(False)), "contact_jacobian": _per_call(contact(True)),
            **linear_algebra_costs(drive)}


def run_costs(out: dict, res) -> tuple[dict, dict]:
    """(per-call costs, split) of a finished belt3d run (``execute``'s outputs)."""
    run, drive = res.extra["result"], res.extra["drive"]
    costs = kernel_costs3d(drive, run.q[-1], run.v[-1], float(run.t[-1]))
    return costs, breakdown(out["results"], costs)


def profile(t_end: float, **params) -> dict:
    from ancf.scenes import SCENES
    out, res = SCENES["belt3d"].execute({"t_end": t_end, **params})
    r = out["results"]
    costs, split = run_costs(out, res)
    return {"t_end": t_end, "converged": out["converged"], "counts": {k: r[k] for k in COUNTS},
            "results": {k: r[k] for k in RESULTS}, "integration_cpu_s": r["integration_cpu_s"],
            "cpu_per_simulated_s": r["integration_cpu_s"] / t_end,
            "per_call_us": {k: v * 1e6 for k, v in costs.items()}, **split}


def main(argv=None) -> int:
    for t_end in [float(a) for a in (sys.argv[1:] if argv is None else argv)] or T_ENDS:
        p = profile(t_end)
        tot = p["integration_cpu_s"]
        shares = ", ".join(f"{k[:-2]} {p[k]:.2f} s ({100 * p[k] / tot:.0f} %)"
                           for k in ("elastic_s", "contact_s", "linear_algebra_s", "other_s"))
        print(f"t_end = {t_end:g} s: integration {tot:.2f} s CPU "
              f"({p['cpu_per_simulated_s']:.1f} s per simulated s; converged {p['converged']}); "
              f"{shares}\n  counts {p['counts']}\n  results {p['results']}\n  per call (us) "
              + ", ".join(f"{k} {v:.1f}" for k, v in p["per_call_us"].items()))
    return 0


if __name__ == "__main__":
    sys.exit(main())
